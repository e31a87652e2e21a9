"""Rasterising with skia: world → pixel mapping, fills, strokes, labels, panels."""
