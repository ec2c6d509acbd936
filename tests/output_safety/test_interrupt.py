"""Ctrl-C on a coupled run: every solver writes its final snapshot, whatever
it was waiting for when the signal came, and the launcher exits with 130.
All three processes take a checkpoint at the step the coupler stopped the
run, whether the signal reached the launcher or one solver alone (the runs
here take no periodic checkpoints: a checkpoint is the interruption's).

Before, the solver that waited for the coupler got the coupler's "interrupted"
error and exited without writing (3 of 4 tries in the fault-injection campaign
of issue 37; 2 of 6 here, so the Ctrl-C test tries 6 times). A SIGTERM to one
solver alone, as a batch system may send, shows it every time: the other
solver, waiting for its states, hears of it from the coupler. The case's
snapshots are due at t = 0 and at the end only, so a second one in an index
is the final snapshot of the interruption.

Run by ctest (test "output_safety"); by hand:
COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/output_safety -v"""
import glob
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest
import xml.etree.ElementTree as ElementTree

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAUNCHER = os.path.join(REPO, "coupler", "cosph")
TRIES = 6


def process_is(pid, program, out):
    """Whether process `pid` runs `program` with --out `out`."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            argv = f.read().decode(errors="replace").split("\0")
    except OSError:
        return False
    return bool(argv) and os.path.basename(argv[0]) == program and out in argv


def snapshot_times(index):
    """The times an XDMF index lists, in order."""
    root = ElementTree.parse(index).getroot()
    return [float(t.get("Value")) for t in root.iter("Time")]


class CtrlCWritesEveryFinalSnapshot(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="cosph_interrupt_")

    def tearDown(self):
        shutil.rmtree(self.root, ignore_errors=True)

    def start_run(self, out, substeps):
        """The launcher, once both solvers have written their first snapshot
        and stepped on for a while; and the two indexes."""
        launcher = subprocess.Popen(
            [LAUNCHER, "run", "elastic_plate", "--out", out, "--quiet",
             "--set", "run.snapshot_interval=1", "--set", "run.checkpoint_interval=-1",
             "--set", f"coupling.max_substeps={substeps}", "--set", "coupling.timeout=60"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True)
        deadline = time.monotonic() + 120
        indexes = [os.path.join(out, f"{phase}.xdmf") for phase in ("fluid", "solid")]
        while not all(os.path.exists(i) for i in indexes) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(1.0)
        return launcher, indexes

    def assert_final_snapshots(self, indexes, log):
        for index in indexes:
            times = snapshot_times(index)
            self.assertEqual(len(times), 2, f"{index}: {times}\n{log}")
            self.assertEqual(times[0], 0.0)
            self.assertGreater(times[1], 0.0, f"{index}\n{log}")
            self.assertTrue(os.path.exists(index[:-len(".xdmf")] + "_000001.h5"))

    def assert_one_checkpoint_set(self, out, log):
        names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(out, "checkpoints", "*")))
        steps = {name.split("_")[1] for name in names}
        self.assertEqual(len(steps), 1, f"{names}\n{log}")
        self.assertEqual([name.split("_")[0] for name in names], ["coupler", "fluid", "solid"],
                         log)

    def test_sigterm_to_one_solver_leaves_both_final_snapshots(self):
        out = os.path.join(self.root, "term")
        launcher, indexes = self.start_run(out, 1)
        fluid = [pid for pid in os.listdir("/proc") if pid.isdigit() and
                 process_is(int(pid), "cosph-fluid", out)]
        self.assertEqual(len(fluid), 1)
        os.kill(int(fluid[0]), signal.SIGTERM)
        log, _ = launcher.communicate(timeout=120)
        self.assertNotEqual(launcher.returncode, 0, log)   # 130, the first exit's
        self.assert_final_snapshots(indexes, log)
        self.assert_one_checkpoint_set(out, log)

    def interrupt_run(self, out, substeps):
        launcher, indexes = self.start_run(out, substeps)
        launcher.send_signal(signal.SIGINT)
        log, _ = launcher.communicate(timeout=120)
        return launcher.returncode, log, indexes

    def test_both_solvers_write_a_final_snapshot(self):
        for attempt in range(TRIES):
            substeps = 1 if attempt % 2 == 0 else 32   # synchronised and multi-rate
            with self.subTest(attempt=attempt, max_substeps=substeps):
                out = os.path.join(self.root, f"try{attempt}")
                code, log, indexes = self.interrupt_run(out, substeps)
                self.assertEqual(code, 130, log)
                self.assert_final_snapshots(indexes, log)
                self.assert_one_checkpoint_set(out, log)


if __name__ == "__main__":
    unittest.main()
