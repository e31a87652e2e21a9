"""Orchestration: what to draw (:mod:`.job`), one file at a time (:mod:`.stream`), on worker processes
or any executor (:mod:`.workers`), in chunks joined afterwards (:mod:`.chunks`), demo reels and
single pictures; :mod:`.library` is the front door the package exports."""
