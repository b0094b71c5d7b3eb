"""Texts of the report and the plots in English and Russian, read from the message catalogues
(:mod:`valvetrain.locale`, ``LANG.toml``): the chapters of the valve's design (``[words]``), the check levels
(``[check_words]``), the chapters of the further stages (``[stage_words]``), the calculation note (``[note_words]``)
and the lost-motion chapter (``[report]``); the names of keys and values in ``[names]``... (:mod:`.names`), the
symbols' meanings in ``[symbols]`` (:mod:`.symbols`), the words of the optimisation's and the tolerance study's
reports in ``[optimize_words]`` and ``[tolerance_words]`` (:mod:`.optimization`, :mod:`.tolerance`)."""

from ..languages import LANGS
from ..locale import catalogue

SECTIONS = ("words", "check_words", "stage_words", "note_words", "report")
"""The sections of ``LANG.toml`` whose words make :data:`TEXT`; no key is in two of them."""

TEXT = {lang: {key: text for section in SECTIONS for key, text in catalogue(lang)[section].items()} for lang in LANGS}
"""The words of the report, ``lang -> key -> text``."""
