"""Issue 24: the report in a real browser (Debian's chromium driven by Playwright, as tests/web/test_web_browser.py):
at 1000 and 1400 px wide and in print (A4, 186 mm between the margins of its @page rule = 703 CSS px) no table, figure
or line of the English and Russian reports of the textbook's appendix example is wider than its container: nothing is cut off
at the right edge or needs a horizontal scroll bar.  Before: the Russian summary table ran past the right edge at
1000 px.

And the length of the printed note: one valve (the textbook's appendix example: a valve, its spring, its strength and
the crank chapter, with the default figures) prints on 13 A4 pages or fewer in either language.  Before issue 24: 16
pages; after it 10, then issue 39 added a title page of its own, every check of the design in its chapter with its
limit, verdict and margin (44 rows) and the tables' titles: 12 pages in English, 13 in Russian.
"""

from pathlib import Path
import re

from click.testing import CliRunner
import pytest

from valvetrain.cli import main

pytest.importorskip("playwright")

PRINT_WIDTH_PX = round((210 - 24) / 25.4 * 96)
"""The width of an A4 page between the report's @page margins (12 mm each side) in CSS px (96 per inch)."""


ONE_VALVE = Path(__file__).parents[2] / "examples" / "seed000-appendix-kurz.toml"


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    """The one-valve example's report in English and in Russian, with the default figures."""
    found = {}
    for lang in ("en", "ru"):
        out = tmp_path_factory.mktemp("layout") / lang
        result = CliRunner().invoke(main, ["run", str(ONE_VALVE), "--out", str(out), "--lang", lang])
        assert result.exit_code == 0, result.output
        found[lang] = (out / "report.html").as_uri()
    return found


WAIT_MS = 120_000
"""How long a test waits for the report to be laid out on a loaded machine; the wait ends as soon as it is."""


def loaded(page, url):
    """``page`` on the report at ``url``, its document and every figure loaded: the page's state, not the load
    event's limit of 30 s (a report of 2 MB of embedded figures on a machine with a load average of 9)."""
    page.goto(url, wait_until="commit")
    page.wait_for_function("() => document.readyState === 'complete' && "
                           "Array.from(document.images).every((img) => img.complete)", timeout=WAIT_MS)


OVERFLOWS = """() => {
    const out = [];
    const page = document.documentElement;
    if (page.scrollWidth > page.clientWidth + 1) out.push(`page ${page.scrollWidth} > ${page.clientWidth}`);
    for (const el of document.querySelectorAll("table, img, p, h1, h2, h3, h4, ol, ul")) {
        const box = el.getBoundingClientRect(), parent = el.parentElement.getBoundingClientRect();
        if (box.right > parent.right + 1 || el.scrollWidth > el.clientWidth + 1 && el.tagName !== "IMG") {
            out.push(`${el.tagName}#${el.id} "${el.textContent.slice(0, 60)}": ${Math.round(box.right)} > `
                     + `${Math.round(parent.right)}`);
        }
    }
    return out;
}"""


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("media,width", [("screen", 1000), ("screen", 1400), ("print", PRINT_WIDTH_PX)])
def test_nothing_is_wider_than_its_container(page, reports, lang, media, width):
    page.emulate_media(media=media)
    page.set_viewport_size({"width": width, "height": 1000})
    loaded(page, reports[lang])
    found = page.evaluate(OVERFLOWS)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_one_valve_prints_on_thirteen_a4_pages_or_fewer(page, reports, lang):
    """Chromium's print to PDF (A4, the report's @page margins), its pages counted (each a /Type /Page object)."""
    loaded(page, reports[lang])
    pdf = page.pdf(format="A4", prefer_css_page_size=True)
    assert 1 <= len(re.findall(rb"/Type\s*/Page(?![a-z])", pdf)) <= 13
