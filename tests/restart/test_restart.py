"""Restart bit for bit (docs/restart.md): a run whose every process was
killed with SIGKILL halfway through writing a checkpoint (the test hook
COSPH_TEST_KILL_IN_CHECKPOINT=N, sphcore/src/checkpoint.cpp), then continued
with `coupler/cosph resume DIR` from the last checkpoint all of them finished,
must leave the same timeseries.csv, snapshot indexes and final snapshots as
the same run never stopped, and coupling.csv must continue (its timing
columns aside). The same for a coupled run stopped by Ctrl-C (SIGINT to the
launcher) and no periodic checkpoint: it resumes from the checkpoint all
three processes wrote at the step the coupler stopped the run. Also: a
resume that would change a field other than run.end_time, a checkpoint of
another format, and a set of parts taken at different coupling steps are
refused with messages that say so.

Run by ctest (test "restart"); by hand:
COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/restart -v"""
import filecmp
import glob
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import h5py
import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "tests", "case_runs"))
from case_runs import read_csv  # noqa: E402

LAUNCHER = os.path.join(REPO, "coupler", "cosph")
TIMEOUT = float(os.environ.get("COSPH_CASE_TIMEOUT", "1500"))
# coupling.csv columns that do not measure wall time.
DETERMINISTIC_COUPLING = ["t", "force_on_fluid_x", "force_on_fluid_y", "force_on_solid_x",
                          "force_on_solid_y", "fluid_interface_particles",
                          "solid_interface_particles", "pairs", "step", "dt"]


def launcher_env(kill_in_checkpoint=None):
    env = dict(os.environ)
    env.pop("COSPH_TEST_KILL_IN_CHECKPOINT", None)
    if kill_in_checkpoint is not None:
        env["COSPH_TEST_KILL_IN_CHECKPOINT"] = str(kill_in_checkpoint)
    return env


def cosph(*arguments, kill_in_checkpoint=None):
    return subprocess.run([LAUNCHER, *arguments, "--quiet"], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True,
                          env=launcher_env(kill_in_checkpoint), timeout=TIMEOUT)


def rows_in(path):
    """Rows of a CSV file with a header, 0 while it does not exist."""
    try:
        with open(path) as f:
            return max(0, sum(1 for _ in f) - 1)
    except OSError:
        return 0


def process_of(program, out):
    """The pid of the running `program` whose --out is `out`, or None."""
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                argv = f.read().decode(errors="replace").split("\0")
        except OSError:
            continue
        if os.path.basename(argv[0]) == program and out in argv:
            return int(pid)
    return None


def interrupt_when(arguments, csv, rows, stall=None):
    """Runs the launcher and sends it SIGINT (Ctrl-C) once `csv` has `rows`
    rows, after stalling the process `stall` (SIGSTOP), if given; the
    finished process, its output in stdout."""
    env = launcher_env()
    env["COSPH_INT_GRACE_S"] = "4"   # how long the launcher waits before it kills a stalled one
    launcher = subprocess.Popen([LAUNCHER, *arguments, "--quiet"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=env,
                                start_new_session=True)
    deadline = time.monotonic() + TIMEOUT
    while rows_in(csv) < rows and launcher.poll() is None and time.monotonic() < deadline:
        time.sleep(0.005)
    if stall is not None:
        os.kill(process_of(stall, arguments[arguments.index("--out") + 1]), signal.SIGSTOP)
    launcher.send_signal(signal.SIGINT)
    stdout, _ = launcher.communicate(timeout=TIMEOUT)
    return subprocess.CompletedProcess(launcher.args, launcher.returncode, stdout)


def run_args(case, out, settings):
    # ctest runs other process-heavy tests beside these: a peer starved of the
    # cores for 10 s is not what they are about.
    arguments = ["run", case, "--out", out, "--set", "coupling.timeout=60"]
    for setting in settings:
        arguments += ["--set", setting]
    return arguments


# The runs through, by (case, settings): a killed and an interrupted run of
# the same settings compare with one.
THROUGH_RUNS = {}
THROUGH_ROOT = None


def run_through(case, settings):
    """The run of CASE with SETTINGS that was never stopped: its folder and process."""
    global THROUGH_ROOT
    key = (case, tuple(settings))
    if key not in THROUGH_RUNS:
        if THROUGH_ROOT is None:
            THROUGH_ROOT = tempfile.mkdtemp(prefix="cosph_restart_through_")
        out = os.path.join(THROUGH_ROOT, str(len(THROUGH_RUNS)))
        THROUGH_RUNS[key] = (out, cosph(*run_args(case, out, settings)))
    return THROUGH_RUNS[key]


def tearDownModule():
    if THROUGH_ROOT is not None:
        shutil.rmtree(THROUGH_ROOT, ignore_errors=True)


class RestartCase:
    """Runs CASE with SETTINGS twice: through, and killed in checkpoint KILL_IN
    then resumed. Mixed into unittest.TestCase."""
    CASE = None
    SETTINGS = []
    KILL_IN = 3
    PHASES = ("fluid", "solid")

    @classmethod
    def setUpClass(cls):
        cls.root = tempfile.mkdtemp(prefix=f"cosph_restart_{cls.CASE}_")
        cls.resumed = os.path.join(cls.root, "resumed")
        cls.through, cls.through_run = run_through(cls.CASE, cls.SETTINGS)
        cls.killed_run = cls.stop_midway()
        cls.partials = sorted(os.path.basename(p) for p in
                              glob.glob(os.path.join(cls.resumed, "checkpoints", "*.partial")))
        cls.checkpoints_when_stopped = sorted(
            os.path.basename(p) for p in glob.glob(os.path.join(cls.resumed, "checkpoints", "*.h5")))
        cls.rows_when_killed = rows_in(os.path.join(cls.resumed, "timeseries.csv"))
        cls.resume_run = cosph("resume", cls.resumed)

    @classmethod
    def stop_midway(cls):
        return cosph(*run_args(cls.CASE, cls.resumed, cls.SETTINGS),
                     kill_in_checkpoint=cls.KILL_IN)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.root, ignore_errors=True)

    def test_runs_were_stopped_midway_and_resumed(self):
        self.assertEqual(self.through_run.returncode, 0, self.through_run.stdout)
        self.assertEqual(self.resume_run.returncode, 0, self.resume_run.stdout)
        self.assertIn("resuming", self.resume_run.stdout)
        # The run was stopped before its end: the resume had rows to add.
        through_rows = rows_in(os.path.join(self.through, "timeseries.csv"))
        self.assertLess(self.rows_when_killed, through_rows, self.killed_run.stdout)
        self.check_how_it_stopped()

    def check_how_it_stopped(self):
        self.assertNotEqual(self.killed_run.returncode, 0, self.killed_run.stdout)
        self.assertIn("SIGKILL", self.killed_run.stdout)
        # A process died in the middle of its write and left a .partial. Each
        # process kills itself there, but on a loaded machine the launcher may
        # stop a slower one on the first one's death before it reaches its own
        # write, so not every part need have one.
        parts = self.PHASES + (("coupler",) if len(self.PHASES) > 1 else ())
        left = {p.split("_")[0] for p in self.partials}
        self.assertTrue(left, "no checkpoint was left half written")
        self.assertLessEqual(left, set(parts))

    def test_timeseries_is_the_same_bytes(self):
        self.assertTrue(filecmp.cmp(os.path.join(self.through, "timeseries.csv"),
                                    os.path.join(self.resumed, "timeseries.csv"), shallow=False))

    def test_snapshot_indexes_list_each_snapshot_once_as_the_run_through(self):
        for phase in self.PHASES:
            self.assertTrue(filecmp.cmp(os.path.join(self.through, f"{phase}.xdmf"),
                                        os.path.join(self.resumed, f"{phase}.xdmf"),
                                        shallow=False), phase)

    def test_final_snapshots_are_the_same_bits(self):
        for phase in self.PHASES:
            last = sorted(glob.glob(os.path.join(self.through, f"{phase}_0*.h5")))[-1]
            with h5py.File(last) as a, \
                    h5py.File(os.path.join(self.resumed, os.path.basename(last))) as b:
                self.assertEqual(sorted(a.keys()), sorted(b.keys()))
                self.assertEqual(a.attrs["time"], b.attrs["time"])
                for name in a.keys():
                    self.assertTrue(np.array_equal(a[name][()], b[name][()]), f"{last}: {name}")

    def test_coupling_csv_continues(self):
        if len(self.PHASES) == 1:
            self.skipTest("a solver alone writes no coupling.csv")
        a = read_csv(os.path.join(self.through, "coupling.csv"))
        b = read_csv(os.path.join(self.resumed, "coupling.csv"))
        for column in DETERMINISTIC_COUPLING:
            np.testing.assert_array_equal(a[column], b[column], err_msg=column)


class DamBreakAlone(RestartCase, unittest.TestCase):
    CASE = "dam_break"
    SETTINGS = ["run.end_time=0.1", "run.snapshot_interval=0.025"]
    KILL_IN = 6
    PHASES = ("fluid",)

    def test_a_resume_may_change_only_the_end_time(self):
        result = cosph("resume", self.resumed, "--set", "fluid.spacing=0.004")
        self.assertEqual(result.returncode, 2, result.stdout)
        self.assertIn("fluid.spacing would change the run", result.stdout)

    def test_a_checkpoint_of_another_format_is_refused(self):
        copy = os.path.join(self.root, "other_format")
        shutil.copytree(self.resumed, copy)
        for path in glob.glob(os.path.join(copy, "checkpoints", "*.h5")):
            with h5py.File(path, "r+") as f:
                f["format"][0] = 999
        result = cosph("resume", copy)
        self.assertEqual(result.returncode, 2, result.stdout)
        self.assertIn("checkpoint format 999", result.stdout)


class ElasticPlateSynchronised(RestartCase, unittest.TestCase):
    CASE = "elastic_plate"
    SETTINGS = ["run.end_time=0.003", "run.output_interval=0.0005",
                "run.snapshot_interval=0.001", "coupling.max_substeps=1"]
    KILL_IN = 6

    def test_parts_of_different_steps_are_refused(self):
        copy = os.path.join(self.root, "mixed_parts")
        shutil.copytree(self.resumed, copy)
        solids = sorted(glob.glob(os.path.join(copy, "checkpoints", "solid_*.h5")))
        self.assertEqual(len(solids), 2)
        shutil.copy(solids[0], solids[1])  # the older solid under the newer name
        result = cosph("resume", copy)
        self.assertNotEqual(result.returncode, 0, result.stdout)
        self.assertIn("the checkpoint's parts do not match", result.stdout)


class ElasticPlateMultiRate(RestartCase, unittest.TestCase):
    CASE = "elastic_plate"
    SETTINGS = ["run.end_time=0.003", "run.output_interval=0.0005",
                "run.snapshot_interval=0.001", "coupling.max_substeps=32"]
    KILL_IN = 6


class InterruptedCase(RestartCase):
    """Stopped by Ctrl-C once timeseries.csv has ROWS rows, with no periodic
    checkpoint: the resume can only start from the one the Ctrl-C wrote."""
    ROWS = 2

    @classmethod
    def stop_midway(cls):
        settings = cls.SETTINGS + ["run.checkpoint_interval=-1"]
        return interrupt_when(run_args(cls.CASE, cls.resumed, settings),
                              os.path.join(cls.resumed, "timeseries.csv"), cls.ROWS)

    def check_how_it_stopped(self):
        log = self.killed_run.stdout
        self.assertEqual(self.killed_run.returncode, 130, log)
        self.assertIn("cosph-coupler: interrupted (Ctrl-C or SIGTERM): stopped the run at coupling "
                      "step", log)
        # One checkpoint of each part, all at the step the coupler stopped the run.
        steps = {name.split("_")[1] for name in self.checkpoints_when_stopped}
        self.assertEqual(len(steps), 1, self.checkpoints_when_stopped)
        self.assertEqual(sorted(name.split("_")[0] for name in self.checkpoints_when_stopped),
                         ["coupler", "fluid", "solid"])
        self.assertIn(f"coupling step {int(steps.pop()[:-3])} ", log)


class ElasticPlateSynchronisedInterrupted(InterruptedCase, unittest.TestCase):
    CASE = "elastic_plate"
    SETTINGS = ElasticPlateSynchronised.SETTINGS


class ElasticPlateMultiRateInterrupted(InterruptedCase, unittest.TestCase):
    CASE = "elastic_plate"
    SETTINGS = ElasticPlateMultiRate.SETTINGS


class ElasticPlateInterruptedWithAStalledSolid(InterruptedCase, unittest.TestCase):
    """Ctrl-C while the solid is stalled (SIGSTOP): the solid takes no
    checkpoint at the step the run stops (the coupler may have answered that
    step, if the solid's state was in, and the fluid and the coupler then took
    theirs), and the run still stops, the fluid with its final snapshot; the
    resume continues from the last periodic checkpoint all three finished."""
    CASE = "elastic_plate"
    SETTINGS = ElasticPlateSynchronised.SETTINGS
    ROWS = 4  # t = 0.0015 s: five periodic checkpoints were taken

    @classmethod
    def stop_midway(cls):
        return interrupt_when(run_args(cls.CASE, cls.resumed, cls.SETTINGS),
                              os.path.join(cls.resumed, "timeseries.csv"), cls.ROWS,
                              stall="cosph-solid-jaumann")

    def check_how_it_stopped(self):
        log = self.killed_run.stdout
        self.assertEqual(self.killed_run.returncode, 130, log)
        fluid = [line for line in log.splitlines() if "fluid: interrupted" in line]
        self.assertEqual(len(fluid), 1, log)
        self.assertIn("final snapshot", fluid[0])
        self.assertIn("cosph-solid-jaumann did not stop, killing it", log)
        sequences = {}
        for name in self.checkpoints_when_stopped:
            sequences.setdefault(name.split("_")[0], set()).add(int(name.split("_")[1][:-3]))
        self.assertEqual(sorted(sequences), ["coupler", "fluid", "solid"])
        whole = max(set.intersection(*sequences.values()))
        self.assertEqual(max(sequences["solid"]), whole)
        self.assertIn(f"resuming {self.resumed} from {whole:09d}", self.resume_run.stdout)


class PlateFractureAfterFailure(RestartCase, unittest.TestCase):
    """Resumed from a checkpoint after the first particles failed (the short
    mode of tests/case_runs/test_plate_fracture_short.py, run to 0.035 s)."""
    CASE = "plate_fracture"
    SETTINGS = ["run.end_time=0.035", "run.snapshot_interval=0.01",
                "coupling.max_substeps=32", "solid.fracture.weakened[0].yield_stress=4000"]
    KILL_IN = 9  # at 0.0315 s: the resume starts from 0.028 s, the band failed at 0.025 s

    def test_resumed_after_the_first_failures(self):
        kept = sorted(glob.glob(os.path.join(self.resumed, "checkpoints", "solid_*.h5")))
        log = [line for line in self.resume_run.stdout.splitlines() if "resuming" in line]
        self.assertTrue(log, self.resume_run.stdout)
        resumed_from = [p for p in kept if os.path.basename(p) in log[0]]
        self.assertEqual(len(resumed_from), 1, log)
        with h5py.File(resumed_from[0]) as f:
            self.assertGreater(int(np.sum(f["failed"][()])), 0)


if __name__ == "__main__":
    unittest.main()
