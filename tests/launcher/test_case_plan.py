"""`cosph run` refuses a bad coupling.* value through the real cosph-case,
before any process starts, naming the file, the field and the reason.

COSPH_TEST_BIN is the folder of the built cosph-case (ctest sets it; default
build/bin). The coupler, fluid and solid are the fakes of fake_bin/, which
record in FAKE_DIR that they were started.
"""
import os
import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FAKE_BIN = HERE / "fake_bin"
REAL_BIN = Path(os.environ.get("COSPH_TEST_BIN", REPO / "build" / "bin"))


class BadCouplingFields(unittest.TestCase):
    def setUp(self):
        case_exe = REAL_BIN / "cosph-case"
        if not os.access(case_exe, os.X_OK):
            if os.environ.get("COSPH_TEST_BIN"):
                self.fail(f"{case_exe} is missing (COSPH_TEST_BIN={REAL_BIN})")
            self.skipTest(f"no built {case_exe}; set COSPH_TEST_BIN")
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph-plan-"))
        self.bin = self.tmp / "bin"
        shutil.copytree(FAKE_BIN, self.bin)
        (self.bin / "cosph-case").unlink()
        (self.bin / "cosph-case").symlink_to(case_exe.resolve())
        self.state = self.tmp / "state"
        self.state.mkdir()
        self.env = {k: v for k, v in os.environ.items() if not k.startswith(("COSPH_", "FAKE_"))}
        self.env.update(COSPH_BIN=str(self.bin), FAKE_DIR=str(self.state), FAKE_STEPS="3")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

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
