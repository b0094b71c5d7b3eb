#!/usr/bin/env python
"""The printed length of design reports: each ``report.html`` printed to PDF by the system's chromium (Playwright, A4,
the report's own @page margins), its pages counted.  Needs the Debian package ``chromium`` and ``playwright``::

    PYTHONPATH=src valvetrain run examples/seed000-appendix-kurz.toml --out /tmp/en
    PYTHONPATH=src valvetrain run examples/seed000-appendix-kurz.toml --out /tmp/ru --lang ru
    python tools/report_pages.py /tmp/en/report.html /tmp/ru/report.html

``tests/report/test_html_browser.py`` checks that one valve prints on 10 pages or fewer.
"""

import argparse
from pathlib import Path
import re
import shutil

from playwright.sync_api import sync_playwright

PAGE = re.compile(rb"/Type\s*/Page(?![a-z])")
"""A page object of the PDF."""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reports", nargs="+", type=Path, help="report.html files")
    args = parser.parse_args()
    browser = shutil.which("chromium") or shutil.which("chromium-headless-shell")
    with sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=browser, args=["--no-sandbox"])
        for report in args.reports:
            page = chromium.new_page()
            page.goto(report.resolve().as_uri())
            pdf = page.pdf(format="A4", prefer_css_page_size=True)
            print(f"{report}: {len(PAGE.findall(pdf))} pages")
        chromium.close()


if __name__ == "__main__":
    main()
