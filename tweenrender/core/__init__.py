"""The interpolation core: pure functions over numpy arrays (no skia, no files)."""
