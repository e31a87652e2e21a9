"""Rasterising with skia: world → pixel mapping, the drawing surface, panels, overlays, title cards,
fonts, and the diagrams in :mod:`.plots`. The only package that imports skia."""
