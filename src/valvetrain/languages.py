"""The languages of valvetrain's texts: the message catalogue (:mod:`valvetrain.locale`), the report and the unit
symbols of :data:`valvetrain.units.UNITS` have one column or file per language, in this order."""

LANGS = ("en", "ru")
"""English, Russian."""
