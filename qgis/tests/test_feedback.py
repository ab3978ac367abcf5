"""Progress and cancel, which ``qgis_process`` cannot drive: the algorithm run in this
process's QGIS (headless, ``harness``) with a feedback object that records progress and
cancels."""

import math
import unittest

import harness  # noqa: F401  # QGIS started, the plugin and sigdt importable
from qgis.core import (
    QgsApplication,
    QgsFeature,
    QgsGeometry,
    QgsPointXY,
    QgsProcessingContext,
    QgsProcessingFeedback,
    QgsVectorLayer,
)
from sigdt_processing.algorithm import READING
from sigdt_processing.provider import SigdtProvider

GROUPS = 600


class Recording(QgsProcessingFeedback):
    """Keeps every progress value; cancels once reconstruction has reported progress, when
    ``cancel_after_first_batch``."""

    def __init__(self, cancel_after_first_batch=False):
        super().__init__()
        self.seen = []
        self.cancel_after_first_batch = cancel_after_first_batch
        self.progressChanged.connect(self.record)

    def record(self, value):
        self.seen.append(value)
        if self.cancel_after_first_batch and value > READING:
            self.cancel()


def rings_layer():
    """``GROUPS`` rings of 12 points in EPSG:3857, one per value of ``island``."""
    layer = QgsVectorLayer("Point?crs=EPSG:3857&field=island:integer", "rings", "memory")
    features = []
    for g in range(GROUPS):
        for k in range(12):
            t = 2 * math.pi * k / 12
            feature = QgsFeature(layer.fields())
            feature.setGeometry(
                QgsGeometry.fromPointXY(QgsPointXY(g * 100 + 10 * math.cos(t), 10 * math.sin(t)))
            )
            feature.setAttributes([g])
            features.append(feature)
    layer.dataProvider().addFeatures(features)
    return layer


class Feedback(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.provider = SigdtProvider()
        QgsApplication.processingRegistry().addProvider(cls.provider)
        cls.layer = rings_layer()

    @classmethod
    def tearDownClass(cls):
        QgsApplication.processingRegistry().removeProvider(cls.provider)

    def areas(self, feedback):
        """The number of features in AREAS after a run with ``feedback``."""
        algorithm = QgsApplication.processingRegistry().createAlgorithmById(
            "sigdt:outlines_from_points"
        )
        context = QgsProcessingContext()
        parameters = {"INPUT": self.layer, "GROUP_FIELD": "island"}
        for name in ("AREAS", "LINES", "LEFT_OUT"):
            parameters[name] = "TEMPORARY_OUTPUT"
        results, ok = algorithm.run(parameters, context, feedback)
        self.assertTrue(ok, results)
        # The context owns the temporary layers: count before it goes.
        return context.getMapLayer(results["AREAS"]).featureCount()

    def test_progress_rises_to_100_over_the_batches(self):
        feedback = Recording()
        self.assertEqual(self.areas(feedback), GROUPS)
        self.assertEqual(feedback.seen, sorted(feedback.seen))
        self.assertEqual(feedback.seen[-1], 100)
        # Several batches: progress between the reading share and the end.
        self.assertTrue(any(READING < p < 100 for p in feedback.seen), feedback.seen)

    def test_cancel_stops_between_batches(self):
        feedback = Recording(cancel_after_first_batch=True)
        written = self.areas(feedback)
        # The first batch is written, no later one.
        self.assertGreater(written, 0)
        self.assertLess(written, GROUPS)
        self.assertLess(max(feedback.seen), 100)


if __name__ == "__main__":
    unittest.main()
