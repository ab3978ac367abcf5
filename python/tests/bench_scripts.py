"""The scripts of python/bench, imported by the tests that check them: they are programs,
not a package, and import their siblings (``from outline_data import ...``)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

BENCH = Path(__file__).resolve().parents[2] / "python" / "bench"


def load(name: str) -> ModuleType:
    """The script ``python/bench/NAME.py`` as module ``name`` (registered, so that
    dataclasses and pickling find it), with its folder on ``sys.path`` for its siblings."""
    if str(BENCH) not in sys.path:
        sys.path.insert(0, str(BENCH))
    spec = importlib.util.spec_from_file_location(name, BENCH / f"{name}.py")
    assert spec is not None and spec.loader is not None, f"no script {name}.py in {BENCH}"
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module
