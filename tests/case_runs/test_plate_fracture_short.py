"""The fracture scene (cases/plate_fracture.pbtxt, three processes through the
launcher) in a short mode: the first 0.04 s, multi-rate coupling, and the
weakened band's yield stress lowered from 20 kPa to 4 kPa so that it fails
within that time (at t = 0.023 s, against 0.072 s in the full case). Checks
the invariants a run through fracture must keep: the plate breaks, the
failed particles stay in the coupling, no water inside a wall, every state
finite.

Run by ctest; by hand: COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/case_runs"""
import glob
import os
import unittest

import h5py
import numpy as np

import case_runs
from case_runs import read_csv

END_TIME = 0.04  # s
SHORT_MODE = [f"run.end_time={END_TIME}", "run.snapshot_interval=0.01",
              "coupling.max_substeps=32", "solid.fracture.weakened[0].yield_stress=4000"]


class PlateFractureShort(case_runs.CaseRunTest):
    CASE = "plate_fracture"
    SETTINGS = SHORT_MODE

    def test_the_plate_breaks_in_its_weakened_band(self):
        series = read_csv(os.path.join(self.out, "timeseries.csv"))
        self.assertAlmostEqual(series["t"][-1], END_TIME, delta=1e-9)
        self.assertGreater(series["failed"][-1], 0)
        # Failed for good: the count never falls.
        self.assertTrue(np.all(np.diff(series["failed"]) >= 0))
        # The broken part's gauge is written and moves downstream.
        self.assertTrue(np.all(np.isfinite(series["broken_x"])))
        self.assertGreater(series["broken_x"][-1], series["broken_x"][0])
        last = self.snapshots("solid")[-1]
        with h5py.File(last) as f:
            failed = f["failed"][:] == 1
            ids = f["id"][:]
        with h5py.File(self.snapshots("solid")[0]) as f:
            y0 = dict(zip(f["id"][:], f["position"][:, 1]))
        band = np.array([0.069 < y0[i] < 0.079 for i in ids[failed]])
        self.assertTrue(np.all(band), "a particle failed outside the weakened band")

    def test_failed_particles_stay_in_the_coupling(self):
        coupling = read_csv(os.path.join(self.out, "coupling.csv"))
        self.assertTrue(np.all(coupling["pairs"] > 0))
        for axis in "xy":
            fluid, solid = coupling[f"force_on_fluid_{axis}"], coupling[f"force_on_solid_{axis}"]
            scale = np.max(np.abs(fluid)) + 1e-30
            self.assertLess(np.max(np.abs(fluid + solid)) / scale, 1e-10)

    def test_no_water_inside_a_wall_and_every_state_finite(self):
        for path in self.snapshots("fluid"):
            with h5py.File(path) as f:
                x, kind = f["position"][:], f["kind"][:]
                for name in f:
                    self.assertTrue(np.all(np.isfinite(f[name][:])), f"{path}: {name}")
            water = x[kind == 0]
            self.assertGreaterEqual(water[:, 1].min(), 0.0, path)  # floor
            self.assertGreaterEqual(water[:, 0].min(), 0.0, path)  # left wall
        for path in self.snapshots("solid"):
            with h5py.File(path) as f:
                for name in f:
                    self.assertTrue(np.all(np.isfinite(f[name][:])), f"{path}: {name}")
                # The solid rests on the floor (solid.walls), it does not enter it.
                self.assertGreaterEqual(f["position"][:, 1].min(), 0.0, path)

    def snapshots(self, name):
        paths = sorted(glob.glob(os.path.join(self.out, f"{name}_0*.h5")))
        self.assertGreater(len(paths), 1, name)
        return paths


if __name__ == "__main__":
    unittest.main()
