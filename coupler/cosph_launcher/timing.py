"""How long the launcher waits, in one place.

The defaults are what users want; the COSPH_*_S overrides exist so the
tests can exercise the timeouts without waiting for them."""

import os

def _env_seconds(name, default):
    """A timeout that can be overridden from the environment.

    The defaults are what users want; the overrides exist so the tests can
    exercise the timeouts without waiting for them."""
    try:
        value = float(os.environ.get(name, ""))
    except ValueError:
        return default
    return value if value >= 0 else default


TERM_GRACE_S = _env_seconds("COSPH_TERM_GRACE_S", 5.0)      # SIGTERM -> SIGKILL after a failure
INT_GRACE_S = _env_seconds("COSPH_INT_GRACE_S", 10.0)       # SIGINT -> SIGKILL on Ctrl-C (final snapshots)
STRAGGLER_S = _env_seconds("COSPH_STRAGGLER_S", 30.0)       # others still running after one finished
PLAIN_PROGRESS_EVERY_S = _env_seconds("COSPH_PROGRESS_EVERY_S", 10.0)
READER_JOIN_S = 1.0     # how long to wait for the rest of an exited process's output
TTY_REDRAW_S = 0.2      # limit redraws of the status line
RATE_WINDOW_S = 20.0    # steps/s and time left are averaged over this window
