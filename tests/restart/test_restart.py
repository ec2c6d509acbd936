"""Restart bit for bit (docs/restart.md): a run whose every process was
killed with SIGKILL halfway through writing a checkpoint (the test hook
COSPH_TEST_KILL_IN_CHECKPOINT=N, sphcore/src/checkpoint.cpp), then continued
with `coupler/cosph resume DIR` from the last checkpoint all of them finished,
must leave the same timeseries.csv, snapshot indexes and final snapshots as
the same run never stopped, and coupling.csv must continue (its timing
columns aside). Also: a resume that would change a field other than
run.end_time, a checkpoint of another format, and a set of parts taken at
different coupling steps are refused with messages that say so.

Run by ctest (test "restart"); by hand:
COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/restart -v"""
import filecmp
import glob
import os
import shutil
import subprocess
import sys
import tempfile
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


def cosph(*arguments, kill_in_checkpoint=None):
    env = dict(os.environ)
    env.pop("COSPH_TEST_KILL_IN_CHECKPOINT", None)
    if kill_in_checkpoint is not None:
        env["COSPH_TEST_KILL_IN_CHECKPOINT"] = str(kill_in_checkpoint)
    return subprocess.run([LAUNCHER, *arguments, "--quiet"], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, env=env, timeout=TIMEOUT)


def run_args(case, out, settings):
    # ctest runs other process-heavy tests beside these: a peer starved of the
    # cores for 10 s is not what they are about.
    arguments = ["run", case, "--out", out, "--set", "coupling.timeout=60"]
    for setting in settings:
        arguments += ["--set", setting]
    return arguments


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
        cls.through = os.path.join(cls.root, "through")
        cls.resumed = os.path.join(cls.root, "resumed")
        cls.through_run = cosph(*run_args(cls.CASE, cls.through, cls.SETTINGS))
        cls.killed_run = cosph(*run_args(cls.CASE, cls.resumed, cls.SETTINGS),
                               kill_in_checkpoint=cls.KILL_IN)
        cls.partials = sorted(os.path.basename(p) for p in
                              glob.glob(os.path.join(cls.resumed, "checkpoints", "*.partial")))
        cls.rows_when_killed = len(read_csv(os.path.join(cls.resumed, "timeseries.csv"))["t"])
        cls.resume_run = cosph("resume", cls.resumed)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.root, ignore_errors=True)

    def test_runs_were_killed_mid_write_and_resumed(self):
        self.assertEqual(self.through_run.returncode, 0, self.through_run.stdout)
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
        self.assertEqual(self.resume_run.returncode, 0, self.resume_run.stdout)
        self.assertIn("resuming", self.resume_run.stdout)
        # The run was stopped before its end: the resume had rows to add.
        through_rows = len(read_csv(os.path.join(self.through, "timeseries.csv"))["t"])
        self.assertLess(self.rows_when_killed, through_rows)

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


class PlateFractureAfterFailure(RestartCase, unittest.TestCase):
    """Resumed from a checkpoint after the first particles failed (the short
    mode of tests/case_runs/test_plate_fracture_short.py, cut at 0.03 s)."""
    CASE = "plate_fracture"
    SETTINGS = ["run.end_time=0.03", "run.snapshot_interval=0.01",
                "coupling.max_substeps=32", "solid.fracture.weakened[0].yield_stress=4000"]
    KILL_IN = 9  # at 0.027 s: the resume starts from 0.024 s, the band failed at 0.023 s

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
