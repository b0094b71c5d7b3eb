"""The example notebook runs from top to bottom (nbclient) and shows the appendix figures."""

from pathlib import Path

import nbformat
from nbclient import NotebookClient


def test_example_notebook_runs():
    nb = nbformat.read(Path(__file__).parents[1] / "examples" / "python-api.ipynb", as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3").execute()
    text = "\n".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs)
    # appendix of Valve-train practical works (n.d.): time-area 2.8564 mm2 s over the intake stroke (spec/valvetrain-works-1-8.md, 4.4)
    assert "time-area 2.8564 mm2 s" in text
    html = [o["data"]["text/html"] for o in nb.cells[1].outputs if "text/html" in o.get("data", {})]
    assert html and "<table>" in html[0]
