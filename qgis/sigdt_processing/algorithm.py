"""The Processing algorithm ``sigdt:outlines_from_points``: QGIS's parameters, feedback and
sinks around sigdt's ``reconstruct_many``. Groups run in batches, so that progress moves and
a cancel takes effect between batches; a group sigdt refuses or cannot outline is reported
in the log, and the other groups go on."""

import os

from qgis.core import (
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingAlgorithm,
    QgsProcessingException,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsWkbTypes,
)

from . import features
from .points import read_groups
from .reconstruct import Failure, load_sigdt, reconstruct_batch

EXPECT = ["curves", "areas"]
#: Output parameter, geometry type, description. Lines and left-out points may be skipped
#: (optional, written by default).
OUTPUTS = [
    ("AREAS", QgsWkbTypes.MultiPolygon, QgsProcessing.TypeVectorPolygon, "Areas"),
    ("LINES", QgsWkbTypes.MultiLineString, QgsProcessing.TypeVectorLine, "Lines"),
    ("LEFT_OUT", QgsWkbTypes.Point, QgsProcessing.TypeVectorPoint, "Left-out points"),
]
OPTIONAL = {"LINES", "LEFT_OUT"}
#: Progress: reading the features, then the groups' batches.
READING = 10.0


class OutlinesFromPoints(QgsProcessingAlgorithm):
    def name(self):
        return "outlines_from_points"

    def displayName(self):  # QGIS's names, from here on
        return "Outlines from points (sigdt)"

    def shortHelpString(self):
        return (
            "Reconstructs the outlines (areas) and curves (lines) that unorganised points "
            "sample, with sigdt's SIG-AUTO method, one group of points per value of the "
            "group field. Line and polygon layers give their vertices. Longitude/latitude "
            "is reconstructed in a plane centred on each group; every output is in the "
            "input's CRS.\n\nAreas: one MultiPolygon per group. Lines: open curves "
            "(kind 'path') and curves that meet at junctions (kind 'network'). Left-out "
            "points: outliers and points inside, with their row (0-based position of the "
            "point in the input) and reason. status, warning and diagnosis say whether a "
            "group's result may not be its points' curves, and why.\n\n"
            "Expect 'areas' when every curve is a closed outline (polygon vertices, "
            "parcels, islands): open readings are closed where a polygon fits as well.\n\n"
            "Needs the sigdt Python package in the Python QGIS runs: without it, the "
            "algorithm's error gives the command that installs the wheel."
        )

    def createInstance(self):
        return OutlinesFromPoints()

    def canExecute(self):
        sigdt, message = load_sigdt()
        return sigdt is not None, message or ""

    def initAlgorithm(self, config=None):
        kinds = [
            QgsProcessing.TypeVectorPoint,
            QgsProcessing.TypeVectorLine,
            QgsProcessing.TypeVectorPolygon,
        ]
        self.addParameter(QgsProcessingParameterFeatureSource("INPUT", "Points", kinds))
        self.addParameter(
            QgsProcessingParameterField(
                "GROUP_FIELD",
                "One outline per value of",
                parentLayerParameterName="INPUT",
                optional=True,
            )
        )
        self.addParameter(
            QgsProcessingParameterEnum("EXPECT", "The points outline", EXPECT, defaultValue=1)
        )
        for name, _, kind, description in OUTPUTS:
            optional = name in OPTIONAL
            self.addParameter(
                QgsProcessingParameterFeatureSink(
                    name, description, kind, optional=optional, createByDefault=True
                )
            )

    def processAlgorithm(self, parameters, context, feedback):
        sigdt, message = load_sigdt()
        if sigdt is None:
            raise QgsProcessingException(message)
        source = self.parameterAsSource(parameters, "INPUT", context)
        if source is None:
            raise QgsProcessingException(self.invalidSourceError(parameters, "INPUT"))
        group_name = self.parameterAsString(parameters, "GROUP_FIELD", context)
        expect = EXPECT[self.parameterAsEnum(parameters, "EXPECT", context)]
        crs = source.sourceCrs()
        group_field = None
        if group_name:
            index = source.fields().lookupField(group_name)
            if index < 0:
                names = ", ".join(source.fields().names())
                raise QgsProcessingException(
                    f"The input has no field {group_name!r} to group by (its fields: {names})"
                )
            group_field = source.fields().at(index)
        sinks, results = {}, {}
        for name, wkb, _, _ in OUTPUTS:
            fields = features.fields(name, group_field)
            sink, dest = self.parameterAsSink(parameters, name, context, fields, wkb, crs)
            if sink is not None:
                sinks[name], results[name] = sink, dest
            elif name not in OPTIONAL or parameters.get(name) is not None:
                raise QgsProcessingException(self.invalidSinkError(parameters, name))

        groups = read_groups(source, group_name, feedback, READING)
        if groups is None:
            return results
        total = sum(len(g.xy) for g in groups)
        if total == 0:
            raise QgsProcessingException(
                "The input has no points: its features have no geometry, or empty ones"
            )
        lon_lat = crs.isValid() and crs.isGeographic()
        if lon_lat:
            feedback.pushInfo(
                f"{crs.authid()} is longitude/latitude: each group is reconstructed in an "
                "azimuthal equidistant plane centred on its points"
            )
        run = _Run(sigdt, sinks, expect, lon_lat, group_field is not None, feedback)
        done, written = 0, 0
        for batch in _batches(groups, os.cpu_count() or 1):
            if feedback.isCanceled():
                feedback.pushInfo(f"Cancelled: {written} of {len(groups)} group(s) written")
                break
            run.batch(batch)
            written += len(batch)
            done += sum(len(g.xy) for g in batch)
            feedback.setProgress(READING + (100.0 - READING) * done / total)
        run.summary(written)
        return results


class _Run:
    """Writes each group's result, and keeps what the log summarises."""

    def __init__(self, sigdt, sinks, expect, lon_lat, with_key, feedback):
        self.sigdt, self.sinks, self.expect = sigdt, sinks, expect
        self.lon_lat, self.with_key, self.feedback = lon_lat, with_key, feedback
        self.failed, self.warned = [], []

    def batch(self, groups):
        arrays = [_array(g.xy) for g in groups]
        results = reconstruct_batch(self.sigdt, arrays, expect=self.expect, lon_lat=self.lon_lat)
        for group, rec in zip(groups, results):
            name = f"group {group.key!r}" if self.with_key else "the points"
            if isinstance(rec, Failure):
                self.failed.append(name)
                self.feedback.reportError(f"{name}: {rec}", False)
                continue
            values = features.group_values(group, rec, self.with_key)
            outputs = {
                "AREAS": [features.area_feature(rec, values)],
                "LINES": features.line_features(rec, values),
                "LEFT_OUT": features.left_out_features(rec, values, group),
            }
            for layer, feats in outputs.items():
                for feature in feats if layer in self.sinks else []:
                    if feature is not None:
                        self.sinks[layer].addFeature(feature, QgsFeatureSink.FastInsert)
            if not rec.polygons and not rec.paths:
                self.failed.append(name)
                self.feedback.pushWarning(f"{name}: no outline ({rec.status}): {_message(rec)}")
            elif rec.warns:
                self.warned.append(name)
                self.feedback.pushWarning(f"{name}: {rec.status}: {_message(rec)}")

    def summary(self, n_groups):
        self.feedback.pushInfo(
            f"{n_groups} group(s): {len(self.failed)} without an outline, {len(self.warned)} "
            "whose result may not be their points' curves (warning = true)"
        )


def _batches(groups, cores):
    """The groups in runs of about a hundredth of them, at least one per core (sigdt runs a
    batch in parallel, one thread per core), so that progress and cancel come between
    batches without idling the cores."""
    size = max(cores, len(groups) // 100)
    return [groups[k : k + size] for k in range(0, len(groups), size)]


def _array(xy):
    import numpy as np  # sigdt's dependency: importable once sigdt is

    return np.asarray(xy, dtype=np.float64).reshape(-1, 2)


def _message(rec):
    """The sampling check's findings, else what the status means (a small result's
    GeoJSON properties: ``Reconstruction`` has no public status message)."""
    found = [f["message"] for f in rec.diagnosis]
    return "; ".join(found) or rec.to_geojson()["properties"]["status_message"]
