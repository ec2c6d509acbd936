"""Terminal output: the progress of the processes and the status line."""

import collections
import os
import re
import sys
import time

from .timing import PLAIN_PROGRESS_EVERY_S, RATE_WINDOW_S, TTY_REDRAW_S

def emit(stream, text):
    """Write and flush, surviving a reader that went away (`cosph ... | head`,
    a closed terminal). That must not abort a simulation that may have run
    for hours, so the stream is pointed at /dev/null and the run goes on."""
    try:
        stream.write(text)
        stream.flush()
    except OSError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, stream.fileno())
        os.close(devnull)


def fmt_duration(seconds):
    seconds = max(0.0, seconds)
    if seconds < 60:
        return f"{seconds:.1f} s"
    seconds = int(round(seconds))
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d} s"
    return f"{seconds // 3600} h {seconds % 3600 // 60:02d} min"


def fmt_size(nbytes):
    for unit in ("B", "kB", "MB", "GB"):
        if nbytes < 1000 or unit == "GB":
            return f"{nbytes:.0f} {unit}" if unit == "B" else f"{nbytes:.1f} {unit}"
        nbytes /= 1000.0
    return ""


PROGRESS_RE = re.compile(r"^progress\s+(.*)$")


def parse_progress(line):
    """'progress t=0.1 end=2 step=100 dt=1e-4' -> (t, end, step) or None."""
    match = PROGRESS_RE.match(line.strip())
    if not match:
        return None
    fields = dict(tok.split("=", 1) for tok in match.group(1).split() if "=" in tok)
    try:
        t, end = float(fields["t"]), float(fields["end"])
        step = int(fields["step"]) if "step" in fields else None
    except (KeyError, ValueError):
        return None
    return t, end, step


class Progress:
    """Latest progress of one process, with a short history for rates."""

    def __init__(self):
        self.t = self.end = self.step = None
        self.samples = collections.deque()   # (wall time, sim time, step)

    def add(self, now, t, end, step):
        self.t, self.end, self.step = t, end, step
        self.samples.append((now, t, step))
        while len(self.samples) > 2 and now - self.samples[0][0] > RATE_WINDOW_S:
            self.samples.popleft()

    @property
    def fraction(self):
        if self.t is None or not self.end or self.end <= 0:
            return None
        return min(1.0, max(0.0, self.t / self.end))

    def _span(self):
        if len(self.samples) < 2:
            return None
        (w0, t0, s0), (w1, t1, s1) = self.samples[0], self.samples[-1]
        return (w1 - w0, t1 - t0, None if s0 is None or s1 is None else s1 - s0) \
            if w1 > w0 else None

    def steps_per_s(self):
        span = self._span()
        return None if span is None or span[2] is None else span[2] / span[0]

    def wall_left(self):
        span = self._span()
        if span is None or span[1] <= 0:
            return None
        return max(0.0, self.end - self.t) * span[0] / span[1]


def status_text(children):
    """One line about the slowest process: it decides when the run ends."""
    tracked = [c for c in children if c.progress.fraction is not None]
    if not tracked:
        return None
    slowest = min(tracked, key=lambda c: c.progress.fraction)
    p = slowest.progress
    parts = [f"t = {p.t:.4g} / {p.end:.4g} s", f"{100 * p.fraction:.1f}%"]
    rate = p.steps_per_s()
    if rate is not None:
        parts.append(f"{rate:.1f} steps/s" if rate < 10 else f"{rate:.0f} steps/s")
    left = p.wall_left()
    parts.append(f"~{fmt_duration(left)} left" if left is not None else "time left: estimating")
    if len(children) > 1:
        parts.append(f"slowest: {slowest.tag}")
    return ", ".join(parts)


class Console:
    """All terminal output goes through here, so passed-through lines and the
    status line do not garble each other. Only the main thread writes."""

    def __init__(self, mode):
        self.mode = mode            # "tty", "plain" or "quiet"
        self.pending = None         # newest status text not yet shown
        self.shown = ""             # status line currently on the terminal
        self.last_draw = None

    def line(self, stream, text):
        self._clear()
        emit(stream, text + "\n")
        self._redraw()

    def error(self, message):
        self.line(sys.stderr, "cosph: " + message)

    def set_status(self, text):
        if self.mode != "quiet" and text:
            self.pending = text
            self.tick()

    def tick(self):
        """Show the pending status if enough time has passed since the last one."""
        if self.pending is None:
            return
        now = time.monotonic()
        every = TTY_REDRAW_S if self.mode == "tty" else PLAIN_PROGRESS_EVERY_S
        if self.last_draw is not None and now - self.last_draw < every:
            return
        self.last_draw = now
        text, self.pending = self.pending, None
        if self.mode == "tty":
            self.shown = text
            self._redraw()
        else:
            emit(sys.stderr, f"cosph: progress: {text}\n")

    def finish(self):
        self._clear()
        self.shown = ""

    def _width(self):
        try:
            columns = os.get_terminal_size(sys.stderr.fileno()).columns
        except OSError:
            columns = 0
        return max(20, columns - 1) if columns > 0 else 79   # 0: size not set (e.g. a bare pty)

    def _clear(self):
        if self.shown:
            emit(sys.stderr, "\r\x1b[K")

    def _redraw(self):
        # Truncated to the terminal width: a wrapped line cannot be redrawn with \r.
        if self.shown:
            emit(sys.stderr, "\r\x1b[K" + self.shown[:self._width()])
