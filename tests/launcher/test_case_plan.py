"""`cosph run` refuses a bad coupling.* value through the real cosph-case,
before any process starts, naming the file, the field and the reason.

The coupler, fluid and solid are the fakes of fake_bin/, which record in
FAKE_DIR that they were started (fake_programs.py).
"""
import subprocess
import unittest

from fake_programs import REPO, FakeProgramsWithRealCase


class BadCouplingFields(FakeProgramsWithRealCase, unittest.TestCase):
    tmp_prefix = "cosph-plan-"

    def launch(self, *settings):
        command = [str(REPO / "coupler" / "cosph"), "run", "elastic_plate",
                   "--out", str(self.tmp / "out"), "--quiet"]
        for setting in settings:
            command += ["--set", setting]
        return subprocess.run(command, env=self.env, stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=60)

    def test_each_bad_value_is_refused_before_anything_starts(self):
        refusals = {
            "coupling.interface=foo": "unknown interface model 'foo'",
            "coupling.timeout=-1": "not negative",
            "coupling.timeout=inf": "finite",
            "coupling.timeout=nan": "finite",
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

    def test_a_good_case_starts_all_three(self):
        proc = self.launch("coupling.timeout=5")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        started = sorted(p.name[:-len(".pid")] for p in self.state.glob("*.pid"))
        self.assertEqual(started, ["cosph-coupler", "cosph-fluid", "cosph-solid-jaumann"])


if __name__ == "__main__":
    unittest.main()
