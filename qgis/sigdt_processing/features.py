"""A group's result as features of the three output layers, one geometry type each (a GIS
layer holds one): ``AREAS`` one MultiPolygon per group, ``LINES`` one MultiLineString per
group and kind (``path``: open curves; ``network``: curves that end at a junction, where
curves cross or meet), ``LEFT_OUT`` one point per point sigdt left out on purpose. Every
feature carries the group's value and the group's ``status``, ``warning``, ``diagnosis``
and ``n_points``, so each layer reads on its own. sigdt's polygons, paths and junctions
decide what goes where, as its own GIS writers split them."""

from qgis.core import (
    QgsFeature,
    QgsField,
    QgsFields,
    QgsGeometry,
    QgsLineString,
    QgsMultiLineString,
    QgsMultiPolygon,
    QgsPoint,
    QgsPolygon,
)
from qgis.PyQt.QtCore import QVariant

#: The group's columns on every layer, after the group field.
_GROUP_FIELDS = [
    ("status", QVariant.String),
    ("warning", QVariant.Bool),
    ("diagnosis", QVariant.String),
    ("n_points", QVariant.LongLong),
]
_EXTRA_FIELDS = {
    "AREAS": [],
    "LINES": [("kind", QVariant.String)],
    "LEFT_OUT": [("row", QVariant.LongLong), ("reason", QVariant.String)],
}


def fields(layer, group_field):
    """The fields of output ``layer`` (``"AREAS"``, ``"LINES"``, ``"LEFT_OUT"``): a copy of
    the input's group field (a ``QgsField``, or ``None``), the group's columns, then the
    layer's own."""
    out = QgsFields()
    if group_field is not None:
        out.append(QgsField(group_field))
    for name, kind in _GROUP_FIELDS + _EXTRA_FIELDS[layer]:
        out.append(QgsField(name, kind))
    return out


def group_values(group, rec, with_key):
    """The attribute values every feature of ``group`` starts with."""
    diagnosis = "; ".join(f["message"] for f in rec.diagnosis)
    values = [rec.status, bool(rec.warns), diagnosis, len(group.xy)]
    return ([group.key] if with_key else []) + values


def area_feature(rec, values):
    """The group's polygons (shells with their holes) as one feature, or ``None``. sigdt's
    ``Reconstruction.layers`` gives them split at the antimeridian when the points are
    longitude/latitude (RFC 7946 §3.1.9, the code of its own GIS writers), so a ring through
    179.9° and -179.9° is two valid polygons meeting there, not one spanning the world."""
    polygons = rec.layers()["areas"]
    if not polygons:
        return None
    multi = QgsMultiPolygon()
    for rings in polygons:
        polygon = QgsPolygon()
        polygon.setExteriorRing(_ring(rings[0]))
        for hole in rings[1:]:
            polygon.addInteriorRing(_ring(hole))
        multi.addGeometry(polygon)
    return _feature(multi, values)


def line_features(rec, values):
    """The group's open paths: a ``path`` feature for those with no end at a junction, a
    ``network`` feature for the others (either left out when empty); split at the
    antimeridian as :func:`area_feature`'s polygons are."""
    layers = rec.layers()
    out = []
    for kind, layer in [("path", "paths"), ("network", "networks")]:
        if layers[layer]:
            multi = QgsMultiLineString()
            for line in layers[layer]:
                multi.addGeometry(_line(line))
            out.append(_feature(multi, values + [kind]))
    return out


def left_out_features(rec, values, group):
    """One point per point sigdt left out, with its ``row`` in the source and ``reason``."""
    out = []
    for i, reason in zip(rec.left_out.tolist(), rec.left_out_reasons):
        x, y = group.xy[i]
        out.append(_feature(QgsPoint(x, y), values + [group.rows[i], reason]))
    return out


def _ring(coordinates):
    """A ring as QGIS stores it: its first vertex repeated at the end."""
    x, y = coordinates[:, 0].tolist(), coordinates[:, 1].tolist()
    if (x[0], y[0]) != (x[-1], y[-1]):
        x.append(x[0])
        y.append(y[0])
    return QgsLineString(x, y)


def _line(coordinates):
    return QgsLineString(coordinates[:, 0].tolist(), coordinates[:, 1].tolist())


def _feature(geometry, values):
    feature = QgsFeature()
    feature.setGeometry(QgsGeometry(geometry))
    feature.setAttributes(values)
    return feature
