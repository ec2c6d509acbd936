"""The coupled plate with the solid stepped at the fluid's step
(coupling.solid_step = "fluid", issue 6's stability map): the rubber's sound
speed allows a step some 18 times shorter, so the run must stop with an error
that names the cause, not go on quietly wrong, and leave its last snapshot.

Run by ctest; by hand: COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs"""
import glob
import os
import shutil
import tempfile
import unittest

from case_runs import run_case


def run_plate(out, *settings):
    return run_case("elastic_plate", out, ["run.end_time=0.01", *settings])


class SolidAtFluidStep(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="cosph_fluid_step_")

    def tearDown(self):
        shutil.rmtree(self.out, ignore_errors=True)

    def test_run_stops_with_an_error_naming_the_cause(self):
        result = run_plate(self.out, "coupling.solid_step=fluid")
        self.assertNotEqual(result.returncode, 0, result.stdout)
        # The solid's step check catches the blow-up within a few steps of
        # 0.01 s, and says both what happened and why the step was so long.
        self.assertIn("the run has blown up", result.stdout)
        self.assertIn("times its stable step, as coupling.solid_step = \"fluid\" asks",
                      result.stdout)
        self.assertIn("warning: taking the coupler's step", result.stdout)
        self.assertTrue(glob.glob(os.path.join(self.out, "solid_*.h5")),
                        "the last good snapshot is kept")

    def test_an_unknown_rule_is_refused_naming_the_field(self):
        result = run_plate(self.out, "coupling.solid_step=sometimes")
        self.assertNotEqual(result.returncode, 0, result.stdout)
        self.assertIn("coupling.solid_step", result.stdout)
        self.assertIn("\"sometimes\"", result.stdout)


if __name__ == "__main__":
    unittest.main()
