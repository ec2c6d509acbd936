"""The example scene of docs/scenes.md (docs/examples/shapes_tank.pbtxt: a
polygon less a circle of water, a circle, a box less its inside, an outline
file and a triangle as walls) run briefly through the launcher: the water
column falls round the cylinder and runs along the floor, and none of it
gets into a wall or is lost.

Run by ctest (coupled_cases); by hand:
  COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs \
      -p test_scene_example.py
"""
import glob
import os
import subprocess
import unittest

import h5py
import numpy as np

import case_runs
from case_runs import REPO, read_csv

EXAMPLE = os.path.join(REPO, "docs", "examples", "shapes_tank.pbtxt")
END_TIME = 0.15  # s: the column's foot has run past the cylinder
DX = 0.01        # m, the example's spacing


def inside_polygon(points, vertices):
    """Crossing-number test of each point against a polygon's vertices."""
    x, y = points[:, 0], points[:, 1]
    inside = np.zeros(len(points), dtype=bool)
    for (xa, ya), (xb, yb) in zip(vertices, vertices[1:] + vertices[:1]):
        crosses = (ya > y) != (yb > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            x_cross = (xb - xa) * (y - ya) / (yb - ya) + xa
        inside ^= crosses & (x < x_cross)
    return inside


def depth_in_polygon(points, vertices):
    """How far inside a polygon each point lies (0 outside)."""
    distance = np.full(len(points), np.inf)
    for a, b in zip(vertices, vertices[1:] + vertices[:1]):
        a, b = np.array(a), np.array(b)
        t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
        distance = np.minimum(distance, np.linalg.norm(points - (a + t[:, None] * (b - a)), axis=1))
    return np.where(inside_polygon(points, vertices), distance, 0.0)


class SceneExample(case_runs.CaseRunTest):
    CASE = EXAMPLE
    SETTINGS = [f"run.end_time={END_TIME}", "run.snapshot_interval=0.05"]

    def water(self, snapshot):
        with h5py.File(snapshot) as f:
            kind, x = f["kind"][:], f["position"][:, :2]
        return x[kind == 0]

    def test_no_water_gets_into_a_wall(self):
        snapshots = sorted(glob.glob(os.path.join(self.out, "fluid_*.h5")))
        self.assertGreaterEqual(len(snapshots), 3)
        first, last = self.water(snapshots[0]), self.water(snapshots[-1])
        # The column has fallen and spread: its front is past its foot.
        self.assertGreater(last[:, 0].max(), first[:, 0].max() + 0.05)
        with open(os.path.join(REPO, "docs", "examples", "breakwater.csv")) as outline:
            breakwater = [tuple(map(float, line.split(","))) for line in outline
                          if line.strip() and not line.startswith("#")]
        beach = [(0.6, 0.0), (1.0, 0.0), (1.0, 0.2)]
        # A particle may come up to half a spacing into a wall's outline (its
        # centre stays off the wall particles' own), not deeper.
        margin = 0.5 * DX
        for x in (first, last):
            r = np.hypot(x[:, 0] - 0.1, x[:, 1] - 0.12)
            self.assertGreater(r.min(), 0.04 - margin, "water inside the cylinder")
            self.assertGreater(x[:, 0].min(), -margin, "water in the tank's left wall")
            self.assertLess(x[:, 0].max(), 1.0 + margin, "water in the tank's right wall")
            self.assertGreater(x[:, 1].min(), -margin, "water in the tank's floor")
            self.assertLess(depth_in_polygon(x, breakwater).max(), margin,
                            "water inside the breakwater")
            self.assertLess(depth_in_polygon(x, beach).max(), margin, "water inside the beach")

    def test_the_output_folders_case_runs_again(self):
        # The copy of the case names its outline file relative to itself: the
        # launcher copies the outline beside it, so the plan accepts the copy.
        self.assertTrue(os.path.isfile(os.path.join(self.out, "breakwater.csv")))
        bin_dir = os.environ.get("COSPH_BIN", os.path.join(REPO, "build", "bin"))
        plan = subprocess.run([os.path.join(bin_dir, "cosph-case"), "plan",
                               os.path.join(self.out, "case.pbtxt")],
                              capture_output=True, text=True, timeout=60)
        self.assertEqual(plan.returncode, 0, plan.stderr)

    def test_no_water_is_lost(self):
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        self.assertAlmostEqual(series["t"][-1], END_TIME, delta=1e-9)
        self.assertEqual(series["water_particles"][-1], series["water_particles"][0])
        self.assertGreater(series["water_particles"][0], 500)


if __name__ == "__main__":
    unittest.main()
