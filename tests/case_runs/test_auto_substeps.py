"""coupling.max_substeps 0 (every case's default): the coupler chooses
multi-rate coupling for the elastic plate and synchronised steps for a plate
20 times lighter than the water (coupler/src/substep_choice.hpp), says so on
its first line, and then steps exactly as the explicit setting would. A solid
that reports undamped modes in its Hello (the shell without its damping) turns
the multi-rate choice into synchronised steps, on a later line; the damped
shell keeps multi-rate, its windows no longer than 2 zeta / (s omega) of its
fastest mode (its Hello) with s by the case's water, and says so."""
import os
import re
import shutil
import tempfile
import unittest

import numpy as np

import case_runs


def median_common_step(case, settings, end_time):
    """The run's median common step (coupling.csv, every step), and its log."""
    out = tempfile.mkdtemp(prefix=f"cosph_auto_{case}_")
    try:
        result = case_runs.run_case(case, out, settings + [
            f"run.end_time={end_time}", f"run.snapshot_interval={end_time}"])
        if result.returncode != 0:
            raise AssertionError(result.stdout)
        dt = case_runs.read_csv(os.path.join(out, "coupling.csv"))["dt"]
        return float(np.median(dt[:-1])), result.stdout   # the last is cut to the end time
    finally:
        shutil.rmtree(out, ignore_errors=True)


class AutomaticChoice:
    """A default run against runs with the explicit settings it must equal
    (SAME) and must not (OTHER)."""
    SETTINGS, SAME, OTHER, CHOSEN, END_TIME = [], None, None, None, None
    ALSO_SAYS = []

    @classmethod
    def setUpClass(cls):
        cls.auto, cls.log = median_common_step("elastic_plate", cls.SETTINGS, cls.END_TIME)
        cls.same, _ = median_common_step("elastic_plate", cls.SETTINGS + [cls.SAME], cls.END_TIME)
        cls.other, _ = median_common_step("elastic_plate", cls.SETTINGS + [cls.OTHER],
                                          cls.END_TIME)

    def test_steps_as_the_chosen_setting(self):
        # The two explicit settings step differently here, so the check tells them apart.
        self.assertGreater(max(self.same, self.other) / min(self.same, self.other), 5.0)
        self.assertAlmostEqual(self.auto / self.same, 1.0, delta=1e-3)

    def test_says_what_it_chose_and_why(self):
        lines = re.findall(r"sub-stepping: (.*)", self.log)
        self.assertTrue(lines, self.log)
        self.assertTrue(lines[-1].startswith(self.CHOSEN), lines[-1])
        self.assertIn("added-mass ratio of a window", lines[-1])
        for word in self.ALSO_SAYS:
            self.assertIn(word, lines[-1])


class ElasticPlateTakesMultiRate(AutomaticChoice, unittest.TestCase):
    SAME, OTHER, CHOSEN = "coupling.max_substeps=32", "coupling.max_substeps=1", "multi-rate"
    END_TIME = 0.001  # s: 26 windows, 480 synchronised steps


class LightPlateTakesSynchronisedSteps(AutomaticChoice, unittest.TestCase):
    SETTINGS = ["solid.density=50"]   # rho_s / rho_f = 0.05: multi-rate breaks (stability map)
    SAME, OTHER, CHOSEN = "coupling.max_substeps=1", "coupling.max_substeps=32", "synchronised"
    END_TIME = 0.0003  # s: some 700 synchronised steps


class UndampedShellTakesSynchronisedSteps(AutomaticChoice, unittest.TestCase):
    # The added-mass ratio alone allows multi-rate; the solid's Hello says no.
    SETTINGS = ["solid.model=shell", "solid.shell_damping=false"]
    SAME, OTHER, CHOSEN = "coupling.max_substeps=1", "coupling.max_substeps=32", "synchronised"
    ALSO_SAYS = ["does not damp", "multi-rate"]
    END_TIME = 0.0005


class DampedShellWindows:
    """Multi-rate, but each window no longer than 2 zeta / (s omega) of the
    shell's fastest mode (its Hello) with the coupling share s of the case's
    water (substep_choice.hpp)."""
    SETTINGS, SHARE, LONGEST_SHARE_OF_WIDE = [], None, None
    END_TIME = 0.0005

    @classmethod
    def setUpClass(cls):
        cls.auto, cls.log = median_common_step("elastic_plate", cls.SETTINGS, cls.END_TIME)
        cls.sync, _ = median_common_step("elastic_plate", cls.SETTINGS + [
            "coupling.max_substeps=1"], cls.END_TIME)
        cls.wide, _ = median_common_step("elastic_plate", cls.SETTINGS + [
            "coupling.max_substeps=32"], cls.END_TIME)

    def stated(self):
        """(the bound, zeta, omega, s) as the last sub-stepping line gives them."""
        lines = re.findall(r"sub-stepping: (.*)", self.log)
        self.assertTrue(lines, self.log)
        found = re.search(r"windows at most ([0-9.e+-]+) s .* with zeta ([0-9.e+-]+), omega "
                          r"([0-9.e+-]+) rad/s, s ([0-9.e+-]+)", lines[-1])
        self.assertTrue(found, lines[-1])
        return [float(value) for value in found.groups()]

    def test_the_bound_is_the_rule_with_the_waters_share(self):
        bound, zeta, omega, share = self.stated()
        self.assertEqual(share, self.SHARE)
        # The log prints 6 digits.
        self.assertAlmostEqual(bound / (2.0 * zeta / (share * omega)), 1.0, delta=1e-4)

    def test_the_window_is_the_damping_bound(self):
        bound = self.stated()[0]
        # The water's and the shell's proposals lie on either side of the bound
        # here, so the bound sets every window, shorter than the added-mass
        # rule's alone.
        self.assertAlmostEqual(self.auto / bound, 1.0, delta=1e-4)
        self.assertLess(self.auto, self.LONGEST_SHARE_OF_WIDE * self.wide)

    def test_still_multi_rate(self):
        self.assertGreater(self.auto, 2.0 * self.sync)


class DampedShellInTheDefaultWater(DampedShellWindows, unittest.TestCase):
    # The Riemann water's measured share: about 26 us at the case's 1 mm, where
    # the added-mass rule alone takes the water's whole step (about 45 us).
    SETTINGS = ["solid.model=shell"]
    SHARE, LONGEST_SHARE_OF_WIDE = 0.2, 0.7


class DampedShellInADeltaSphWater(DampedShellWindows, unittest.TestCase):
    # s = 1: about 5 us.
    SETTINGS = ["solid.model=shell", "fluid.dissipation=delta_sph", "fluid.kernel=cubic_spline",
                "fluid.h_factor=1.3"]
    SHARE, LONGEST_SHARE_OF_WIDE = 1.0, 0.2


if __name__ == "__main__":
    unittest.main()
