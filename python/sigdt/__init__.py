"""sigdt: parameter-free 2D curve reconstruction from unorganised points.

SIG-CONNECT2D (Marin, Ohrhallinger, Wimmer, "SIGDT: 2D Curve Reconstruction", Pacific
Graphics 2022), implemented in Rust: numpy arrays in, numpy arrays and shapely geometries
out.

>>> import numpy as np, sigdt
>>> t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
>>> rec = sigdt.reconstruct(np.c_[np.cos(t), np.sin(t)])
>>> rec.status, len(rec.edges), rec.is_manifold
('polygon', 64, True)
"""

from ._api import proximity_graph, read_points, reconstruct, reconstruct_many
from ._core import GRAPH_KINDS, METHODS, __version__
from ._eval import evaluate, graph_epsilon, graph_overlap
from ._geometries import outlines
from ._result import Reconstruction
from ._trace import PHASES, Trace, trace
from .errors import InternalError, InvalidInputError, ParseError, SigdtError, SigdtWarning
from .geopandas import reconstruct_frame
from .plot import plot_steps
from .shapely import from_shapely, to_shapely

__all__ = [
    "GRAPH_KINDS",
    "METHODS",
    "PHASES",
    "InternalError",
    "InvalidInputError",
    "ParseError",
    "Reconstruction",
    "SigdtError",
    "SigdtWarning",
    "Trace",
    "__version__",
    "evaluate",
    "from_shapely",
    "graph_epsilon",
    "graph_overlap",
    "outlines",
    "plot_steps",
    "proximity_graph",
    "read_points",
    "reconstruct",
    "reconstruct_frame",
    "reconstruct_many",
    "to_shapely",
    "trace",
]
