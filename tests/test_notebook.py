"""The example notebook runs from top to bottom (nbclient) and shows the appendix figures."""

from pathlib import Path

import nbformat
from nbclient import NotebookClient


EXAMPLES = Path(__file__).parents[1] / "examples"


def test_example_notebook_runs():
    """Run in its own folder, as Jupyter runs it: it reads seed000-appendix-kurz.toml beside it."""
    nb = nbformat.read(EXAMPLES / "python-api.ipynb", as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(EXAMPLES)}}).execute()
    text = "\n".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs)
    # appendix of Valve-train practical works (n.d.): time-area 2.8564 mm2 s over the intake stroke (spec/valvetrain-works-1-8.md, 4.4)
    assert "time-area 2.8564 mm2 s" in text
    html = [o["data"]["text/html"] for o in nb.cells[1].outputs if "text/html" in o.get("data", {})]
    assert html and "<table>" in html[0]
    # the last cell draws the valve lift: a PNG image, not the text "<Figure size 600x300 with 1 Axes>"
    assert any("image/png" in o.get("data", {}) for o in nb.cells[-1].outputs)
