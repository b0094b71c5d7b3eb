"""The words of the report in the message catalogues (src/valvetrain/locale/LANG.toml): both languages, the same
fields, each word in one section."""

import re
import string

from valvetrain.languages import LANGS
from valvetrain.locale import catalogue
from valvetrain.report.i18n import SECTIONS, TEXT
from valvetrain.report.names import NAMES, label, link_names, value_text
from valvetrain.report.symbols import NOTATION

TRANSLATED = ("check_words", "stage_words", "note_words", "tolerance_words", "report", "names", "stage_names",
              "symbols", "name_words", "worked_symbols")
"""The sections whose every English word has its Russian (``[words]`` has Russian-only forms, ``[optimize_words]``
names the English quantities the Russian translates in its ``rows``)."""

BY_ENGLISH = ("values", "segments", "links")
"""The sections keyed by the English itself (a record's text value, a lift law's segment, a drive link): in every
language but English."""


def _fields(text):
    return sorted(name for _, name, _, _ in string.Formatter().parse(text) if name is not None)


def test_every_word_is_in_both_languages_with_the_same_fields():
    """A chapter's text without its Russian, or whose Russian drops or renames a ``{field}`` of the English, would
    print the English or fail to format in the Russian report."""
    for section in TRANSLATED:
        en, ru = catalogue("en")[section], catalogue("ru")[section]
        assert en.keys() == ru.keys(), section
        for key, text in en.items():
            if isinstance(text, str):
                assert _fields(text) == _fields(ru[key]), key
            elif isinstance(text, dict):
                assert {k: _fields(v) for k, v in text.items()} == {k: _fields(v) for k, v in ru[key].items()}, key


def test_the_sections_keyed_by_the_english_are_in_every_other_language_and_russian():
    """``[values]``, ``[segments]`` and ``[links]`` map the English (the key) to the language's text; English has no
    such section, Russian has each text in Russian (or a symbol: the segments ``A1``, ``Phi1``: ``Φ1``)."""
    for section in BY_ENGLISH:
        assert section not in catalogue("en"), section
        for lang in LANGS[1:]:
            texts = catalogue(lang)[section]
            assert texts and all(t and (t == key or re.search("[а-яёα-ω]", t, re.I)) for key, t in texts.items()), section
    assert value_text("Phi1 opening", "ru") == "Φ1, подъём" and value_text("clearance take-up closing", "ru") == \
        "выборка зазора, опускание"
    assert link_names(["pushrod", "unknown"], "ru") == "штанга, unknown" and link_names(["pushrod"], "en") == "pushrod"


def test_every_key_has_its_name_in_every_language_and_the_stages_names_are_joined():
    """``[stage_names]`` joins ``[names]`` (no key in both); a name's English has no Russian word (a symbol's Cyrillic
    index as the source writes it may be there: ``φ_вв``) and its Russian has Russian (or is the same symbol: ``A0``)."""
    assert not set(catalogue("en")["names"]) & set(catalogue("en")["stage_names"])
    for key, (en, ru) in NAMES.items():
        assert en and not re.search("[а-яё]{3}", en, re.I), key
        assert ru == en or re.search("[а-яё]", ru, re.I), key
    assert NAMES["switching.inner_arm"] == (catalogue("en")["stage_names"]["switching.inner_arm"],
                                            catalogue("ru")["stage_names"]["switching.inner_arm"])
    assert label("switching.inner_arm_mm", "ru") == "внутренний рычаг от оси до центра ролика L_i, мм"
    assert label("switching.inner_arm_mm", "en") == "inner arm, pivot to roller centre L_i, mm"


def test_every_symbol_has_its_notation_and_its_meaning_in_every_language():
    for lang in LANGS:
        assert catalogue(lang)["symbols"].keys() == NOTATION.keys(), lang


def test_the_report_has_every_word_of_its_sections_once():
    """A key in two sections would take the later section's word silently."""
    for lang in ("en", "ru"):
        keys = [key for section in SECTIONS for key in catalogue(lang)[section]]
        assert len(keys) == len(set(keys)) == len(TEXT[lang]), lang
        assert all(TEXT[lang][key] == text for section in SECTIONS for key, text in catalogue(lang)[section].items())
