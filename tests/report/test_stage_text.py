"""The texts of the further stages' chapters (report/stage_text.py): both languages, the same fields."""

import string

from valvetrain.report.i18n import TEXT
from valvetrain.report.stage_text import STAGE_TEXT


def _fields(text):
    return sorted(name for _, name, _, _ in string.Formatter().parse(text) if name is not None)


def test_every_stage_text_is_in_both_languages_with_the_same_fields():
    """A chapter's text without its Russian, or whose Russian drops or renames a ``{field}`` of the English, would
    print the English or fail to format in the Russian report."""
    assert STAGE_TEXT["en"].keys() == STAGE_TEXT["ru"].keys()
    for key, en in STAGE_TEXT["en"].items():
        ru = STAGE_TEXT["ru"][key]
        if isinstance(en, str):
            assert _fields(en) == _fields(ru), key
        else:
            assert {k: _fields(v) for k, v in en.items()} == {k: _fields(v) for k, v in ru.items()}, key


def test_the_report_has_every_stage_text():
    for lang in ("en", "ru"):
        assert all(TEXT[lang][key] == text for key, text in STAGE_TEXT[lang].items())
