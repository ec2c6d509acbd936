"""Exit codes and the exceptions that carry them out of the launcher."""


EXIT_OK = 0
EXIT_FAILURE = 1
EXIT_BAD_INPUT = 2
EXIT_INTERRUPTED = 130


class UsageError(Exception):
    """Bad input from the user (or a missing build): 'cosph: <msg>', exit 2."""


class Exit(Exception):
    """Leave main() with this exit code; the message was already printed."""

    def __init__(self, code):
        super().__init__(code)
        self.code = code


class Interrupted(Exception):
    """SIGINT/SIGTERM/SIGHUP arrived before any solver was started."""
