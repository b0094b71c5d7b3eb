"""The bibliography (valvetrain.bibliography): every work's entry is complete and its short form unique, every key the
package cites is a work of it, and the corrections notes it ships are numbered, cited and translated item by item
(what users see cites these works: tests/test_citations.py)."""

from pathlib import Path
import re

import valvetrain
from valvetrain import bibliography
from valvetrain.bibliography import NO_AUTHORS, UNKNOWN, WORKS, cite, corrections_notes, corrections_text, entry

ROOT = Path(__file__).parent.parent
SRC = Path(valvetrain.__file__).parent


def test_bibliography_entries_are_complete():
    for key, work in WORKS.items():
        assert work.authors, key                   # authors, editor or institution, or NO_AUTHORS said so
        assert work.title and work.kind and work.language, key
        assert re.fullmatch(r"1[89]\d\d|20\d\d", work.year) or work.year == UNKNOWN, key
        if work.language != "English":
            assert work.translation, key          # a title in another language with its translation
        assert not re.search(r"[\u3000-\u9fff]", work.reference() + work.reference("ru")), key  # no CJK glyph
        if work.authors == NO_AUTHORS or work.year == UNKNOWN:   # said so in words, never "(n.d.)"
            assert "not given in the document" in work.reference(), key
        assert work.short.endswith(f"({work.year})") or work.year == UNKNOWN or work.short.startswith("EN "), key
    assert len({w.short for w in WORKS.values()}) == len(WORKS)
    assert cite("shang1988", "eq. (2.6)") == "Shang Hanji (1988), eq. (2.6)"
    assert "ISBN 7-309-00035-8" in entry("shang1988") and "Fudan University Press" in entry("shang1988")


def test_every_cited_key_is_in_the_bibliography():
    used = set()
    for path in SRC.rglob("*.py"):
        used |= set(re.findall(r"\b(?:cite|entry)\(\s*[\"'](\w+)[\"']", path.read_text(encoding="utf-8")))
    assert used <= set(WORKS), used - set(WORKS)


def test_corrections_notes_ship_with_the_package():
    text = corrections_text()
    numbers = [int(n) for n in re.findall(r"^(\d+)\. ", text, flags=re.M)]
    assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) >= 40
    # every "corrections note N" the package cites exists
    cited = set()
    for path in [*SRC.rglob("*.py"), *SRC.rglob("*.html"), *SRC.rglob("*.toml"), ROOT / "README.md",
                 *(ROOT / "tests").rglob("*.py")]:
        for a, b in re.findall(r"corrections notes? (\d+)(?:-(\d+))?", path.read_text(encoding="utf-8")):
            cited |= set(range(int(a), int(b or a) + 1))
    assert cited and cited <= set(numbers), cited - set(numbers)
    assert bibliography.corrections_text is corrections_text


def test_the_russian_corrections_notes_are_the_same_items():
    """Issue 24: the Russian report shows the corrections notes it cites in Russian: data/corrections.ru.md has every
    item of the English file under its number, and each Russian item is Cyrillic text."""
    english, russian = corrections_notes("en"), corrections_notes("ru")
    assert list(russian) == list(english) == list(range(1, 52))
    assert all(re.search("[а-яё]{4,}", title + text) for title, text in russian.values())
    assert russian[20][0] == "Прогиб распределительного вала, формула (7.3)."
    assert english[45] == ("Table 2.6, 60 deg, lambda = 0.26.", "Printed 0.978. Correct: 0.9816.")
