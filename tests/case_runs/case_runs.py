"""What the coupled-case tests share: a case run through the launcher
(coupler/cosph, three processes), a test class around one such run, and the
run's CSV output read by column name."""
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run_case(case, out, settings):
    """Runs cases/CASE.pbtxt into OUT with each FIELD=VALUE of SETTINGS;
    returns the finished process, its output and errors together in stdout."""
    command = [os.path.join(REPO, "coupler", "cosph"), "run", case, "--out", out, "--quiet",
               "--overwrite",
               # ctest runs other process-heavy tests beside these: a peer
               # starved of the cores for 10 s is not what they are about.
               "--set", "coupling.timeout=60"]
    for setting in settings:
        command += ["--set", setting]
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          # Seconds in a release build; sanitizer builds are tens of times slower.
                          timeout=float(os.environ.get("COSPH_CASE_TIMEOUT", "1500")))


def read_csv(path):
    """The columns of a cosph CSV file by name, units dropped: "t [s]" is "t"."""
    with open(path) as f:
        names = [n.split(" [")[0] for n in f.readline().strip().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


class CaseRunTest(unittest.TestCase):
    """Runs cases/CASE.pbtxt (or the case file CASE) with SETTINGS once for
    the whole class, into a temporary folder `out` (removed afterwards) with
    the launcher's output in `log`; every test first checks that the run
    succeeded."""
    CASE = None
    SETTINGS = []

    @classmethod
    def setUpClass(cls):
        cls.out = tempfile.mkdtemp(prefix=f"cosph_{os.path.basename(cls.CASE)}_")
        result = run_case(cls.CASE, cls.out, cls.SETTINGS)
        cls.log = result.stdout
        cls.returncode = result.returncode

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.out, ignore_errors=True)

    def setUp(self):
        self.assertEqual(self.returncode, 0, self.log)
