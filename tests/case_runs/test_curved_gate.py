"""The curved flexible gate of docs/examples/curved_gate.pbtxt (a shell given
as a band about a curved mid-line) run briefly through the launcher: the water
runs out under the gate, pushes it downstream, and never gets into it.

Run by ctest (coupled_cases); by hand:
  COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs \
      -p test_curved_gate.py
"""
import glob
import os
import unittest

import h5py
import numpy as np

import case_runs
from case_runs import REPO, read_csv

EXAMPLE = os.path.join(REPO, "docs", "examples", "curved_gate.pbtxt")
END_TIME = 0.1      # s: the water has run out under the gate and bent it
THICKNESS = 0.005   # m, the gate's


def distance_to_line(points, line):
    """Each point's distance to the polyline through `line`'s points."""
    distance = np.full(len(points), np.inf)
    for a, b in zip(line[:-1], line[1:]):
        t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
        distance = np.minimum(distance, np.linalg.norm(points - (a + t[:, None] * (b - a)), axis=1))
    return distance


class CurvedGate(case_runs.CaseRunTest):
    CASE = EXAMPLE
    SETTINGS = [f"run.end_time={END_TIME}", "run.snapshot_interval=0.02"]

    def test_no_water_gets_into_the_gate(self):
        fluid = sorted(glob.glob(os.path.join(self.out, "fluid_*.h5")))
        solid = sorted(glob.glob(os.path.join(self.out, "solid_*.h5")))
        self.assertEqual(len(fluid), len(solid))
        self.assertGreaterEqual(len(fluid), 5)
        for fluid_file, solid_file in zip(fluid, solid):
            with h5py.File(fluid_file) as f:
                water = f["position"][:, :2][f["kind"][:] == 0]
            with h5py.File(solid_file) as f:
                mid_line = f["position"][:, :2]
            # Every water particle's centre stays outside the plate's
            # section, half the thickness either side of its mid-line.
            self.assertGreater(distance_to_line(water, mid_line).min(), 0.5 * THICKNESS,
                               fluid_file)

    def test_the_water_runs_out_and_bends_the_gate_downstream(self):
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        self.assertAlmostEqual(series["t"][-1], END_TIME, delta=1e-9)
        self.assertEqual(series["water_particles"][-1], series["water_particles"][0])
        self.assertGreater(series["front"][-1], 0.18)  # m: well past the gate's foot at 0.13 m
        # Pushed downstream by millimetres, not blown away.
        self.assertGreater(series["tip_dx"][-1], 0.001)
        self.assertLess(series["tip_dx"][-1], 0.03)


if __name__ == "__main__":
    unittest.main()
