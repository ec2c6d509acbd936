"""The wave flume's theory helpers (scripts/wave_theory.py) on answers known in
closed form: the two-gauge separation of incident and reflected waves on a
synthetic record, and the travel time over the beach in the long-wave limit.
"""
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))

import wave_theory as wt  # noqa: E402

DEPTH = 0.25


class IncidentAndReflected(unittest.TestCase):
    def test_separates_a_synthetic_partial_standing_wave(self):
        period, x_a, x_b = 1.3, 1.0, 1.3
        k, omega = wt.wavenumber(period, DEPTH), 2 * np.pi / period
        t = np.arange(0.0, 10.0, 0.01)

        def level(x):  # 20 mm incident, 3 mm reflected, a phase between them
            return (DEPTH + 0.010 * np.cos(omega * t - k * x + 0.4)
                    + 0.0015 * np.cos(omega * t + k * x - 1.1))

        incident, reflected = wt.incident_and_reflected(
            t, level(x_a), level(x_b), x_a, x_b, period, DEPTH, 2 * period, 6 * period)
        self.assertAlmostEqual(incident, 0.020, delta=1e-9)
        self.assertAlmostEqual(reflected, 0.003, delta=1e-9)


class BeachTravelTime(unittest.TestCase):
    def test_long_waves_take_the_closed_form_time(self):
        # At c = sqrt(g h) the slope from depth d to the shoreline takes
        # 2 L / sqrt(g d), L = d / s its length.
        beach = wt.Beach(DEPTH, toe_x=3.0, slope=0.1)
        long_wave = lambda h: np.sqrt(wt.G * h)  # noqa: E731
        expected = (3.0 - 1.0 + 2 * 2.5) / np.sqrt(wt.G * DEPTH)
        self.assertAlmostEqual(beach.time_to_shore(1.0, long_wave), expected, delta=1e-3)
        # From a point on the slope, 1 m before the shoreline.
        self.assertAlmostEqual(beach.time_to_shore(4.5, long_wave),
                               2 * 1.0 / np.sqrt(wt.G * 0.1), delta=1e-3)


if __name__ == "__main__":
    unittest.main()
