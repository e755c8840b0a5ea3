"""The example notebook (docs/api.ipynb) is executed in a fresh kernel and must print what it
shows: every text output of every code cell as stored, the drawing as an SVG, the check table as
HTML. Re-make the stored outputs after a deliberate change: ``python -m tests.test_notebook``."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from tests.conftest import ROOT

NOTEBOOK = ROOT / "docs" / "api.ipynb"


def execute(path: Path = NOTEBOOK):
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=180, kernel_name="python3",
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    return nb


def texts(cell) -> list[str]:
    """A code cell's outputs as text: printed text, and the plain form of each result. Printed text
    is one piece however many messages the kernel sent it in (a loaded machine splits it)."""
    out = []
    last_stream = None
    for o in cell.get("outputs", []):
        if o["output_type"] == "stream":
            if last_stream == o.get("name") and out:
                out[-1] += o["text"]
            else:
                out.append(o["text"])
            last_stream = o.get("name")
            continue
        last_stream = None
        if o["output_type"] in ("execute_result", "display_data"):
            out.append(o["data"].get("text/plain", ""))
        elif o["output_type"] == "error":
            out.append(f"ERROR {o['ename']}: {o['evalue']}")
    return out


def test_the_notebook_runs_and_shows_what_it_stores():
    pytest.importorskip("nbclient", reason="a test dependency: pip install '.[test]'")
    import nbformat

    stored = nbformat.read(NOTEBOOK, as_version=4)
    ran = execute()
    code = [(a, b) for a, b in zip(stored.cells, ran.cells) if a.cell_type == "code"]
    assert len(code) >= 7
    for old, new in code:
        assert texts(new) == texts(old), old.source
    kinds = [set(o.get("data", {})) for _, new in code for o in new.outputs]
    assert {"image/svg+xml", "text/plain"} in kinds  # the drawing, shown by its _repr_svg_
    assert {"text/html", "text/plain"} in kinds      # the check table (and the DataFrame) as HTML
    svg = next(o["data"]["image/svg+xml"] for _, new in code for o in new.outputs if "image/svg+xml" in o.get("data", {}))
    assert svg.startswith("<svg") and 'width="222mm"' in svg


if __name__ == "__main__":  # re-make the stored outputs
    import nbformat

    nbformat.write(execute(), NOTEBOOK)
    sys.exit(0)
