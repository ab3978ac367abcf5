"""The Processing provider ``sigdt``: its algorithms are ``sigdt:NAME`` in the toolbox,
models and ``qgis_process run``."""

from qgis.core import QgsProcessingProvider

from .algorithm import OutlinesFromPoints


class SigdtProvider(QgsProcessingProvider):
    def id(self):
        return "sigdt"

    def name(self):
        return "sigdt"

    def longName(self):  # QGIS's name
        return "sigdt: curves and outlines from unorganised points"

    def loadAlgorithms(self):  # QGIS's name
        self.addAlgorithm(OutlinesFromPoints())
