"""The points of a QGIS feature source, grouped by a field's value, as sigdt reads a file:
every vertex of every feature (a point layer's points, a line's vertices, a polygon's ring
vertices with each ring's closing vertex once), numbered from 0 in the order the source
gives them. That number is the ``row`` of a left-out point, so it equals the CLI's for the
same GeoPackage."""

from qgis.core import QgsFeatureRequest, QgsWkbTypes
from qgis.PyQt.QtCore import QVariant


class Group:
    """One group's points: ``key`` (the field's value, ``None`` for NULL or no field),
    ``xy`` (``[x, y]`` lists) and ``rows`` (each point's number in the source)."""

    __slots__ = ("key", "rows", "xy")

    def __init__(self, key):
        self.key = key
        self.xy = []
        self.rows = []


def read_groups(source, group_field, feedback, progress_share):
    """The source's points as a list of :class:`Group`, in the order each group first
    appears; ``None`` when ``feedback`` is cancelled. Progress runs from 0 to
    ``progress_share`` percent over the features."""
    index = source.fields().lookupField(group_field) if group_field else -1
    request = QgsFeatureRequest().setSubsetOfAttributes([index] if index >= 0 else [])
    polygons = QgsWkbTypes.geometryType(source.wkbType()) == QgsWkbTypes.PolygonGeometry
    total = max(source.featureCount(), 1)
    groups = {}
    row = 0
    for n, feature in enumerate(source.getFeatures(request)):
        if feedback.isCanceled():
            return None
        key = _value(feature.attribute(index)) if index >= 0 else None
        group = groups.get(key)
        if group is None:
            group = groups[key] = Group(key)
        for x, y in _vertices(feature.geometry(), polygons):
            group.xy.append([x, y])
            group.rows.append(row)
            row += 1
        if n % 1000 == 0:
            feedback.setProgress(progress_share * n / total)
    return list(groups.values())


def _value(value):
    """A field value as a plain, hashable key: NULL (a null ``QVariant``) is ``None``."""
    if isinstance(value, QVariant):
        return None if value.isNull() else value.value()
    return value


def _vertices(geometry, polygons):
    """``(x, y)`` of every vertex of ``geometry`` (none for a missing or empty one); a
    polygon ring's closing vertex, a copy of its first, is not a second point."""
    if geometry is None or geometry.isNull():
        return
    for part in geometry.constGet().coordinateSequence():
        for ring in part:
            if polygons and len(ring) > 1 and ring[0] == ring[-1]:
                ring = ring[:-1]
            for p in ring:
                yield p.x(), p.y()
