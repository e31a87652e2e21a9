"""Vertex correspondence (maths §2, §5.10): which vertex of one key goes with which of the next.

:mod:`.correspond` is the entry point (least work or Sederberg–Greenwood energy, cyclic and open);
its searches are :mod:`._small_dtw` (numpy, small keys), :mod:`._cyclic_dtw` and :mod:`._lean_dtw`
(numba kernels on the grid of :mod:`._dtw_grid`; the Sederberg–Greenwood cost's in :mod:`._sg_kernel`),
:mod:`._sg_search` (branch and bound over starts); shape hints are :mod:`.hints`
and the hinted search :mod:`.hint_search` (kernel :mod:`._hint_kernel`); :mod:`.assignment` pairs
whole contours and elements at least cost.
"""
