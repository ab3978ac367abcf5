"""The plugin object: it only registers the Processing provider, in the desktop and in
``qgis_process``, which calls :meth:`SigdtPlugin.initProcessing` alone (``hasProcessingProvider``
in metadata.txt)."""

from qgis.core import QgsApplication

from .provider import SigdtProvider


class SigdtPlugin:
    def __init__(self, iface):
        self.iface = iface
        self.provider = None

    def initProcessing(self):  # QGIS's name
        # Registered once, even when both QGIS entry points call this.
        if self.provider is None:
            self.provider = SigdtProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # QGIS's name
        self.initProcessing()

    def unload(self):
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
