"""The visible text of an HTML report and the English words in it (the Russian reports: tests/report/test_i18n.py,
the tolerance study's report: tests/test_tolerance.py); the Latin words of a Russian text, its citations included
(the Russian report: tests/report/test_russian.py, the designer's sources: tests/web/test_app.py)."""

import html
from html.parser import HTMLParser
import re

from valvetrain.bibliography import WORKS
from valvetrain.spring_materials import GRADES

ALLOWED = {
    # symbols of the sources (the report explains each where it is first used)
    "cp", "vp", "max", "min", "in", "spr", "gas", "cam", "sin", "cos", "ln", "dt", "dh", "dx", "ik", "hv", "mv",
    "av", "aT", "hT", "vT", "jT", "Cp", "Cq", "Cr", "Cs", "Kr", "Wi", "fg", "Fp", "Vh", "ic", "pi", "pN", "pS",
    "pK", "pT", "mT", "mj", "mr", "iw", "vv", "c1", "v0", "p0", "PD", "TR", "dp",
    # unit-free names of formulas and proper names
    "Kurz", "Wiebe", "Euler", "VDSiCr", "VDCrV", "valvetrain", "json", "csv", "dxf", "png",
    # authors of cited works in the notes of a computation (the citations themselves are not translated)
    "Shang", "Hanji", "Heywood", "Reinsch",
}
"""Latin words allowed in the Russian report: symbols, proper names and file types."""

LATIN_WORD = re.compile(r"[A-Za-z]{2,}")


class Visible(HTMLParser):
    """The visible text of an HTML page and its image descriptions, without styles, scripts, names given by the
    designer (class ``name``) and citations (class ``cite``, the bibliography)."""

    SKIP_CLASSES = {"name", "cite", "bibliography"}
    VOID = {"img", "br", "meta", "hr", "input", "link"}

    def __init__(self):
        super().__init__()
        self.stack, self.texts = [], []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag in self.VOID:
            if not self._skipping() and attrs.get("alt"):
                self.texts.append(attrs["alt"])
            return
        skip = tag in ("style", "script") or bool(self.SKIP_CLASSES & set((attrs.get("class") or "").split()))
        self.stack.append((tag, skip))

    def handle_endtag(self, tag):
        while self.stack:
            if self.stack.pop()[0] == tag:
                break

    def _skipping(self):
        return any(skip for _, skip in self.stack)

    def handle_data(self, data):
        if not self._skipping() and data.strip():
            self.texts.append(data)


def english_words(texts):
    """The Latin words of ``texts`` that are not in :data:`ALLOWED`, with the text each is in."""
    found = []
    for text in texts:
        for word in LATIN_WORD.findall(text):
            if word not in ALLOWED:
                found.append((word, text.strip()[:120]))
    return found


SYMBOLS = {"max", "min", "cos", "sin", "tan", "arccos", "zap", "MFB"}
"""Symbols of the sources spelt in Latin letters."""

PROPER = ({"valvetrain", "HP", "Academy", "ASTM"} | {w for grade in GRADES for w in re.findall(r"[A-Za-z]+", grade)}
          | {w for work in WORKS.values() for w in re.findall(r"[A-Za-z]+", work.short)})
"""Proper names: the program's, a web page's author, a standard's body, the spring steels' grades, the words of the
works' in-text forms (a citation names a work as the bibliography does)."""


def latin_words(page):
    """The Latin words of three letters or more in an HTML page or a text that are not a symbol (a word joined to a
    subscript by "_", :data:`SYMBOLS`), a key of the specification (its dotted path), a proper name (:data:`PROPER`, a name the designer gave, a title quoted «»)
    or in a work's entry in another language (``<li lang="en">``)."""
    page = re.sub(r"<style.*?</style>", "", page, flags=re.S)
    page = re.sub(r'<li [^>]*lang="(?!ru")[^"]*">.*?</li>', "", page, flags=re.S)
    page = re.sub(r'<(span|a) class="name"[^>]*>.*?</\1>', "", page, flags=re.S)
    text = html.unescape(re.sub(r"<[^>]+>", " ", page))
    text = re.sub(r"[\w.]*_[\w.]*", " ", text)    # symbols with a subscript (phi_p0, a_T), keys (valves.intake.lash_adjuster)
    text = re.sub(r"«[A-Za-z0-9 ,.:'-]+»", " ", text)          # a title in another language, quoted: a proper name
    return [w for w in re.findall(r"[A-Za-z]{3,}", text) if w not in SYMBOLS | PROPER]
