"""The launcher starts a solid of the user's own that only the case names
(solid.executable), through the real cosph-case, and refuses a case whose
program is missing before anything starts.

Run from the repository root:
    COSPH_TEST_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/launcher -v

The coupler and the fluid are the fakes of fake_bin/, copied next to a link
to the real cosph-case (fake_programs.py); the third-party solid is a fake
too (fake_solver.py), named my-solid, in the case's folder or on PATH.
"""
import json
import os
import subprocess
import unittest

from fake_programs import FAKE_BIN, REPO, FakeProgramsWithRealCase

MY_SOLID = f"""#!/usr/bin/python3
# A solid model of someone else's: the fake solver, under another name.
import sys
sys.dont_write_bytecode = True
sys.path.insert(0, {str(FAKE_BIN)!r})
import fake_solver
fake_solver.main("my-solid")
"""


def coupled_case(executable, model="my_model"):
    """cases/elastic_plate.pbtxt with the solid block naming another model and program."""
    text = (REPO / "cases" / "elastic_plate.pbtxt").read_text()
    assert 'model: "jaumann"' in text
    return text.replace('model: "jaumann"',
                        f'model: "{model}"\n  executable: "{executable}"')


class ThirdPartySolid(FakeProgramsWithRealCase, unittest.TestCase):
    tmp_prefix = "cosph-3rd-"

    def setUp(self):
        super().setUp()
        (self.bin / "cosph-solid-jaumann").unlink()   # the built-in solid must not be what runs
        self.cases = self.tmp / "my_cases"
        self.cases.mkdir()
        self.out = self.tmp / "out"

    def install(self, folder, name="my-solid", executable=True):
        folder.mkdir(parents=True, exist_ok=True)
        program = folder / name
        program.write_text(MY_SOLID)
        program.chmod(0o755 if executable else 0o644)
        return program

    def launch(self, case_text, *extra, **env):
        case = self.cases / "plate.pbtxt"
        case.write_text(case_text)
        proc = subprocess.run([str(REPO / "coupler" / "cosph"), "run", str(case),
                               "--out", str(self.out), "--quiet", "--overwrite", *extra],
                              env={**self.env, **env}, stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=60)
        return case, proc

    def started(self):
        return sorted(p.name[:-len(".pid")] for p in self.state.glob("*.pid"))

    def test_solid_named_only_in_the_case_is_started(self):
        program = self.install(self.cases)
        case, proc = self.launch(coupled_case("my-solid"))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(self.started(), ["cosph-coupler", "cosph-fluid", "my-solid"])
        args = json.loads((self.state / "my-solid.args").read_text())
        self.assertEqual(args[:4], ["--case", str(case), "--out", str(self.out)])
        self.assertEqual(args[-2:], ["--endpoint", f"ipc://{self.out}/private/coupler.sock"])
        self.assertIn(str(program), (self.out / "command.txt").read_text())

    def test_program_on_path_and_by_relative_path(self):
        elsewhere = self.tmp / "tools"
        self.install(elsewhere)
        _, proc = self.launch(coupled_case("my-solid"),
                              PATH=f"{elsewhere}:{os.environ.get('PATH', '')}")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("my-solid", self.started())
        for pid in self.state.glob("*.pid"):
            pid.unlink()
        # A path with a "/" is taken from the case's folder, not the working directory.
        self.install(self.cases / "solids")
        _, proc = self.launch(coupled_case("solids/my-solid"))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("my-solid", self.started())

    @unittest.skipIf(len(os.sched_getaffinity(0)) < 2, "needs two cores")
    def test_multi_rate_plan_gives_each_solver_cores_of_its_own(self):
        """The real plan asks for it in a multi-rate run only, and the solid of
        the user's own gets the second half of the cores as cosph-solid-jaumann would."""
        self.install(self.cases)
        allowed = sorted(os.sched_getaffinity(0))
        cores = {}
        for max_substeps in (1, 32):
            text = coupled_case("my-solid").replace(
                "max_substeps: 0", f"max_substeps: {max_substeps}", 1)
            _, proc = self.launch(text)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            cores[max_substeps] = {name: json.loads((self.state / f"{name}.cores").read_text())
                                   for name in ("cosph-coupler", "cosph-fluid", "my-solid")}
        self.assertEqual(cores[1], dict.fromkeys(cores[1], allowed))   # synchronised: free
        self.assertEqual(cores[32]["cosph-coupler"], allowed)
        self.assertEqual(sorted(cores[32]["cosph-fluid"] + cores[32]["my-solid"]), allowed)
        self.assertEqual(cores[32]["my-solid"], allowed[(len(allowed) + 1) // 2:])

    def test_missing_program_is_refused_naming_file_field_and_reason(self):
        case, proc = self.launch(coupled_case("no-such-solid"))
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn(str(case), proc.stderr)
        self.assertIn("solid.executable", proc.stderr)
        self.assertIn("no executable program 'no-such-solid'", proc.stderr)
        self.assertEqual(self.started(), [])   # nothing was started
        case, proc = self.launch(coupled_case("./gone/my-solid"))
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("does not exist", proc.stderr)
        self.assertEqual(self.started(), [])

    def test_program_that_is_not_executable_is_refused(self):
        self.install(self.cases, executable=False)
        _, proc = self.launch(coupled_case("./my-solid"))
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("solid.executable", proc.stderr)
        self.assertIn("is not executable", proc.stderr)
        _, proc = self.launch(coupled_case("my-solid"))   # by name: found, but not runnable
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("is not executable", proc.stderr)
        self.assertEqual(self.started(), [])

    def test_unknown_model_without_a_program_is_still_refused(self):
        text = coupled_case("x").replace('  executable: "x"\n', "")
        case, proc = self.launch(text)
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("solid.model", proc.stderr)
        self.assertIn("unknown model 'my_model'", proc.stderr)
        self.assertIn("solid.executable", proc.stderr)   # the hint
        self.assertEqual(self.started(), [])


if __name__ == "__main__":
    unittest.main()
