"""The HTML report (report/html.py).  Issue 24: the report is a document one signs: a title block from the optional
[document] section, a table of contents linking every chapter, a Conclusions chapter, the long tables in an appendix,
page numbers in print.  A compiled template kept between runs is that of the report's language."""

import re
import tomllib

from click.testing import CliRunner

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.report.html import render_report
from valvetrain.report.i18n import TEXT
from valvetrain.specification import example_spec

from appendix import appendix_text


def _report(tmp_path, extra=""):
    spec = tmp_path / "spec.toml"
    spec.write_text(appendix_text() + extra, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["run", str(spec), "--out", str(out), "--figures", "none"])
    assert result.exit_code == 0, result.output
    return (out / "report.html").read_text(encoding="utf-8"), out


def test_title_block_contents_conclusions_and_appendix(tmp_path):
    page, out = _report(tmp_path, '\n[document]\nnumber = "VT-24-001"\nauthor = "A. Designer"\n'
                                  'checker = "B. Checker"\ndate = "2026-11-25"\n')
    block = page[page.index('id="title-block"'):page.index("</table>", page.index('id="title-block"'))]
    for text in ("VT-24-001", "A. Designer", "B. Checker", "2026-11-25"):
        assert text in block
    # the contents: one link per chapter, in order, each to an anchor that exists
    toc = page[page.index('<nav id="toc">'):page.index("</nav>")]
    links = re.findall(r'href="#(ch\d+)"', toc)
    assert links == [f"ch{i}" for i in range(1, len(links) + 1)] and len(links) >= 5
    assert all(f'<h2 id="{a}"' in page for a in links)
    chapters = re.findall(r'<h2 id="ch\d+"[^>]*>(.*?)</h2>', page)
    # GOST 7.32's order: the conclusions, the list of sources, then the appendices
    assert chapters.index("Conclusions") < chapters.index("Sources") < \
        chapters.index("Appendix: input data and lift tables")
    # the lift table and the input dump are in the appendix, after the conclusions
    appendix = page.index("Appendix: input data and lift tables</h2>")
    assert page.index("Lift table (every") > appendix and page.index("<h3>Input data</h3>") > appendix
    # page numbers and the document number in print
    assert "counter(page)" in page and '"VT-24-001"' in page
    # the [document] section is kept in the specification written beside the results
    assert tomllib.loads((out / "spec.toml").read_text())["document"]["number"] == "VT-24-001"


def test_without_a_document_section_the_block_has_empty_fields_to_fill(tmp_path):
    page, _ = _report(tmp_path)
    assert 'id="title-block"' in page and "Calculated by" in page and "Checked by" in page


def test_a_too_long_document_field_is_refused(tmp_path):
    spec = tmp_path / "spec.toml"
    spec.write_text(appendix_text() + f'\n[document]\nauthor = "{"x" * 201}"\n', encoding="utf-8")
    result = CliRunner().invoke(main, ["validate", str(spec)])
    assert result.exit_code == 2 and "document.author" in result.output


def test_a_kept_compiled_template_is_that_of_its_language(monkeypatch):
    """Jinja2 applies a filter to a literal when it compiles the template (``{{ "mm" | unit }}``): the compiled
    template kept between runs must be that of the report's language.  The reference is each report rendered from a
    template compiled afresh (no bytecode cache), after the other language's was compiled and kept."""
    import valvetrain.report.html as html

    results = run(example_spec())
    kept = {lang: render_report(results, {}, lang) for lang in ("en", "ru", "en")}
    monkeypatch.setattr(html, "BYTECODE_CACHES", dict.fromkeys(TEXT))
    assert kept == {lang: render_report(results, {}, lang) for lang in ("ru", "en")}
