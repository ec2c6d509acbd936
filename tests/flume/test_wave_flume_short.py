"""The wave flume's short mode (cases/wave_flume.pbtxt; docs/validation.md,
"Wave flume"): spacing 20 mm (12.5 particles over the depth, a quarter of the
default's particles), one period, T = 1 s, through the launcher, until a
reflection from the beach's shoreline could be back at the gauge. Asserts

- the level gauge reads the still level at the start within 2 % of a spacing:
  at 20 mm the water box's 12.5 rows round to 13, so the lattice's top edge,
  the still level, is 0.26 m;
- waves arrive, between 90 and 105 % of Biesel's height for that depth: at
  this spacing the waves are less than a spacing high and measured 5 % low
  (docs/validation.md, "Wave flume"); with the previous settings (cubic
  spline, whose particles pair up over these seconds) they were 16 to 24 %
  low at 10 mm, and with the Wendland kernel at h = 1.3 dx about 15 % low,
  which the bound refuses.
"""
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "case_runs"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))

import case_runs  # noqa: E402
import wave_theory as wt  # noqa: E402

DEPTH, STILL_LEVEL, STROKE, GAUGE_X = 0.25, 0.26, 0.02, 1.0
BEACH = wt.Beach(DEPTH, toe_x=3.0, slope=0.1)  # cases/wave_flume.pbtxt
PERIOD, SPACING = 1.0, 0.02


class WaveFlumeShort(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="cosph_wave_flume_")
        nominal = wt.biesel_height_over_stroke(PERIOD, DEPTH) * STROKE
        cls.t_from, cls.t_to = wt.gauge_window(PERIOD, PERIOD, GAUGE_X, BEACH, nominal)
        out = os.path.join(cls.dir, "out")
        cls.result = case_runs.run_case(
            "wave_flume", out,
            [f"fluid.spacing={SPACING}", f"fluid.moving_walls[0].piston.period={PERIOD}",
             f"fluid.moving_walls[0].piston.ramp_time={PERIOD}", f"run.end_time={cls.t_to + 0.05}",
             "run.snapshot_interval=100"])
        cls.series = (case_runs.read_csv(os.path.join(out, "timeseries.csv"))
                      if cls.result.returncode == 0 else None)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def setUp(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout)

    def test_gauge_reads_the_still_level(self):
        level = self.series["level0"]
        self.assertAlmostEqual(level[0], STILL_LEVEL, delta=0.02 * SPACING)

    def test_wave_height_is_biesels(self):
        self.assertGreaterEqual(self.t_to - self.t_from, 2 * PERIOD)
        height, _ = wt.first_harmonic_height(self.series["t"], self.series["level0"], PERIOD,
                                             self.t_from, self.t_to)
        theory = wt.biesel_height_over_stroke(PERIOD, STILL_LEVEL) * STROKE
        self.assertTrue(0.9 <= height / theory <= 1.05,
                        msg=f"H = {1e3 * height:.2f} mm, Biesel {1e3 * theory:.2f} mm")


if __name__ == "__main__":
    unittest.main()
