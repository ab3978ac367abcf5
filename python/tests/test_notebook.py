"""docs/examples/real_outline.ipynb runs: its code cells are executed in order, in one
namespace, from the notebook's folder (as Jupyter would run them), with matplotlib's Agg
backend; the checks below are on what the cells leave behind."""

from __future__ import annotations

import json
import os
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt

NOTEBOOK = Path(__file__).resolve().parents[2] / "docs" / "examples" / "real_outline.ipynb"


def test_the_example_notebook_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    code = [("".join(c["source"]), k) for k, c in enumerate(cells) if c["cell_type"] == "code"]
    assert len(code) >= 4
    assert all(not c.get("outputs") for c in cells if c["cell_type"] == "code"), "stored bare"
    monkeypatch.chdir(NOTEBOOK.parent)
    namespace: dict[str, object] = {"__name__": "__main__"}
    for source, k in code:
        try:
            exec(compile(source, f"{NOTEBOOK.name}[cell {k}]", "exec"), namespace)  # noqa: S102  # the notebook is ours
        except Exception as e:  # pragma: no cover  # names the cell that failed
            raise AssertionError(f"cell {k} of {NOTEBOOK.name} failed: {e!r}") from e
    auto = namespace["auto"]
    assert auto.status == "polygon" and len(auto.left_out) > 0  # type: ignore[attr-defined]
    feature = namespace["feature"]
    assert feature["geometry"]["type"] == "Polygon"  # type: ignore[index]
    assert os.path.getsize(namespace["out"]) > 100  # type: ignore[arg-type]
    plt.close("all")
