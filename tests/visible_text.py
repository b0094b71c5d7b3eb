"""The visible text of an HTML report and the English words in it (the Russian reports: tests/report/test_i18n.py,
the tolerance study's report: tests/test_tolerance.py)."""

from html.parser import HTMLParser
import re

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
