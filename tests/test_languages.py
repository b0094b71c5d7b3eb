"""The languages of valvetrain's texts (valvetrain.languages): each language of LANGS has its message catalogue and
its column of unit symbols, in LANGS' order, and no other language is offered."""

from importlib.resources import files

import pytest

from valvetrain.languages import LANGS
from valvetrain.locale import catalogue
from valvetrain.units import UNITS, symbol


def test_every_language_has_its_catalogue_and_nothing_else_is_offered():
    shipped = {p.name.removesuffix(".toml") for p in files("valvetrain.locale").iterdir() if p.name.endswith(".toml")}
    assert shipped == set(LANGS) == {"en", "ru"}
    assert all(catalogue(lang)["checks"].keys() == catalogue("en")["checks"].keys() for lang in LANGS)
    with pytest.raises(ValueError, match="allowed"):
        catalogue("de")


def test_the_unit_symbols_have_a_column_per_language_in_its_order():
    """English first, then Russian: the millimetre is "mm", then "мм"; every unit has exactly one symbol a language."""
    assert all(len(row) == 2 + len(LANGS) for row in UNITS.values())
    assert [symbol("mm", lang) for lang in LANGS] == ["mm", "мм"]

