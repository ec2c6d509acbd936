"""The elastic plate (three processes through the launcher) in a short mode,
against a stored reference, plus the invariants every coupled run must keep.

Run by ctest; by hand: COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs
Regenerate the reference after a deliberate physics change with
COSPH_UPDATE_REFERENCE=1 (and say why in the commit)."""
import os
import shutil
import unittest

import numpy as np

import case_runs
from case_runs import REPO, read_csv

REFERENCE = os.path.join(REPO, "tests", "reference", "elastic_plate_short.csv")
END_TIME = 0.004  # s: about 1900 common steps, a few seconds


class ElasticPlateShort(case_runs.CaseRunTest):
    CASE = "elastic_plate"
    # Synchronised steps, as the stored reference was made (the case's own
    # choice is tested in test_auto_substeps.py).
    SETTINGS = [f"run.end_time={END_TIME}", "run.output_interval=0.0005",
                "coupling.max_substeps=1"]

    def test_matches_stored_reference(self):
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        if os.environ.get("COSPH_UPDATE_REFERENCE"):
            shutil.copy(os.path.join(self.out, "timeseries.csv"), REFERENCE)
        reference = read_csv(REFERENCE)
        self.assertAlmostEqual(series["t"][-1], END_TIME, delta=1e-9)
        for column, tolerance in (("tip_dx", 2e-5), ("tip_dy", 2e-5), ("level", 2e-4)):
            ours = np.interp(reference["t"], series["t"], series[column])
            np.testing.assert_allclose(ours, reference[column], atol=tolerance, err_msg=column)
        # The water pushes the plate downstream: a frozen coupling cannot pass.
        self.assertGreater(series["tip_dx"][-1], 1e-4)

    def test_summary_names_the_end_time(self):
        # The coupler's progress lines come at most twice a second; its last
        # one must still reach the launcher's summary.
        self.assertIn(f"simulated {END_TIME:g} s", self.log)

    def test_cross_phase_forces_cancel_and_follow_the_interface(self):
        coupling = read_csv(os.path.join(self.out, "coupling.csv"))
        for axis in "xy":
            fluid, solid = coupling[f"force_on_fluid_{axis}"], coupling[f"force_on_solid_{axis}"]
            scale = np.max(np.abs(fluid)) + 1e-30
            self.assertLess(np.max(np.abs(fluid + solid)) / scale, 1e-10)
        self.assertTrue(np.all(coupling["pairs"] > 0))
        # Water pushes the plate downstream (+x) from the first step.
        self.assertGreater(coupling["force_on_solid_x"][0], 0.0)

    def test_each_solver_wrote_snapshots_paraview_can_open(self):
        for name in ("fluid", "solid"):
            index = os.path.join(self.out, f"{name}.xdmf")
            self.assertTrue(os.path.exists(index), name)
            with open(index) as f:
                self.assertIn(f"{name}_000000.h5:/position", f.read())


if __name__ == "__main__":
    unittest.main()
