"""The cosph launcher: runs a case's processes (see coupler/cosph)."""
