"""The water column on a clamped plate (cases/hydrostatic_plate.pbtxt, three
processes through the launcher) in a short mode: the first 2 ms, about half a
period of the plate's first mode, at the case's own spacings and stepping.
Checks that the interface passes the water's hydrostatic pressure to the
shell at rest without bias, and that the plate answers the sudden load within
the bound of a linear system (the full run and its settled deflection:
scripts/validate_hydrostatic_plate.py).

Run by ctest; by hand: COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs"""
import os
import sys
import unittest

import numpy as np

import case_runs
from case_runs import REPO, read_csv

sys.path.insert(0, os.path.join(REPO, "scripts"))
import hydrostatic_plate as hp  # noqa: E402  (the theory the validation uses)

END_TIME = 0.002  # s


class HydrostaticPlateShort(case_runs.CaseRunTest):
    CASE = "hydrostatic_plate"
    SETTINGS = [f"run.end_time={END_TIME}", f"run.snapshot_interval={END_TIME}"]

    def test_the_case_runs_the_shell_multi_rate(self):
        # A window of this heavy plate is far from mu_W = 1, so multi-rate;
        # the damped shell states its fastest mode, which bounds the window.
        self.assertIn("cosph-solid-shell", self.log)
        self.assertIn("sub-stepping: multi-rate, at most 32 sub-steps a window (automatic",
                      self.log)
        self.assertIn("sub-stepping: multi-rate, at most 32 sub-steps a window, windows at most",
                      self.log)

    def test_the_water_weighs_on_the_plate_at_rest(self):
        # At t = 0 both are at rest and the water in hydrostatic balance: the
        # moving wall's pressure over the plate adds up to the water's weight
        # rho g H L (the held ends carry the water's walls, not water). The
        # kernel's cut at the plate's lower face (e = 0.05 m against a reach
        # of 2 h = 0.06 m) and the corners allow a few per cent.
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        self.assertEqual(series["t"][0], 0.0)
        self.assertAlmostEqual(-series["plate_force_y"][0] / hp.water_load(), 1.0, delta=0.03)
        self.assertLess(abs(series["plate_force_x"][0]), 1e-6 * hp.water_load())

    def test_the_plate_answers_the_sudden_load(self):
        # A linear system under a load switched on at once swings to at most
        # twice its static deflection (less, as the water takes energy away).
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        self.assertAlmostEqual(series["t"][-1], END_TIME, delta=1e-9)
        _w_eb, w_t = hp.static_deflection()
        deflection = -series["tip_dy"]
        self.assertGreater(deflection.max(), 0.5 * w_t)
        self.assertLess(deflection.max(), 2.0 * w_t)
        self.assertTrue(np.all(deflection >= 0.0))


if __name__ == "__main__":
    unittest.main()
