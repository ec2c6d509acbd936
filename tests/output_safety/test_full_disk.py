"""A full disk stops a run with a message that names the file, and leaves
every file whole: the XDMF index as it was before the write that failed (a
readable document listing only snapshots that exist), timeseries.csv with
whole rows, and no *.partial file.

The full disk is a file-size limit (RLIMIT_FSIZE, `ulimit -f`) with SIGXFSZ
ignored, so that a write past it fails with EFBIG as one on a full disk fails
with ENOSPC. The solver is started directly: the launcher, like any Python
subprocess, sets SIGXFSZ back to its default, which kills the process.

Before, the index was replaced by a torn one and *.h5.partial files were left
(issue 37)."""
import glob
import os
import resource
import shutil
import signal
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.environ.get("COSPH_BIN", os.path.join(REPO, "build", "bin"))


def limit_file_size(limit):
    def before_exec():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, resource.RLIM_INFINITY))
    return before_exec


class FullDiskKeepsFilesWhole(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="cosph_full_disk_")

    def tearDown(self):
        shutil.rmtree(self.out, ignore_errors=True)

    def run_fluid(self, limit, checkpoint_interval=-1):
        return subprocess.run(
            [os.path.join(BIN, "cosph-fluid"), "--case", os.path.join(REPO, "cases",
                                                                       "dam_break.pbtxt"),
             "--out", self.out, "--set", "run.end_time=0.1", "--set", "run.snapshot_interval=0.001",
             "--set", f"run.checkpoint_interval={checkpoint_interval}"],
            stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=600,
            preexec_fn=limit_file_size(limit), restore_signals=False)

    def assert_whole(self):
        self.assertEqual(glob.glob(os.path.join(self.out, "**", "*.partial"), recursive=True), [])
        index = os.path.join(self.out, "fluid.xdmf")
        files = ([item.text.split(":")[0]
                  for item in ElementTree.parse(index).getroot().iter("DataItem")]
                 if os.path.exists(index) else [])
        for name in set(files):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)
        with open(os.path.join(self.out, "timeseries.csv")) as f:
            text = f.read()
        self.assertTrue(text.endswith("\n"))
        columns = text.splitlines()[0].count(",")
        for line in text.splitlines()[1:]:
            self.assertEqual(line.count(","), columns, line)
            [float(v) for v in line.split(",")]

    def test_the_index_fills_first(self):
        # A snapshot of the dam break takes 181 kB, the index 2.1 kB more with
        # each: it passes the limit at about the 90th of the 100 due.
        proc = self.run_fluid(190_000)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn(f"{self.out}/fluid.xdmf: cannot write it (File too large)", proc.stderr)
        self.assert_whole()
        self.assertGreater(len(glob.glob(os.path.join(self.out, "fluid_0*.h5"))), 50)

    def test_a_checkpoint_that_does_not_fit(self):
        # A checkpoint holds every array: larger than a snapshot, past the limit.
        proc = self.run_fluid(190_000, checkpoint_interval=0.05)
        self.assertEqual(proc.returncode, 1, proc.stderr)   # not SIGSEGV at exit
        self.assertRegex(proc.stderr, rf"{self.out}/checkpoints/fluid_\d+\.h5: cannot write it "
                                      r"\(File too large\)")
        self.assert_whole()
        self.assertEqual(os.listdir(os.path.join(self.out, "checkpoints")), [])

    def test_a_snapshot_that_does_not_fit(self):
        proc = self.run_fluid(100_000)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn(f"{self.out}/fluid_000000.h5", proc.stderr)
        self.assert_whole()
        self.assertEqual(glob.glob(os.path.join(self.out, "fluid_0*.h5")), [])


if __name__ == "__main__":
    unittest.main()
