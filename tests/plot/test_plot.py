"""`coupler/cosph plot DIR`: the pictures of a short coupled run, of a run
that blew up, refusal of a folder that is not an output folder, a launcher
without matplotlib, and the published curves the cases name.

Run by ctest; by hand:
    COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/plot -v"""
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent.parent
LAUNCHER = REPO / "coupler" / "cosph"
sys.path.insert(0, str(REPO / "coupler"))
from cosph_launcher import cosph_output  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
TIMEOUT = float(os.environ.get("COSPH_CASE_TIMEOUT", "1500"))


def launcher(*args, env=None):
    return subprocess.run([str(LAUNCHER), *map(str, args)], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=TIMEOUT, env=env)


def run_case(case, out, *settings):
    # coupling.timeout: ctest runs other process-heavy tests beside this one.
    sets = [arg for s in ("coupling.timeout=60",) + settings for arg in ("--set", s)]
    return launcher("run", case, "--out", out, "--quiet", "--overwrite", *sets)


def png_size(path):
    """(width, height) from a PNG's IHDR chunk; fails unless it is a PNG."""
    data = Path(path).read_bytes()
    if data[:8] != PNG_SIGNATURE or data[12:16] != b"IHDR":
        raise AssertionError(f"{path} is not a PNG")
    return struct.unpack(">II", data[16:24])


def drawn_fraction(path):
    """The share of pixels that are not the white background."""
    import matplotlib.image
    pixels = matplotlib.image.imread(str(path))[:, :, :3]
    return float(np.mean(pixels.min(axis=2) < 0.9))


def index_times(folder, phase):
    """The snapshot times NAME.xdmf lists, read without the module under test."""
    text = (Path(folder) / f"{phase}.xdmf").read_text()
    return [float(t) for t in re.findall(r'<Time Value="([^"]+)"', text)]


class PictureChecks(unittest.TestCase):
    def assert_picture(self, path, min_drawn):
        width, height = png_size(path)
        self.assertGreater(min(width, height), 300, path)
        self.assertGreater(os.path.getsize(path), 15000, f"{path}: too small to hold a plot")
        self.assertGreater(drawn_fraction(path), min_drawn, f"{path}: (nearly) blank")


class PlotOfCoupledRun(PictureChecks):
    """The elastic plate for 4 ms, a snapshot every ms."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = Path(tempfile.mkdtemp(prefix="cosph_plot_"))
        cls.out = cls.tmp / "run"
        cls.run_result = run_case("elastic_plate", cls.out, "run.end_time=0.004",
                           "run.snapshot_interval=0.001", "run.output_interval=0.0005")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def setUp(self):
        result = self.run_result
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)

    def test_writes_gauges_and_four_snapshots_spread_over_the_run(self):
        result = launcher("plot", self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        plots = self.out / "plots"
        written = sorted(p.name for p in plots.iterdir())
        self.assertEqual(sorted(Path(line).name for line in result.stdout.split()), written,
                         "plot prints the path of every file it wrote")
        times = index_times(self.out, "fluid")
        self.assertEqual(len(times), 5)
        expected = {f"particles_t{times[k]:.4f}s.png" for k in (0, 1, 3, 4)}
        self.assertEqual({n for n in written if n.startswith("particles_")}, expected)
        gauges = {n for n in written if n.startswith("timeseries_")}
        for group in ("water_front", "tip", "energy", "speed", "counts"):
            self.assertIn(f"timeseries_{group}.png", gauges)
        for name in written:
            self.assert_picture(plots / name, min_drawn=0.03)

    def test_times_and_into_choose_the_snapshot_and_the_folder(self):
        into = self.tmp / "chosen"
        result = launcher("plot", self.out, "--times", "0.0021", "--into", into)
        self.assertEqual(result.returncode, 0, result.stderr)
        particles = sorted(p.name for p in into.glob("particles_*.png"))
        self.assertEqual(particles, ["particles_t0.0020s.png"])

    def test_bad_times_are_refused(self):
        result = launcher("plot", self.out, "--times", "soon")
        self.assertEqual(result.returncode, 2)
        self.assertIn("bad --times 'soon'", result.stderr)

    def test_the_case_names_columns_the_run_writes(self):
        case, case_path = cosph_output.read_case(self.out)
        references = cosph_output.read_references(case, REPO, case_path, self.out)
        series, _ = cosph_output.read_timeseries(self.out / "timeseries.csv")
        self.assertEqual(sorted(r.column for r in references), ["tip_dx", "tip_dy"])
        for reference in references:
            self.assertIn(reference.column, series)

    def test_movie_has_a_frame_per_snapshot(self):
        try:
            import PIL.Image
        except ImportError:
            self.skipTest("Pillow (python3-pil) is not installed")
        into = self.tmp / "movie"
        result = launcher("plot", self.out, "--movie", "--into", into)
        self.assertEqual(result.returncode, 0, result.stderr)
        movies = list(into.glob("movie.*"))
        self.assertEqual(len(movies), 1)
        if movies[0].suffix == ".gif":
            with PIL.Image.open(movies[0]) as movie:
                self.assertEqual(movie.n_frames, len(index_times(self.out, "fluid")))


class PlotOfRunThatBlewUp(PictureChecks):
    """The oscillating plate flung far too fast (as tests/solid's runaway
    test): cosph-solid stops and keeps solid_last_good.h5."""

    def setUp(self):
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph_plot_"))

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_draws_the_last_good_state(self):
        out = self.tmp / "run"
        run = run_case("oscillating_plate", out, "solid.spacing=0.0033333333333333", "run.cfl=1",
                       "run.end_time=0.05", "solid.initial_velocity.tip_speed=60")
        self.assertEqual(run.returncode, 1, run.stdout + run.stderr)
        self.assertTrue((out / "solid_last_good.h5").is_file())
        result = launcher("plot", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        picture = out / "plots" / "particles_last_good.png"
        self.assertIn(str(picture), result.stdout.split())
        self.assert_picture(picture, min_drawn=0.02)


class PlotRefusals(unittest.TestCase):
    def setUp(self):
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph_plot_"))

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_a_folder_that_is_not_an_output_folder(self):
        (self.tmp / "notes.txt").write_text("not a run\n")
        result = launcher("plot", self.tmp)
        self.assertEqual(result.returncode, 2)
        self.assertIn(f"{self.tmp} is not a cosph output folder", result.stderr)
        self.assertFalse((self.tmp / "plots").exists())

    def test_a_folder_that_does_not_exist(self):
        result = launcher("plot", self.tmp / "gone")
        self.assertEqual(result.returncode, 2)
        self.assertIn(f"{self.tmp / 'gone'} is not a folder", result.stderr)

    def test_without_matplotlib_plot_names_the_package_and_run_still_works(self):
        hidden = self.tmp / "hide"
        (hidden / "matplotlib").mkdir(parents=True)
        (hidden / "matplotlib" / "__init__.py").write_text("raise ImportError('hidden')\n")
        (self.tmp / "timeseries.csv").write_text("t [s],front [m]\n0,0.1\n")
        env = dict(os.environ, PYTHONPATH=str(hidden))
        result = launcher("plot", self.tmp, env=env)
        self.assertEqual(result.returncode, 2)
        self.assertIn("python3-matplotlib", result.stderr)
        self.assertEqual(launcher("run", "--help", env=env).returncode, 0)


class CaseReferences(unittest.TestCase):
    """The dam break's reference is found and read, and its scales are those
    of the case's own column: t = T sqrt(a / 2g), front = a Z."""

    def test_dam_break_reference_is_martin_and_moyce_in_seconds_and_metres(self):
        case_path = REPO / "cases" / "dam_break.pbtxt"
        case = cosph_output.parse_text_format(case_path.read_text())
        (reference,) = cosph_output.read_references(case, REPO, case_path, case_path.parent)
        self.assertEqual(reference.column, "front")
        self.assertEqual(reference.path, REPO / "validation" / "reference" /
                         "martin_moyce_n2_front.csv")
        names, data = cosph_output.read_reference_csv(reference.path)
        fluid = cosph_output.first(case, "fluid")
        a = cosph_output.first(cosph_output.first(cosph_output.first(fluid, "water"), "max"), "x")
        g = -cosph_output.first(cosph_output.first(cosph_output.first(case, "run"), "gravity"),
                                "y")
        self.assertEqual(len(reference.t), len(data["Z_z_over_a"]))
        self.assertGreaterEqual(len(reference.t), 10)
        np.testing.assert_allclose(reference.t, np.array(data["T_t_sqrt_2g_over_a"]) *
                                   math.sqrt(a / (2 * g)), rtol=1e-5)
        np.testing.assert_allclose(reference.value, np.array(data["Z_z_over_a"]) * a, rtol=1e-12)

    def test_every_case_reference_resolves(self):
        for case_path in sorted((REPO / "cases").glob("*.pbtxt")):
            case = cosph_output.parse_text_format(case_path.read_text())
            for reference in cosph_output.read_references(case, REPO, case_path, case_path.parent):
                self.assertGreater(len(reference.t), 5, f"{case_path.name}: {reference.path}")
                self.assertTrue(all(math.isfinite(v) for v in reference.t + reference.value))


if __name__ == "__main__":
    unittest.main()
