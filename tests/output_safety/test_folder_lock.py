"""One run per output folder, also for processes started by hand (docs/restart.md,
"One run per folder"; two hosts, docs/coupling.md): a solver started by hand
into a folder a launcher's run holds is refused, naming that run; so is a
process of another hand-started run, and so is a launcher arriving second;
the coupler and the solvers of one hand-started run share their folder.

Before, a solver started by hand took no lock and wrote into the folder
beside the running run.

Run by ctest (test "output_safety"); by hand:
COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/output_safety -v"""
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAUNCHER = os.path.join(REPO, "coupler", "cosph")
BIN = os.environ.get("COSPH_BIN", os.path.join(REPO, "build", "bin"))
CASE = os.path.join(REPO, "cases", "elastic_plate.pbtxt")
# Short: the hand-started run below goes to its end; a solver that waits for a
# coupler that never comes gives up soon.
SETTINGS = ["--set", "run.end_time=0.0002", "--set", "coupling.timeout=5"]


def by_hand(program, out, endpoint, **popen):
    return subprocess.Popen([os.path.join(BIN, program), "--case", CASE, "--out", out,
                             "--endpoint", endpoint, *SETTINGS],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **popen)


def wait_for(condition, seconds=60):
    deadline = time.monotonic() + seconds
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.02)
    return condition()


def lock_names(out, pid):
    """Whether the folder's lock file names process `pid` as its holder."""
    try:
        with open(os.path.join(out, ".cosph.lock")) as f:
            return f.read().startswith(f"pid {pid},")
    except OSError:
        return False


class HandStartedProcessesTakeTheFolderLock(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="cosph_lock_")   # mode 0700: fit for ipc sockets
        self.out = os.path.join(self.root, "out")
        self.processes = []

    def tearDown(self):
        # Ctrl-C first: a launcher killed outright leaves its children to
        # write their final snapshots into the folder after it is removed.
        for process in self.processes:
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
        for process in self.processes:
            try:
                process.communicate(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                process.communicate()
        shutil.rmtree(self.root, ignore_errors=True)

    def start(self, program, endpoint):
        process = by_hand(program, self.out, endpoint)
        self.processes.append(process)
        return process

    def assert_refused(self, process, holder_pid):
        _, err = process.communicate(timeout=60)
        self.assertEqual(process.returncode, 2, err)
        self.assertIn(f"{self.out} is in use by another run (pid {holder_pid}, started ", err)

    def test_a_solver_by_hand_is_refused_by_a_launchers_run(self):
        launcher = subprocess.Popen(
            [LAUNCHER, "run", "elastic_plate", "--out", self.out, "--quiet",
             "--set", "run.end_time=1", "--set", "run.checkpoint_interval=-1"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True)
        self.processes.append(launcher)
        self.assertTrue(wait_for(lambda: os.path.exists(os.path.join(self.out, "fluid.xdmf"))))
        solid = self.start("cosph-solid-jaumann", f"ipc://{self.root}/other.sock")
        self.assert_refused(solid, launcher.pid)
        launcher.send_signal(signal.SIGINT)
        log, _ = launcher.communicate(timeout=60)
        self.assertEqual(launcher.returncode, 130, log)   # its run went on undisturbed

    def test_runs_started_by_hand_share_no_folder(self):
        endpoint = f"ipc://{self.root}/run.sock"
        fluid = self.start("cosph-fluid", endpoint)       # waits for its coupler
        self.assertTrue(wait_for(lambda: lock_names(self.out, fluid.pid)))
        # A solid of another run (another coupler's endpoint) is refused ...
        stranger = self.start("cosph-solid-jaumann", f"ipc://{self.root}/other.sock")
        self.assert_refused(stranger, fluid.pid)
        # ... and so is a launcher's run.
        launcher = subprocess.run(
            [LAUNCHER, "run", "elastic_plate", "--out", self.out, "--overwrite", "--quiet"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertEqual(launcher.returncode, 2, launcher.stdout)
        self.assertIn(f"is in use by another run (pid {fluid.pid}, started ", launcher.stdout)
        # The coupler and the solid of the fluid's own run share the folder
        # with it, as on host A of docs/coupling.md, and the run goes to its end.
        coupler = self.start("cosph-coupler", endpoint)
        solid = self.start("cosph-solid-jaumann", endpoint)
        for process in (coupler, fluid, solid):
            _, err = process.communicate(timeout=120)
            self.assertEqual(process.returncode, 0, err)
        with open(os.path.join(self.out, "timeseries.csv")) as f:
            self.assertGreater(len(f.readlines()), 1)


if __name__ == "__main__":
    unittest.main()
