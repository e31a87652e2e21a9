"""What to draw, below both renderers: the render options, checked once (:mod:`.options`), and the
job they make of a scene (:mod:`.job`: panels, size, rate, frames, overlays). The raster pipeline
(:mod:`tweenrender.pipeline`) draws a job's frames; the vector stage (:mod:`tweenrender.vector`)
writes its paths."""
