"""Reports on a scene as plain data (the documented ``--json`` outputs) and as text."""
