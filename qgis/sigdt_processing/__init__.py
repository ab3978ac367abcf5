"""sigdt Processing: a QGIS plugin whose Processing provider offers "Outlines from points
(sigdt)". QGIS calls :func:`classFactory`; nothing else is imported until then, so that a
missing sigdt package shows up as the algorithm's message, not as a plugin that fails to
load (licence: MIT OR Apache-2.0, see LICENSE)."""


def classFactory(iface):  # the name QGIS looks for
    """The plugin object QGIS (or ``qgis_process``, with ``iface`` None) keeps and starts."""
    from .plugin import SigdtPlugin

    return SigdtPlugin(iface)
