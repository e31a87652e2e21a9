"""The interpolation methods: :mod:`.registry` lists every one (name, paths function, docs row) and
runs them; each method's paths live in a module of their own (:mod:`.paths` linear, nonlinear and
rigid; :mod:`.joints`, :mod:`.arap`, :mod:`.intrinsic`, :mod:`.injective`, :mod:`.qcurves` for
``auto``), on the meshes of :mod:`.mesh` (one outline), :mod:`.compatible` and :mod:`.mesh_overlay`
(every contour of an element, in two keys) and :mod:`.bounded_distortion` (shape-keeping solves on
those meshes). A new method is one registry entry and its module here.
"""
