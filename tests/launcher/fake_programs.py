"""What the launcher tests that run the real cosph-case share: a folder of
the fake programs of fake_bin/ with a link to the built cosph-case in it,
and an environment that points cosph at that folder.

COSPH_TEST_BIN is the folder of the built cosph-case (ctest sets it; default
build/bin): without it and without a build, the tests skip; with it set and
the program missing, they fail.
"""
import os
import shutil
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FAKE_BIN = HERE / "fake_bin"
REAL_BIN = Path(os.environ.get("COSPH_TEST_BIN", REPO / "build" / "bin"))


class FakeProgramsWithRealCase:
    """A unittest.TestCase mixin. setUp makes self.tmp (removed by tearDown),
    self.bin (the fakes and the real cosph-case), self.state (where the fakes
    record that they ran: FAKE_DIR) and self.env (cosph's environment)."""

    tmp_prefix = "cosph-"

    def setUp(self):
        case_exe = REAL_BIN / "cosph-case"
        if not os.access(case_exe, os.X_OK):
            if os.environ.get("COSPH_TEST_BIN"):
                self.fail(f"{case_exe} is missing (COSPH_TEST_BIN={REAL_BIN})")
            self.skipTest(f"no built {case_exe}; set COSPH_TEST_BIN")
        self.tmp = Path(tempfile.mkdtemp(prefix=self.tmp_prefix))
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
