"""Starting the processes, passing their output through, and stopping them
all when one fails or the user presses Ctrl-C."""

import ctypes
import os
import queue
import signal
import subprocess
import sys
import threading
import time

from .console import Progress, parse_progress, status_text
from .errors import EXIT_FAILURE, EXIT_INTERRUPTED, EXIT_OK, Exit, Interrupted
from .output_dir import LOCK_FD_VARIABLE
from .timing import INT_GRACE_S, READER_JOIN_S, STRAGGLER_S, TERM_GRACE_S

def _load_prctl():
    try:
        return ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None   # not Linux: a child then stops on its broken stdout pipe


_PRCTL = _load_prctl()   # looked up here, not in the forked child
PR_SET_PDEATHSIG = 1


def _die_with_parent(parent_pid):
    """Runs in the child before exec: if the launcher is killed hard (SIGKILL,
    OOM killer) the kernel sends SIGTERM to the child, so nothing is orphaned."""
    if _PRCTL is None:
        return
    _PRCTL(PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0)
    if os.getppid() != parent_pid:   # the launcher died before prctl took effect
        os.kill(os.getpid(), signal.SIGTERM)


class Child:
    def __init__(self, name, cmd):
        name = os.path.basename(name)                     # a solid.executable path
        self.name = name                                  # cosph-fluid
        self.tag = name[len("cosph-"):] if name.startswith("cosph-") else name
        self.cmd = cmd
        self.proc = None
        self.shares_cores = False  # set when the run has more than one process
        self.cores = None          # the cores it may run on, if the launcher chose them
        self.lock_fd = None        # the output folder's lock, handed to the child
        self.readers = []
        self.done = False          # exited, reaped and its output taken in
        self.cpu_s = None          # CPU time (user + system) of all its threads, once reaped
        self.last_stderr = ""
        self.progress = Progress()

    def start(self):
        parent = os.getpid()
        # A session of its own, so that a terminal Ctrl-C reaches only the
        # launcher (which then stops the run in order) and so that we can
        # signal the process together with anything it spawned.
        # Several processes share the cores: OpenMP threads that spin while
        # waiting would steal them from each other, so they sleep instead
        # (unless the user chose otherwise).
        env = dict(os.environ)
        if self.shares_cores:
            env.setdefault("OMP_WAIT_POLICY", "passive")
        # The folder's lock, held open in the child too: it is its run's, and
        # stays locked while any process of the run lives (output_dir.py).
        passed = ()
        if self.lock_fd is not None:
            env[LOCK_FD_VARIABLE] = str(self.lock_fd)
            passed = (self.lock_fd,)
        cores = self.cores

        def before_exec():
            _die_with_parent(parent)
            if cores:
                # Before exec: every thread the solver starts inherits it. A
                # placement refused (a cpuset that changed meanwhile) costs
                # speed only, not the run.
                try:
                    os.sched_setaffinity(0, cores)
                except OSError:
                    pass

        self.proc = subprocess.Popen(
            self.cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
            stderr=subprocess.PIPE, start_new_session=True, env=env,
            pass_fds=passed, preexec_fn=before_exec)

    def reap(self, block=False):
        """Whether the child has exited. Reaps it with wait4 rather than
        Popen's waitpid, to keep the CPU time it used: what a coupled run
        costs the machine, beyond its wall time."""
        if self.proc.returncode is not None:
            return True
        try:
            pid, status, usage = os.wait4(self.proc.pid, 0 if block else os.WNOHANG)
        except ChildProcessError:   # reaped elsewhere: Popen knows how it ended
            return self.proc.poll() is not None
        if pid == 0:
            return False
        self.proc.returncode = os.waitstatus_to_exitcode(status)
        self.cpu_s = usage.ru_utime + usage.ru_stime
        return True

    def start_readers(self, events):
        for kind, stream in (("out", self.proc.stdout), ("err", self.proc.stderr)):
            thread = threading.Thread(target=_read_lines,
                                      args=(self, kind, stream, events),
                                      name=f"{self.tag}-{kind}", daemon=True)
            thread.start()
            self.readers.append(thread)

    def join_readers(self, timeout):
        # Bounded: a grandchild that inherited the pipe could keep it open.
        deadline = time.monotonic() + timeout
        for thread in self.readers:
            thread.join(max(0.0, deadline - time.monotonic()))

    def signal_group(self, sig):
        """Signal the child's whole process group.

        Also used after the child itself was reaped, to catch leftovers it
        spawned: the group id stays reserved while any member lives, and Linux
        hands out pids sequentially, so it cannot name a stranger's group here."""
        try:
            os.killpg(self.proc.pid, sig)
        except (ProcessLookupError, PermissionError):
            pass

    def exit_code(self):
        rc = self.proc.returncode
        return EXIT_FAILURE if rc < 0 else rc

    def describe_exit(self):
        rc = self.proc.returncode
        if rc < 0:
            try:
                signame = f" ({signal.Signals(-rc).name})"
            except ValueError:
                signame = ""
            return f"killed by signal {-rc}{signame}"
        return f"exit code {rc}"


def _read_lines(child, kind, stream, events):
    """Reader thread: hand each line to the main thread, then an EOF marker."""
    try:
        for raw in iter(stream.readline, b""):
            events.put((child, kind, raw.decode("utf-8", "replace").rstrip("\r\n")))
    except (OSError, ValueError):
        pass
    finally:
        events.put((child, kind, None))
        stream.close()


class SignalState:
    """SIGINT/SIGTERM/SIGHUP all mean 'stop the run'.

    Before the solvers start, the handler raises (nothing to clean up but a
    short-lived plan process, which subprocess.run kills on the way out).
    Afterwards it only counts, and the supervision loop reacts within 0.1 s;
    a second signal skips the grace period."""

    def __init__(self):
        self.count = 0
        self.raise_now = True

    def install(self):
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, self._handler)

    def _handler(self, signum, frame):
        self.count += 1
        if self.raise_now:
            raise Interrupted()


class Run:
    """Starts the processes and supervises them until all are gone."""

    def __init__(self, children, console, signals):
        self.children = children
        self.console = console
        self.signals = signals
        self.events = queue.Queue()

    def running(self):
        return [c for c in self.children if not c.done]

    # -- starting

    def start(self):
        self.warn_of_spinning_threads()
        for child in self.children:
            child.shares_cores = len(self.children) > 1
            try:
                child.start()
            except OSError as err:
                self.console.error(f"cannot start {child.cmd[0]}: {err}")
                self.children = [c for c in self.children if c.proc is not None]
                self.kill_remaining()
                raise Exit(EXIT_FAILURE) from err
        # Threads only after all forks: preexec_fn is not safe with threads around.
        for child in self.children:
            child.start_readers(self.events)

    def warn_of_spinning_threads(self):
        """The launcher lets OpenMP threads sleep while they wait, unless the
        user chose otherwise: say what spinning costs when processes share cores."""
        if len(self.children) < 2:
            return
        if os.environ.get("OMP_WAIT_POLICY", "").strip().lower() != "active":
            return
        self.console.line(sys.stderr,
                          f"cosph: warning: OMP_WAIT_POLICY=active: {len(self.children)} processes "
                          f"share {os.cpu_count()} cores, and a thread that spins while it waits "
                          "holds a core another process needs (on two cores, the coupled elastic "
                          "plate with two threads per solver ran 30 times slower); unset it to "
                          "let waiting threads sleep")

    # -- output

    def pump(self, timeout):
        """Handle child output for up to `timeout` seconds (less if lines arrive)."""
        try:
            event = self.events.get(timeout=timeout)
        except queue.Empty:
            event = None
        handled = 0
        while event is not None:
            self._handle(*event)
            handled += 1
            if handled >= 1000:   # bounded, so a chatty child cannot starve exit polling
                break
            try:
                event = self.events.get_nowait()
            except queue.Empty:
                event = None
        self.console.tick()

    def _handle(self, child, kind, text):
        if text is None:   # end of stream; the reader thread is joined elsewhere
            return
        if kind == "out":
            progress = parse_progress(text)
            if progress is not None:
                child.progress.add(time.monotonic(), *progress)
                self.console.set_status(status_text(self.children))
                return
            self.console.line(sys.stdout, f"[{child.tag}] {text}")
        else:
            if text.strip():
                child.last_stderr = text.strip()
            self.console.line(sys.stderr, f"[{child.tag}] {text}")

    def collect_exits(self):
        """Reap the children that have exited; returns them."""
        exited = [c for c in self.running() if c.reap()]
        for child in exited:
            child.join_readers(READER_JOIN_S)   # its last error line decides the message
        if exited:
            self.pump(0)
        for child in exited:
            child.done = True
        return exited

    # -- supervision

    def supervise(self):
        """Returns the launcher's exit code."""
        first_done = None   # (child, time) of the first clean exit
        while True:
            if self.signals.count:
                return self.interrupt()
            self.pump(0.1)
            exited = self.collect_exits()
            failed = [c for c in exited if c.proc.returncode != 0]
            if failed:
                for child in failed:
                    what = ("was interrupted" if child.proc.returncode == EXIT_INTERRUPTED
                            else f"failed ({child.describe_exit()})")
                    self.console.error(f"{child.name} {what}: "
                                       f"{child.last_stderr or '(no error output)'}")
                # SIGINT or SIGTERM that reached a solver alone (a batch
                # system's) stops a coupled run at the coupler's next step, every
                # process writing its checkpoint: the others get as long for
                # that as on a Ctrl-C to the launcher.
                interrupted = all(c.proc.returncode == EXIT_INTERRUPTED for c in failed)
                self.stop_all(signal.SIGTERM, INT_GRACE_S if interrupted else TERM_GRACE_S)
                if not interrupted:
                    # The processes stopped on its account print their own
                    # lines after the cause's: the last line names the cause.
                    cause = next(c for c in failed if c.proc.returncode != EXIT_INTERRUPTED)
                    self.console.error(f"the run stopped because {cause.name} failed "
                                       f"({cause.describe_exit()}): see its error above")
                return failed[0].exit_code()
            if exited and first_done is None:
                first_done = (exited[0], time.monotonic())
            if not self.running():
                return EXIT_OK
            if first_done and time.monotonic() - first_done[1] > STRAGGLER_S:
                return self.stop_stragglers(first_done[0])

    def stop_stragglers(self, finished):
        # In a coupled run all processes end together; one still running long
        # after another finished is waiting for a partner that will never come.
        for child in self.running():
            self.console.error(f"{child.name} failed (still running {STRAGGLER_S:g} s "
                               f"after {finished.name} finished); stopping it")
        self.stop_all(signal.SIGTERM, TERM_GRACE_S)
        return EXIT_FAILURE

    def interrupt(self):
        names = ", ".join(c.name for c in self.running())
        if names:
            # The children are in their own sessions, so the terminal's Ctrl-C
            # did not reach them: forward it. They write a final snapshot.
            self.console.error(f"interrupted: stopping {names} (up to {INT_GRACE_S:g} s "
                               f"for final snapshots; interrupt again to kill now)")
            self.stop_all(signal.SIGINT, INT_GRACE_S)
        self.console.error("interrupted")
        return EXIT_INTERRUPTED

    def stop_all(self, sig, grace):
        """Send `sig` to every running child, wait up to `grace` seconds while
        still showing their output, then SIGKILL what is left and reap all.
        Another signal to the launcher cuts the wait short."""
        signals_before = self.signals.count
        for child in self.running():
            child.signal_group(sig)
        deadline = time.monotonic() + grace
        while self.running() and time.monotonic() < deadline \
                and self.signals.count == signals_before:
            self.pump(0.05)
            self.collect_exits()
        for child in self.running():
            self.console.error(f"{child.name} did not stop, killing it")
        self.kill_remaining()

    def kill_remaining(self):
        """SIGKILL whatever is still running and reap everything, including
        processes the children spawned into their process groups."""
        for child in self.running():
            child.signal_group(signal.SIGKILL)
        for child in self.children:
            child.reap(block=True)
            child.signal_group(signal.SIGKILL)   # leftovers of an exited child
        self.collect_exits()
        for child in self.children:
            child.join_readers(READER_JOIN_S)
        self.pump(0)
