"""Every error names its file or peer: ZeroMQ's own words ("No such file or
directory", "Permission denied") do not say which endpoint or file they are
about, so the programs add it."""
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

from fake_programs import REAL_BIN, REPO


class ErrorsNamePaths(unittest.TestCase):
    def setUp(self):
        self.coupler = REAL_BIN / "cosph-coupler"
        if not os.access(self.coupler, os.X_OK):
            if os.environ.get("COSPH_TEST_BIN"):
                self.fail(f"{self.coupler} is missing (COSPH_TEST_BIN={REAL_BIN})")
            self.skipTest(f"no built {self.coupler}; set COSPH_TEST_BIN")
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph-names-"))

    def tearDown(self):
        subprocess.run(["rm", "-rf", str(self.tmp)], check=False)

    def test_an_endpoint_the_coupler_cannot_bind_is_named(self):
        endpoint = f"ipc://{self.tmp}/missing/coupler.sock"
        proc = subprocess.run(
            [str(self.coupler), "--case", str(REPO / "cases" / "elastic_plate.pbtxt"),
             "--out", str(self.tmp / "out"), "--endpoint", endpoint],
            stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn(f"cannot bind the coupling endpoint {endpoint}: No such file or directory",
                      proc.stderr)


if __name__ == "__main__":
    unittest.main()
