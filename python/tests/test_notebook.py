"""The example notebooks run: their code cells are executed in order, in one namespace, from
the notebook's folder (as Jupyter would run them), with matplotlib's Agg backend; the checks
below are on what the cells leave behind."""

from __future__ import annotations

import json
import os
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt

EXAMPLES = Path(__file__).resolve().parents[2] / "docs" / "examples"


def _run(notebook: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, object]:
    cells = json.loads(notebook.read_text())["cells"]
    code = [("".join(c["source"]), k) for k, c in enumerate(cells) if c["cell_type"] == "code"]
    assert len(code) >= 4
    assert all(not c.get("outputs") for c in cells if c["cell_type"] == "code"), "stored bare"
    monkeypatch.chdir(notebook.parent)
    namespace: dict[str, object] = {"__name__": "__main__"}
    for source, k in code:
        try:
            exec(compile(source, f"{notebook.name}[cell {k}]", "exec"), namespace)  # noqa: S102  # the notebook is ours
        except Exception as e:  # pragma: no cover  # names the cell that failed
            raise AssertionError(f"cell {k} of {notebook.name} failed: {e!r}") from e
    plt.close("all")
    return namespace


def test_the_real_outline_notebook_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    namespace = _run(EXAMPLES / "real_outline.ipynb", monkeypatch)
    auto = namespace["auto"]
    assert auto.status == "polygon" and len(auto.left_out) > 0  # type: ignore[attr-defined]
    feature = namespace["feature"]
    assert feature["geometry"]["type"] == "Polygon"  # type: ignore[index]
    assert os.path.getsize(namespace["out"]) > 100  # type: ignore[arg-type]


def test_the_island_geopackage_notebook_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    namespace = _run(EXAMPLES / "islands_gis.ipynb", monkeypatch)
    back = namespace["back"]
    assert back.crs.to_epsg() == 4326  # type: ignore[attr-defined]
    assert back["status"].tolist() == ["polygons"] * 4  # type: ignore[index]
    assert set(back.geom_type) == {"MultiPolygon"}  # type: ignore[attr-defined]
    # The twelve islands of the true outline (SIG-CONNECT2D, the default before, merged two
    # pairs of them).
    assert len(namespace["aland"]) == 12  # type: ignore[arg-type]
