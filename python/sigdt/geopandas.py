"""GeoPandas-shaped results: a result as a ``GeoDataFrame``, and one outline per group of
points in one call.

GeoPandas is optional: it is imported when these functions run. The coordinate reference
system of the input is kept on every result; a geographic one (longitude/latitude) is
reconstructed in a plane centred on each group (azimuthal equidistant), as
:func:`sigdt.reconstruct` does.
"""

from __future__ import annotations

from ._frame import GROUP_COLUMNS, layers, reconstruct_frame
from ._geodataframe import CURVE_COLUMNS, to_geopandas

__all__ = ["CURVE_COLUMNS", "GROUP_COLUMNS", "layers", "reconstruct_frame", "to_geopandas"]
