"""Behaviour shared by the fake cosph-fluid, cosph-solid-jaumann and cosph-coupler.

Steered by environment variables (NAME lists are comma-separated exe names):
  FAKE_DIR          folder for <exe>.pid, <exe>.args (JSON argv), <exe>.cores
                    (JSON list of the cores it may run on), <exe>.sigint,
                    <exe>.grandchild.pid
  FAKE_STEPS        progress lines before a normal exit (default 10)
  FAKE_INTERVAL     seconds between progress lines (default 0.05)
  FAKE_HANG         NAMEs that never finish on their own
  FAKE_BUSY         NAMEs that spend FAKE_INTERVAL of CPU time computing, not sleeping
  FAKE_FAIL         NAMEs that fail after FAKE_FAIL_AFTER seconds (default 0.3)
                    with exit code FAKE_FAIL_CODE (default 3), or, if
                    FAKE_FAIL_SIGNAL is set, by killing themselves with it
  FAKE_IGNORE_TERM  NAMEs that ignore SIGTERM
  FAKE_IGNORE_INT   NAMEs that ignore SIGINT
  FAKE_GRANDCHILD   NAMEs that start a `sleep 60` in their process group
On SIGINT (like the real solvers) a fake writes <exe>.sigint, prints a
"writing final snapshot" line and exits 130 at its next step.
"""
import json
import os
import signal
import subprocess
import sys
import time


def _names(var):
    return [n for n in os.environ.get(var, "").split(",") if n]


def _write(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)   # atomic: the tests never read half a pid


def main(name):
    tag = name[len("cosph-"):] if name.startswith("cosph-") else name
    state = os.environ.get("FAKE_DIR")
    args = sys.argv[1:]
    out = args[args.index("--out") + 1] if "--out" in args else "."

    interrupted = []

    def on_sigint(signum, frame):
        # Like the real solvers: only note it; the loop writes the snapshot.
        # (Printing here could re-enter a print that the signal interrupted.)
        interrupted.append(signum)

    signal.signal(signal.SIGINT,
                  signal.SIG_IGN if name in _names("FAKE_IGNORE_INT") else on_sigint)
    if name in _names("FAKE_IGNORE_TERM"):
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
    if state:
        if name in _names("FAKE_GRANDCHILD"):
            sleeper = subprocess.Popen(["sleep", "60"], stdin=subprocess.DEVNULL,
                                       stdout=subprocess.DEVNULL)
            _write(os.path.join(state, name + ".grandchild.pid"), str(sleeper.pid))
        _write(os.path.join(state, name + ".args"), json.dumps(args))
        _write(os.path.join(state, name + ".cores"), json.dumps(sorted(os.sched_getaffinity(0))))
        _write(os.path.join(state, name + ".pid"), str(os.getpid()))

    print(f"starting, case {args[args.index('--case') + 1]}", flush=True)
    print("warning: this is a fake solver", file=sys.stderr, flush=True)

    steps = int(os.environ.get("FAKE_STEPS", "10"))
    interval = float(os.environ.get("FAKE_INTERVAL", "0.05"))
    hang = name in _names("FAKE_HANG")
    busy = name in _names("FAKE_BUSY")
    fail = name in _names("FAKE_FAIL")
    fail_after = float(os.environ.get("FAKE_FAIL_AFTER", "0.3"))
    start = time.monotonic()
    step = 0
    while hang or step < steps:
        if busy:   # CPU time, not wall time: a loaded machine must not shorten it
            until = time.process_time() + interval
            while time.process_time() < until:
                pass
        else:
            time.sleep(interval)
        if interrupted:
            if state:
                _write(os.path.join(state, name + ".sigint"), "1")
            print("writing final snapshot", flush=True)
            sys.exit(130)
        step += 1
        t = step / 1000.0 if hang else step / steps
        print(f"progress t={t:g} end=1 step={step * 100} dt=1e-05", flush=True)
        if fail and time.monotonic() - start >= fail_after:
            print(f"error: {tag} diverged at step {step * 100}", file=sys.stderr, flush=True)
            if os.environ.get("FAKE_FAIL_SIGNAL"):
                os.kill(os.getpid(), int(os.environ["FAKE_FAIL_SIGNAL"]))
                time.sleep(5)
            sys.exit(int(os.environ.get("FAKE_FAIL_CODE", "3")))

    with open(os.path.join(out, "timeseries.csv"), "a") as f:
        f.write(f"{tag},1.0\n")
    with open(os.path.join(out, f"{tag}.xdmf"), "w") as f:
        f.write("<Xdmf/>\n")
    print("done", flush=True)
