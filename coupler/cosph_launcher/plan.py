"""Planning a run: which processes a case needs (cosph-case plan), their
command lines, and where they may run."""

import os
import re
import subprocess
import sys

from .console import emit
from .errors import EXIT_FAILURE, Exit, UsageError
from .locate import exe_path, set_args

EXE_NAME_RE = re.compile(r"^cosph-[A-Za-z0-9_-]+$")


SEPARATE_CORES = "separate-cores"


def run_plan(case_exe, case, sets):
    """Ask cosph-case which executables the case needs, in start order: one
    per line, each a cosph-* name or the absolute path of a program the case
    names (solid.executable; a path may hold spaces), and whether the solvers
    should get cores of their own (a last line "separate-cores": a multi-rate
    run). Returns the command, the names, and that flag.

    On bad input its stderr (which names file, field and reason) is shown
    verbatim and we exit with its code: the message is for the user, not us."""
    cmd = [str(case_exe), "plan", str(case)] + set_args(sets)
    result = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True)
    sys.stderr.flush()
    sys.stderr.buffer.write(result.stderr)   # warnings on success, the error otherwise
    sys.stderr.buffer.flush()
    if result.returncode < 0:
        emit(sys.stderr, f"cosph: {case_exe.name} plan was killed by signal "
                         f"{-result.returncode}\n")
        raise Exit(EXIT_FAILURE)
    if result.returncode != 0:
        raise Exit(result.returncode)
    names = [line.strip() for line in result.stdout.decode("utf-8", "replace").splitlines()
             if line.strip()]
    separate_cores = bool(names) and names[-1] == SEPARATE_CORES
    if separate_cores:
        names.pop()
    bad = [n for n in names if not (EXE_NAME_RE.match(n) or os.path.isabs(n))]
    if not names or bad or len(set(names)) != len(names):
        emit(sys.stderr, f"cosph: unexpected output from {case_exe.name} plan: "
                         f"{result.stdout.decode('utf-8', 'replace').strip()!r}\n")
        raise Exit(EXIT_FAILURE)
    return cmd, names, separate_cores


def core_placement(names, separate_cores, allowed):
    """{name: cores} for the solvers of a multi-rate run, else {}.

    In a multi-rate run the solid works through its sub-steps while the water
    waits, every window. Left to the scheduler, the solid's wait per window
    had a long tail, likely a process woken on the core it was working on;
    each solver on cores of its own, the multi-rate elastic plate ran faster.
    Beside an outside CPU-bound job pinning was never slower (docs/coupling.md
    gives the runs): the scheduler can stack both solvers on one core while
    the job holds the other; pinned, the job shares a core with one solver
    only. A synchronised run, where each side waits
    for the other at every step, ran slower so, and is left to the scheduler
    (README, "Speed", and the commits give the numbers).
    The water gets the first half of the allowed cores (the larger, if odd),
    the solid the rest; the coupler, mostly waiting, may run anywhere."""
    cores = sorted(allowed)
    if not separate_cores or len(names) != 3 or len(cores) < 2:
        return {}
    half = (len(cores) + 1) // 2
    return {names[1]: cores[:half], names[2]: cores[half:]}


def check_endpoint(endpoint):
    # Unix socket paths are limited to 107 bytes; ZeroMQ's own error for a
    # longer one ("File name too long") does not say what to do about it.
    if endpoint.startswith("ipc://") and len(endpoint[len("ipc://"):].encode()) > 107:
        raise UsageError(f"socket path of endpoint {endpoint} is longer than 107 "
                         f"bytes; use a shorter --out folder or give e.g. "
                         f"--endpoint ipc:///tmp/cosph-$USER.sock")


def child_commands(names, folder, case, out, sets, endpoint):
    common = ["--case", str(case), "--out", str(out)] + set_args(sets)
    if len(names) > 1:
        common += ["--endpoint", endpoint]
    return [[str(exe_path(folder, name))] + common for name in names]
