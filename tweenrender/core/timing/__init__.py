"""When things move: timing curves (:mod:`.easing`), spacing charts (:mod:`.spacing`), and the
timeline (:mod:`.timeline`: keys → segments → shapes at any time, stagger, growing and fading
contours)."""
