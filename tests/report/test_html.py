"""The HTML report (report/html.py).  Issue 24: the report is a document one signs: a title block from the optional
[document] section, a table of contents linking every chapter, a Conclusions chapter, the long tables in an appendix,
page numbers in print.  A compiled template kept between runs is that of the report's language."""

from collections import defaultdict
from html import unescape
import json
import re
import tomllib

from click.testing import CliRunner
import pytest

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.locale import catalogue
from valvetrain.report.html import embedded, render_report
from valvetrain.report.i18n import TEXT
from valvetrain.report.names import record_quantity_text
from valvetrain.specification import example_spec

from appendix import appendix_text


def _report(tmp_path, extra=""):
    spec = tmp_path / "spec.toml"
    spec.write_text(appendix_text() + extra, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["run", str(spec), "--out", str(out), "--figures", "none"])
    assert result.exit_code == 0, result.output
    return (out / "report.html").read_text(encoding="utf-8"), out


DOCUMENT = {"organisation": "Moscow Automobile and Road Institute", "department": "Department of Engines",
            "discipline": "Engine design", "title": "Valve train of a petrol engine", "number": "VT-24-001",
            "author": "A. Designer", "group": "D-41", "supervisor": "C. Supervisor", "checker": "B. Checker",
            "city": "Kharkiv", "date": "2026-11-25"}


def _title_page(page):
    """The title page of a report: from its section to the end of the section."""
    return page[page.index('<section id="title-page">'):page.index("</section>")]


def test_title_page_contents_conclusions_and_appendix(tmp_path):
    """Issue 39: a title page after GOST 7.32 / 2.105 from [document]: the organisation and department, the kind of
    document and the course, the title, the engine, the number, the performer (and group), supervisor and checker
    each with a signature line, the city and year."""
    fields = "".join(f'{k} = "{v}"\n' for k, v in DOCUMENT.items()) + "year = 2026\n"
    page, out = _report(tmp_path, "\n[document]\n" + fields)
    title = _title_page(page)
    for text in [*DOCUMENT.values(), "2026", "CALCULATION NOTE", "to the course project in"]:
        assert text in title, text
    assert title.count("signature, date") == 3 and "blank" not in title.replace("blank short", "")
    order = [title.index(DOCUMENT[k]) for k in ("organisation", "department", "title", "number", "author",
                                                "supervisor", "checker", "city")]
    assert order == sorted(order)
    # the contents: one link per chapter, in order, each to an anchor that exists
    toc = page[page.index('<nav id="toc">'):page.index("</nav>")]
    links = re.findall(r'href="#(ch\d+)"', toc)
    assert links == [f"ch{i}" for i in range(1, len(links) + 1)] and len(links) >= 5
    assert all(f'<h2 id="{a}"' in page for a in links)
    assert page.index("</section>") < page.index('<nav id="toc">')          # the contents after the title page
    chapters = re.findall(r'<h2 id="ch\d+"[^>]*>(.*?)</h2>', page)
    # GOST 7.32's order: the conclusions, the list of sources, then the appendices
    assert chapters.index("Conclusions") < chapters.index("Sources") < \
        chapters.index("Appendix A: input data and lift tables")
    # the lift table and the input dump are in the appendix, after the conclusions
    appendix = page.index("Appendix A: input data and lift tables</h2>")
    assert page.index("Lift table (every") > appendix and page.index("<h3>Input data</h3>") > appendix
    # page numbers and the document number in print, not on the title page
    assert "counter(page)" in page and '"VT-24-001"' in page and "@page :first" in page
    # the [document] section is kept in the specification written beside the results
    assert tomllib.loads((out / "spec.toml").read_text())["document"]["number"] == "VT-24-001"


def test_without_a_document_section_the_title_page_has_blank_lines_to_fill(tmp_path):
    """Every field the file leaves out is a blank line to fill in by hand; the signature lines are there."""
    title = _title_page(_report(tmp_path)[0])
    assert "Performed by" in title and "Supervisor" in title and "Checked by" in title
    assert title.count('<span class="blank"></span>') == 7   # organisation, department, number, three names, city
    assert title.count('<span class="blank short"></span>') == 4   # three signatures and the year
    assert "course project" not in title


@pytest.mark.parametrize("field,value", [("author", '"' + "x" * 201 + '"'), ("supervisor", '"' + "x" * 201 + '"'),
                                         ("year", "1850"), ("year", '"2026"'), ("city", "3")])
def test_a_wrong_document_field_is_refused(tmp_path, field, value):
    spec = tmp_path / "spec.toml"
    spec.write_text(appendix_text() + f"\n[document]\n{field} = {value}\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["validate", str(spec)])
    assert result.exit_code == 2 and f"document.{field}" in result.output, result.output


def test_a_kept_compiled_template_is_that_of_its_language(monkeypatch):
    """Jinja2 applies a filter to a literal when it compiles the template (``{{ "mm" | unit }}``): the compiled
    template kept between runs must be that of the report's language.  The reference is each report rendered from a
    template compiled afresh (no bytecode cache), after the other language's was compiled and kept."""
    import valvetrain.report.html as html

    results = run(example_spec())
    kept = {lang: render_report(results, {}, lang) for lang in ("en", "ru", "en")}
    monkeypatch.setattr(html, "BYTECODE_CACHES", dict.fromkeys(TEXT))
    assert kept == {lang: render_report(results, {}, lang) for lang in ("ru", "en")}


def test_a_linked_figure_is_embedded_from_its_file():
    """embedded() puts each figure a page links (``<img src="plots/NAME"``) into the page as a data URI; the reference
    is the file's bytes, read back from the page by the standard library's base64 decoder; the text around it and a
    mention of ``plots/`` outside an image stay as they were."""
    import base64

    images = {"a.png": b"\x89PNG first", "b&c.png": bytes(range(256))}
    page = ('<p>see plots/a.png</p><img src="plots/a.png" alt="A" class="tall">'
            '<img src="plots/b&amp;c.png" alt="B">')
    got = embedded(page, images)
    uris = re.findall(r'<img src="data:image/png;base64,([^"]*)"', got)
    assert [base64.b64decode(u, validate=True) for u in uris] == [images["a.png"], images["b&c.png"]]
    assert re.sub(r'data:image/png;base64,[^"]*', "X", got) == (
        '<p>see plots/a.png</p><img src="X" alt="A" class="tall"><img src="X" alt="B">')


@pytest.fixture(scope="module")
def builtin():
    """The built-in example designed in this process."""
    return run(example_spec())


def _cells(row):
    """The texts of a table row's cells (tags taken out, entities decoded, spaces joined)."""
    return [" ".join(unescape(re.sub(r"<[^>]+>", "", cell)).split())
            for cell in re.findall(r"<td[^>]*>(.*?)</td>", row, re.S)]


def _check_rows(page):
    """The rows of the report's tables of checks in their chapters: ``[(heading of the chapter (h2), cells)]``."""
    rows = []
    for chapter in re.split(r"(?=<h2[ >])", page)[1:]:
        heading = " ".join(unescape(re.sub(r"<[^>]+>", "", chapter[:chapter.index("</h2>")])).split())
        for table in re.findall(r'<table class="checks">(.*?)</table>', chapter, re.S):
            rows += [(heading, _cells(row)) for row in re.findall(r"<tr class=[^>]*>(.*?)</tr>", table, re.S)]
    return rows


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_graded_check_of_results_json_is_in_its_chapter_with_its_limit(builtin, lang):
    """Issue 39: every graded check (a failure's allowable limit, a warning's recommended range) of results.json
    appears once in the chapter of its valve (the engine's outside the valves' chapters), as its name, its value,
    its limit, a verdict in words and its margin.  Before: 24 of the built-in example's 77 graded checks showed their
    limit in the note (the strength tables and the accepted list).  The numbers are results.json's, printed by the
    report's rule of numbers (4 significant figures; a bound as given, to 6)."""
    records = [c for c in json.loads(json.dumps(builtin.to_dict()))["checks"] if c["severity"] != "info"]
    assert len(records) == 77
    rows = _check_rows(render_report(builtin, {}, lang))
    assert len(rows) == len(builtin.checks)               # every check once, the remarks (info) too
    t = TEXT[lang]

    def chapter_of_valve(head):
        """The valve whose chapter has the heading ``head`` (None: not a valve's)."""
        return next((v for v in builtin.valves if f'"{v}"' in head or f"«{v}»" in head), None)

    for c in records:
        name = record_quantity_text(c, lang).removeprefix(f"{c['valve']}: ")     # the chapter names the valve,
        for chapter in catalogue(lang)["chapters"].values():                     # or the part of the engine
            name = name.removeprefix(f"{chapter}: ")
        name = name.replace("_", "")                                             # a symbol's index subscript
        found = [(head, cells) for head, cells in rows if cells[0] == name and chapter_of_valve(head) == c["valve"]]
        assert len(found) == 1, (c["code"], c["valve"], name, [h for h, _ in found])
        _, (_, value, limit, verdict, margin, *_) = found[0]
        comma = (lambda x: x.replace(".", ",")) if lang == "ru" else (lambda x: x)
        printed = float(re.match(r"[-\d.,]+", value).group().replace(",", "."))
        assert printed == pytest.approx(c["value"], rel=6e-4, abs=1e-6), (c["code"], value, c["value"])
        for bound in (c["low"], c["high"]):
            assert bound is None or comma(f"{bound:g}") in limit, (c["code"], limit, bound)
        assert verdict.startswith(t[("verdict_in_" if c["pass"] else "verdict_out_") + c["severity"]]), (c, verdict)
        assert (t["verdict_accepted"] in verdict) == (c["accepted"] and not c["pass"])
        assert margin.endswith("%") and (margin.startswith("-") == (c["margin"] < 0)), (c["code"], margin)


class _EveryFigure(dict):
    """The figures of a report rendered without its folder, every one drawn (``figure.png``, linked)."""

    def get(self, key, default=None):
        return "figure.png" if key == "(timing)" else defaultdict(lambda: "figure.png")


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_table_and_figure_is_numbered_captioned_and_referred_to(builtin, lang):
    """Issue 39 (GOST 2.105): every table of the note has a numbered title above it ("Table 3 – ...", "Таблица 3 –
    ..."), every figure a numbered caption below it ("Figure 2 – ...", "Рисунок 2 – ..."), each kind numbered 1, 2,
    ... in the order of the note and A.1, A.2, ... in the appendix, and the text refers to each (a link to it in a
    sentence of its section).  Not numbered: the title page's table and the worked substitutions (formulas)."""
    page = render_report(builtin, _EveryFigure(), lang)
    table, figure = ("Таблица", "Рисунок") if lang == "ru" else ("Table", "Figure")
    body = page[page.index("<!--toc-->") if "<!--toc-->" in page else page.index('<nav id="toc">'):]
    tables = re.findall(r'(<p class="tcap" id="table-([^"]+)">([^<]*)[^\n]*\n)?<table( [^>]*)?>', body)
    numbered = [(label, head) for cap, label, head, attrs in tables if 'class="worked"' not in attrs]
    assert all(head == f"{table} {label} – " or head.startswith(f"{table} {label} – ") for label, head in numbered)
    labels = [label for label, _ in numbered]
    appendix = labels.index(next(l for l in labels if "." in l))
    letter = "А" if lang == "ru" else "A"
    assert labels == [str(n) for n in range(1, appendix + 1)] + [f"{letter}.{n}" for n in range(1, len(labels) - appendix + 1)]
    assert len(labels) > 40
    figures = re.findall(r'<figure><img [^>]*><figcaption id="figure-(\d+)">([^<]*)', body)
    assert [int(n) for n, _ in figures] == list(range(1, len(figures) + 1)) and len(figures) >= 8
    assert all(caption.startswith(f"{figure} {n} – ") for n, caption in figures)
    assert page.count("<figure>") == len(figures) and page.count("<img ") == len(figures)
    # the text refers to each: a link to it from a sentence of its section
    refs = "".join(re.findall(r'<p class="refs">(.*?)</p>', page))
    for kind, label in [("table", l) for l in labels] + [("figure", n) for n, _ in figures]:
        assert f'href="#{kind}-{label}"' in refs or re.search(
            rf'href="#{kind}-([^"]+)">[^<]*</a>–<a href="#{kind}-([^"]+)"', refs), (kind, label)
