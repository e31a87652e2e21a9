"""Raster orchestration: a job's frames drawn (:mod:`.frames`), streamed into one file (:mod:`.stream`),
on worker processes or any executor (:mod:`.workers`), in chunks joined afterwards (:mod:`.chunks`),
or on a dask cluster (:mod:`.cluster`); :mod:`.library` is what the front door (:mod:`tweenrender.api`)
calls to load, draw and write."""
