"""`cosph run` refuses a bad coupling.* value through the real cosph-case,
before any process starts, naming the file, the field and the reason.

The coupler, fluid and solid are the fakes of fake_bin/, which record in
FAKE_DIR that they were started (fake_programs.py).
"""
import subprocess
import unittest

from fake_programs import REPO, FakeProgramsWithRealCase


class LaunchesElasticPlate(FakeProgramsWithRealCase):
    """`cosph run elastic_plate` with the given --set values, into a fresh folder."""

    def launch(self, *settings):
        command = [str(REPO / "coupler" / "cosph"), "run", "elastic_plate",
                   "--out", str(self.tmp / "out"), "--quiet"]
        for setting in settings:
            command += ["--set", setting]
        return subprocess.run(command, env=self.env, stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=60)


class BadCouplingFields(LaunchesElasticPlate, unittest.TestCase):
    tmp_prefix = "cosph-plan-"

    def test_each_bad_value_is_refused_before_anything_starts(self):
        refusals = {
            "coupling.interface=foo": "unknown interface model 'foo'",
            "coupling.timeout=-1": "not negative",
            "coupling.timeout=inf": "finite",
            "coupling.timeout=nan": "finite",
            "coupling.timeout=1e300": "must be at most 1e+06 s",
            "coupling.max_substeps=-1": "must not be negative",
            "coupling.solid_step=half": "must be \"own\"",
            "coupling.artificial_viscosity=-0.5": "must not be negative",
            "coupling.artificial_viscosity_quadratic=inf": "finite",
        }
        for setting, reason in refusals.items():
            with self.subTest(setting=setting):
                proc = self.launch(setting)
                field = setting.split("=")[0]
                self.assertEqual(proc.returncode, 2, proc.stderr)
                self.assertIn("elastic_plate.pbtxt", proc.stderr)
                self.assertIn(f"{field}:", proc.stderr)
                self.assertIn(reason, proc.stderr)
                self.assertEqual(list(self.state.glob("*.pid")), [],
                                 "a process was started before the case was refused")

    def test_fracture_on_a_solid_without_it_is_refused_before_anything_starts(self):
        for model in ("shell", "total_lagrangian"):
            with self.subTest(model=model):
                proc = self.launch(f"solid.model={model}", "solid.fracture.enabled=true",
                                   "solid.fracture.yield_stress=1e5")
                self.assertEqual(proc.returncode, 2, proc.stderr)
                self.assertIn("elastic_plate.pbtxt: solid.fracture.enabled: von Mises failure "
                              f"is not implemented for solid.model '{model}'", proc.stderr)
                self.assertEqual(list(self.state.glob("*.pid")), [],
                                 "a process was started before the case was refused")

    def test_a_good_case_starts_all_three(self):
        proc = self.launch("coupling.timeout=5")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        started = sorted(p.name[:-len(".pid")] for p in self.state.glob("*.pid"))
        self.assertEqual(started, ["cosph-coupler", "cosph-fluid", "cosph-solid-jaumann"])


class BadNumbersAnywhere(LaunchesElasticPlate, unittest.TestCase):
    """Every number of a case is checked for infinities and NaN by one walk
    over the parsed case (sph::require_finite), so that no field's own check
    can miss one; and a scene too large for the particle limit is refused
    with its estimate before anything is allocated."""
    tmp_prefix = "cosph-numbers-"

    def test_non_finite_values_are_refused_naming_the_field(self):
        for setting in ("run.end_time=inf", "fluid.density=inf", "solid.youngs_modulus=nan",
                        "fluid.water[0].max.x=-inf", "run.gravity.y=nan",
                        "solid.tip_gauge.x=inf"):
            with self.subTest(setting=setting):
                proc = self.launch(setting)
                field = setting.split("=")[0]
                self.assertEqual(proc.returncode, 2, proc.stderr)
                self.assertIn(f"elastic_plate.pbtxt: {field}: must be a finite number",
                              proc.stderr)
                self.assertNotIn("Traceback", proc.stderr)
                self.assertEqual(list(self.state.glob("*.pid")), [],
                                 "a process was started before the case was refused")

    def test_a_spacing_far_too_small_is_refused_with_the_estimate(self):
        # 1e-5 m would make some 10^9 particles; refused within the timeout,
        # not allocated.
        proc = self.launch("fluid.spacing=1e-5")
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("run.max_particles: the scene would make up to", proc.stderr)
        self.assertIn("--set run.max_particles=", proc.stderr)
        self.assertEqual(list(self.state.glob("*.pid")), [])

    def test_the_limit_is_the_case_field(self):
        lowered = self.launch("run.max_particles=1000")
        self.assertEqual(lowered.returncode, 2, lowered.stderr)
        self.assertIn("more than the limit 1000", lowered.stderr)
        raised = self.launch("run.max_particles=1000", "run.max_particles=1e6")
        self.assertEqual(raised.returncode, 0, raised.stderr)


if __name__ == "__main__":
    unittest.main()
