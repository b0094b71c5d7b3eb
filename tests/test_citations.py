"""What users see cites real works: no internal tags (seed numbers, spec files, misprint tags) in the report,
results.json, command-line help, public docstrings, README and examples; every citation is in the bibliography."""

from html import unescape
import importlib
import inspect
import io
import json
from pathlib import Path
import pkgutil
import re
import tokenize

from click.testing import CliRunner
import pytest

import valvetrain
from valvetrain.bibliography import WORKS, cited_in
from valvetrain.cli import main

ROOT = Path(__file__).parent.parent
SRC = Path(valvetrain.__file__).parent
EXAMPLES = ROOT / "examples"

TAG = re.compile(r"[Ss]eed 0|\bSPEC\b|spec/|methods-seeds|valvetrain-works|spec section|\[(?:R|D|A|S|V|S\+D)\]"
                 r"|\bE\d{1,2}\b")
"""Internal tags; ``E12``-style misprint tags are told from moduli such as ``E1 E2 / (E1 + E2)`` by :func:`tags`."""

CITATION = re.compile(r"[A-Z][\w'’.-]*(?: [\w'’.-]+){0,5} \((?:1[89]\d\d|20\d\d|n\.d\.)\)")
"""A short in-text citation: words before ``(year)`` or ``(n.d.)``."""


def _modulus(text, m):
    """Whether the match ``m`` of an ``E1``-like tag in ``text`` is a modulus in arithmetic (``E1 E2 / (E1 + E2)``)."""
    around = text[max(m.start() - 3, 0):m.end() + 3]
    return bool(re.search(r"[+*/=^]", around) or re.search(r"E\d+\s+E\d", around))


def tags(text):
    """The internal tags in ``text`` (with some context), arithmetic with E1, E2, ... (moduli) excepted."""
    found = []
    for m in TAG.finditer(text):
        if m.group().startswith("E") and _modulus(text, m):
            continue
        found.append(text[max(m.start() - 40, 0):m.end() + 40])
    return found


def unknown_citations(text):
    """Short citations in ``text`` that no work of the bibliography ends."""
    shorts = [w.short for w in WORKS.values()]
    return [m.group() for m in CITATION.finditer(text)
            if not any(m.group().endswith(s) or s.endswith(m.group()) for s in shorts)]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The built-in example in English and Russian and a shipped example, each run to an output folder."""
    out = {}
    for label, (file, lang) in {"en": ([], "en"), "ru": ([], "ru"), "v8": ([str(EXAMPLES / "v8-crank.toml")], "en")}.items():
        folder = tmp_path_factory.mktemp(label) / "design"
        result = CliRunner().invoke(main, ["run", *file, "--out", str(folder), "--lang", lang])
        assert result.exit_code == 0, result.output
        out[label] = folder
    return out


@pytest.mark.parametrize("label", ["en", "ru", "v8"])
def test_report_and_results_cite_real_works(runs, label):
    html = (runs[label] / "report.html").read_text(encoding="utf-8")
    results = (runs[label] / "results.json").read_text(encoding="utf-8")
    assert tags(html) == [] and tags(results) == []
    assert unknown_citations(html) == []
    # issue 39: the note cites each work by its number in the list of sources, numbered in the order of the first
    # citation (GOST 7.32), and lists the works it cites and only those, each in the form of GOST 7.1 in its own
    # language; no "(n.d.)" or "(б. г.)" is left
    lang = "ru" if label == "ru" else "en"
    sources = html[html.index('<ol class="bibliography">'):]
    items = re.findall(r'<li value="(\d+)" lang="[^"]+">(.*?)</li>', sources[:sources.index("</ol>")])
    assert [int(n) for n, _ in items] == list(range(1, len(items) + 1)) and len(items) >= 3
    references = {unescape(text) for _, text in items}
    cited = [key for key, work in WORKS.items() if work.reference(lang) in references]
    assert len(cited) == len(items) and ("shang1988" in cited or label == "v8")
    text = unescape(re.sub(r"<[^>]+>", "", html[:html.index('<ol class="bibliography">')]))
    numbers = [int(n) for n in re.findall(r"\[(\d+)(?:, [^\]]*)?\]", text)]
    assert set(numbers) == set(range(1, len(items) + 1))
    assert [n for i, n in enumerate(numbers) if n not in numbers[:i]] == list(range(1, len(items) + 1))
    assert not any(WORKS[key].short in text for key in WORKS) and "n.d." not in html and "б. г." not in html
    # every source of a warning is a citation of the bibliography
    for w in json.loads(results)["warnings"]:
        assert cited_in(w["source"]), w


def test_command_line_help():
    texts = [CliRunner().invoke(main, ["--help"]).output]
    texts += [CliRunner().invoke(main, [name, "--help"]).output for name in main.commands]
    assert len(texts) > 3
    for text in texts:
        assert tags(text) == [], text


def _modules():
    yield valvetrain
    for info in pkgutil.walk_packages(valvetrain.__path__, "valvetrain."):
        if not info.name.endswith("__main__"):
            yield importlib.import_module(info.name)


def _docstrings():
    """Module, public object and public method docstrings reachable with pydoc."""
    for module in _modules():
        yield module.__name__, module.__doc__ or ""
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
                continue
            yield f"{module.__name__}.{name}", inspect.getdoc(obj) or ""
            if inspect.isclass(obj):
                for attr, member in vars(obj).items():
                    if not attr.startswith("_") and (inspect.isfunction(member) or isinstance(member, property)):
                        yield f"{module.__name__}.{name}.{attr}", inspect.getdoc(member) or ""


def test_public_docstrings():
    bad = {where: found for where, doc in _docstrings() if (found := tags(doc) + unknown_citations(doc))}
    assert bad == {}


def test_every_string_of_the_package():
    """Every string literal of the package's code (docstrings, check sources, messages, attribute docstrings);
    internal tags may stay in comments only."""
    bad = {}
    for path in SRC.rglob("*.py"):
        tokens = tokenize.generate_tokens(io.StringIO(path.read_text(encoding="utf-8")).readline)
        for tok in tokens:
            if tok.type == tokenize.STRING and (found := tags(tok.string) + unknown_citations(tok.string)):
                bad[f"{path.relative_to(SRC)}:{tok.start[0]}"] = found
    assert bad == {}


@pytest.mark.parametrize("path", [ROOT / "README.md", ROOT / "docs" / "corrections.md",
                                  *sorted(EXAMPLES.rglob("*.*")), *sorted((SRC / "data").glob("*.*")),
                                  *sorted((SRC / "report" / "templates").glob("*.html"))],
                         ids=lambda p: str(p.relative_to(ROOT) if p.is_relative_to(ROOT) else p.relative_to(SRC.parent)))
def test_shipped_texts(path):
    text = path.read_text(encoding="utf-8")
    assert tags(text) == []
    assert unknown_citations(text) == []


SEED_WORKS = {"000": "vt_works", "001": "power_units", "002": "shang1988", "003": "valve_dynamics_article",
              "004": "ukrsurt2019"}
"""The work each seed document of the project is (tests/README-style tags ``seed 000`` ... ``seed 004``); the
``E1``-``E29`` misprint tags are the corrections notes 1-29 of Valve-train practical works (n.d.)."""

SEED_TAG = re.compile(r"\b[Ss]eeds? (00[0-4])(?:\s*(?:-|–|\.\.\.|and|,)\s*(00[0-4]))?")


def _texts(source):
    """The comments (a run of comment lines as one) and the strings of Python ``source``: ``(line, text)``."""
    tokens = tokenize.generate_tokens(io.StringIO(source).readline)
    block, first, last = [], None, None
    for tok in tokens:
        if tok.type == tokenize.COMMENT and block and tok.start[0] == last + 1:
            block.append(tok.string)
        elif tok.type == tokenize.COMMENT:
            if block:
                yield first, " ".join(block)
            block, first = [tok.string], tok.start[0]
        elif tok.type == tokenize.STRING:
            yield tok.start[0], tok.string
        else:
            continue
        last = tok.start[0]
    if block:
        yield first, " ".join(block)


def uncited_tags(source):
    """The comments and strings of test ``source`` that carry a seed tag or a misprint tag without the short form
    of the work the tag stands for: ``(line, tag, short form)``."""
    found = []
    for line, text in _texts(source):
        needed = [(m.group(), SEED_WORKS[g]) for m in SEED_TAG.finditer(text) for g in m.groups() if g]
        needed += [(m.group(), "vt_works") for m in re.finditer(r"\bE\d{1,2}\b", text) if not _modulus(text, m)]
        found += [(line, tag, WORKS[key].short) for tag, key in needed if WORKS[key].short not in text]
    return found


def test_the_tag_finder_of_the_tests():
    """A seed tag or a misprint tag without its work's short form is found; beside it, or a modulus, is not."""
    assert uncited_tags('"""The appendix of seed 000 (E2)."""') == [
        (1, "seed 000", "Valve-train practical works (n.d.)"), (1, "E2", "Valve-train practical works (n.d.)")]
    assert uncited_tags("# seed 004, eq. 7\n") == [(1, "seed 004", "UkrSURT Proceedings (2019)")]
    assert uncited_tags("# Shang Hanji (1988), eq. 2.6 (seed 002)\n# E_m = 2 E1 E2 / (E1 + E2)\n") == []
    assert uncited_tags('x = "Valve-train practical works (n.d.), corrections note 2 (E2)"\n') == []


def test_tests_cite_their_sources_by_the_short_form():
    """Every test that cites a source document by its internal tag names the work by the bibliography's short form
    in the same comment or string, as the code does (this file, which defines the tags, excepted)."""
    found = [(str(path.relative_to(ROOT)), *hit) for path in sorted((ROOT / "tests").rglob("*.py"))
             if path != Path(__file__) for hit in uncited_tags(path.read_text(encoding="utf-8"))]
    assert not found, found
