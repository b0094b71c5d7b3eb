"""The words of the report in the message catalogues (src/valvetrain/locale/LANG.toml): both languages, the same
fields, each word in one section."""

import string

from valvetrain.locale import catalogue
from valvetrain.report.i18n import SECTIONS, TEXT

TRANSLATED = ("check_words", "stage_words", "note_words", "tolerance_words", "report")
"""The sections whose every English word has its Russian (``[words]`` has Russian-only forms, ``[optimize_words]``
names the English quantities the Russian translates in its ``rows``)."""


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


def test_the_report_has_every_word_of_its_sections_once():
    """A key in two sections would take the later section's word silently."""
    for lang in ("en", "ru"):
        keys = [key for section in SECTIONS for key in catalogue(lang)[section]]
        assert len(keys) == len(set(keys)) == len(TEXT[lang]), lang
        assert all(TEXT[lang][key] == text for section in SECTIONS for key, text in catalogue(lang)[section].items())
