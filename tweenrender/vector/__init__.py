"""Vector output: a job's paths as keyframes for players that move values on straight lines or
Béziers between them (:mod:`.keyframes`), every frame reduced to them (:mod:`.export`), with gradient
fills and clip paths sampled and keyframed (:mod:`.paint_keys`); ``encode``'s Lottie and animated SVG
writers put them in files."""
