#!/usr/bin/python3
"""Conformance suite for a cosph solid executable.

Any solid model that takes part in a coupled cosph run must pass it:

    /usr/bin/python3 tests/conformance/solid_conformance.py --solid PATH/TO/SOLID-EXE \
        [--model NAME] [--bin DIR] [unittest options, e.g. -v or a test name]

--bin is the folder holding cosph-case, cosph-coupler and cosph-dummy
(default: the folder of --solid, then build/bin). --model is written as solid.model into
the cases (default: "jaumann" for cosph-solid-jaumann, "total_lagrangian" for
cosph-solid-tl, "shell" for cosph-solid-shell, otherwise the field is left out).
--thin runs the bodies as thin plates, for a solid of thin bodies only
(reduced-dimension: one line of particles on the mid-line; default for
solid.model "shell"): the free bar 5 mm thick and standing 40 mm tall, the
cantilever 5 mm thick and 8 times stiffer (the same deflection). Such a solid
has round(length / spacing) + 1 particles along its mid-line and presents its
section filled with interface particles, round(thickness / spacing) across for
each (as a continuum body of that spacing would).

The solid under test runs against cosph-coupler and a cosph-dummy fluid: a
block of particles left of x = 0 with a prescribed uniform stress -P I and no
physics. Every run is tiny (a few hundred particles, seconds). Every case
written here names the solid in solid.executable (its absolute path), as a
user's case names a solid model of their own (Plan checks that the launcher
would start this solid for such a case), and the solid is started as the
launcher starts it:
    SOLID --case CASE --out DIR --endpoint ipc://DIR/coupler.sock
It must read the fields of the case files written here (proto/case.proto):
run.end_time, output_interval, snapshot_interval, threads; solid.model,
spacing, density, youngs_modulus, poisson_ratio, body, clamp, tip_gauge;
coupling.timeout; and accept solid.executable (the launcher's field).

What is checked (docs/coupling.md, "A solid model of your own" explains why):
  Plan           cosph-case plan, asked which programs a case naming the solid
                 in solid.executable needs, answers with this solid.
  BadInput       a bad solid parameter is refused naming the case file and the
                 field; with no coupler the solid gives up with a message that
                 names the coupler, within coupling.timeout plus a grace.
  PushedFreeBar  a free bar pushed by the dummy's pressure: all three processes
                 exit 0 at end_time; the interface is well formed (both sides
                 send particles, only those the coupler asked for, the forces
                 cancel); tip gauges with units; snapshots ParaView can open;
                 the bar's centre of mass moves as the impulse the coupler
                 delivered says it must.
  Cantilever     a clamped cantilever loaded by the dummy's pressure on one
                 face: the mean tip deflection over the first oscillation
                 against Timoshenko beam theory.
  PeerDies       the dummy fluid is killed mid-run: the solid exits non-zero
                 within the timeout plus a few seconds, leaving no process.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# Filled in by main() from the command line.
SOLID = None   # the executable under test
MODEL = None   # solid.model, or None to leave the field out
THIN = False   # --thin: the bodies as thin plates
BIN = None     # folder with cosph-coupler and cosph-dummy

DX = 0.0025          # m, particle spacing of both the solid and the dummy fluid
PRESSURE = 1000.0    # Pa, the dummy fluid's prescribed pressure
DENSITY = 1100.0     # kg/m^3
POISSON = 0.3
# The Participant of cosph waits timeout + max(1 s, timeout/4) so that the
# coupler, which knows who is missing, reports first; a solid of another make
# may wait differently but must give up within this much more.
GRACE_S = 5.0
# How long a coupled run may take to finish. Release builds need seconds; a
# sanitizer build is tens of times slower, hence the generous default.
FINISH_S = float(os.environ.get("COSPH_CONFORMANCE_FINISH_S", "600"))


# --------------------------------------------------------------------------
# Case files and processes

def case_text(body, clamp=None, tip=None, youngs_modulus=1e6, poisson=POISSON, end_time=0.01,
              output_interval=1e-9, snapshot_interval=None, timeout=2.0, dx=DX):
    """A coupled case: the dummy fluid needs only its section to exist (it
    reads nothing from the case), the coupler reads run and coupling."""
    box = "{ min { x: %r y: %r } max { x: %r y: %r } }"
    model = f'  model: "{MODEL}"\n' if MODEL else ""
    lines = [
        "title: \"solid conformance\"",
        f"run {{ end_time: {end_time!r} output_interval: {output_interval!r} "
        f"snapshot_interval: {(snapshot_interval or end_time)!r} threads: 1 }}",
        "fluid { spacing: %r density: 1000 }" % dx,
        "solid {",
        model.rstrip("\n"),
        f"  executable: {json.dumps(SOLID)}",
        f"  spacing: {dx!r} density: {DENSITY!r}",
        f"  youngs_modulus: {youngs_modulus!r} poisson_ratio: {poisson!r}",
        "  body " + box % body,
    ]
    if clamp:
        lines.append("  clamp " + box % clamp)
    if tip:
        lines.append("  tip_gauge { x: %r y: %r }" % tip)
    lines += ["}", f"coupling {{ timeout: {timeout!r} }}", ""]
    return "\n".join(line for line in lines if line)


class Process:
    """A child in its own process group, its output in files of the run folder."""

    def __init__(self, name, argv, folder):
        self.name = name
        self.argv = argv
        self.out_path = os.path.join(folder, name + ".out")
        self.err_path = os.path.join(folder, name + ".err")
        with open(self.out_path, "w") as out, open(self.err_path, "w") as err:
            self.proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                                         start_new_session=True)
        self.pid = self.proc.pid

    def wait(self, seconds):
        """The exit code, or None if still running after `seconds`."""
        try:
            return self.proc.wait(timeout=seconds)
        except subprocess.TimeoutExpired:
            return None

    def stop(self):
        """Ends this child and its group if still there (test teardown only)."""
        if self.proc.poll() is None:
            try:
                os.killpg(self.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self.proc.wait()
        else:
            try:
                os.killpg(self.pid, signal.SIGKILL)   # anything it left in its group
            except ProcessLookupError:
                pass

    def group_alive(self):
        """Whether any process of this child's group (itself or what it started) is left."""
        try:
            os.killpg(self.pid, 0)
            return True
        except ProcessLookupError:
            return False
        except PermissionError:
            return True

    def err(self):
        with open(self.err_path, errors="replace") as f:
            return f.read()

    def log(self):
        with open(self.out_path, errors="replace") as f:
            text = f.read()
        return f"--- {self.name}: {' '.join(self.argv)}\n{text}{self.err()}"


class CoupledRun:
    """cosph-coupler + a cosph-dummy fluid + the solid under test, over ipc://."""

    def __init__(self, prefix, case, fluid_particles, dx=DX, fluid_extra=()):
        self.dir = tempfile.mkdtemp(prefix=f"cosph_conf_{prefix}_")
        self.out = os.path.join(self.dir, "out")
        self.case = os.path.join(self.dir, "case.pbtxt")
        with open(self.case, "w") as f:
            f.write(case)
        timeout = float(re.search(r"timeout: ([0-9.e+-]+)", case).group(1))
        endpoint = "ipc://" + os.path.join(self.dir, "coupler.sock")
        common = ["--case", self.case, "--out", self.out, "--endpoint", endpoint]
        self.coupler = Process("coupler", [os.path.join(BIN, "cosph-coupler")] + common, self.dir)
        self.fluid = Process("fluid", [
            os.path.join(BIN, "cosph-dummy"), "--phase", "fluid", "--endpoint", endpoint,
            "--out", self.out, "--timeout", repr(timeout), "--particles", str(fluid_particles),
            "--spacing", repr(dx), "--stress", repr(PRESSURE), "--dt", "1"] + list(fluid_extra),
            self.dir)
        self.solid = Process("solid", [SOLID] + common, self.dir)
        self.processes = [self.coupler, self.fluid, self.solid]
        self.started = time.monotonic()

    def wait_all(self, seconds):
        deadline = time.monotonic() + seconds
        codes = [p.wait(max(0.0, deadline - time.monotonic())) for p in self.processes]
        self.seconds = time.monotonic() - self.started
        return codes

    def logs(self):
        return "\n".join(p.log() for p in self.processes)

    def close(self):
        for p in self.processes:
            p.stop()
        if not os.environ.get("COSPH_KEEP_CONFORMANCE"):
            shutil.rmtree(self.dir, ignore_errors=True)


def read_csv(path):
    """Columns by name (the " [unit]" cut off), and the units."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    names = [h.split(" [")[0] for h in header]
    units = {h.split(" [")[0]: (h.split(" [")[1].rstrip("]") if " [" in h else None)
             for h in header}
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}, units


def snapshots(out, name="solid"):
    """The snapshot files an xdmf index names, in order."""
    with open(os.path.join(out, f"{name}.xdmf")) as f:
        text = f.read()
    files = []
    for h5 in re.findall(r"([A-Za-z0-9_.-]+\.h5):/position", text):
        if h5 not in files:
            files.append(h5)
    return [os.path.join(out, h5) for h5 in files]


def read_snapshot(path):
    import h5py
    with h5py.File(path, "r") as f:
        data = {key: np.array(f[key]) for key in f.keys()}
        data["time"] = float(f.attrs["time"]) if "time" in f.attrs else float(
            f["position"].attrs["time"])
    return data


def solid_particles(box, dx=DX):
    """How many particles the solid has for a body box: a lattice, or with
    --thin one line along the box's long side, a particle on each end."""
    if THIN:
        (x0, y0, x1, y1) = box
        return int(round(max(x1 - x0, y1 - y0) / dx)) + 1
    return len(lattice(box, dx))


def interface_particles(box, dx=DX):
    """How many interface particles the whole body presents: with --thin, the
    section filled, round(thickness / spacing) across each mid-line particle."""
    (x0, y0, x1, y1) = box
    across = max(1, int(round(min(x1 - x0, y1 - y0) / dx))) if THIN else 1
    return across * solid_particles(box, dx)


def lattice(box, dx=DX):
    """Particle centres of a box filled on the square lattice (half a spacing inside)."""
    (x0, y0, x1, y1) = box
    nx, ny = int(round((x1 - x0) / dx)), int(round((y1 - y0) / dx))
    xs = x0 + (np.arange(nx) + 0.5) * dx
    ys = y0 + (np.arange(ny) + 0.5) * dx
    return np.array([(x, y) for x in xs for y in ys])


# --------------------------------------------------------------------------

def planned_programs(case_path):
    """What `cosph-case plan` answers for a case: the programs the launcher starts."""
    result = subprocess.run([os.path.join(BIN, "cosph-case"), "plan", case_path],
                            capture_output=True, text=True, timeout=30)
    return result.returncode, result.stdout.splitlines(), result.stderr


class Plan(unittest.TestCase):
    """coupler/cosph starts the program cosph-case plans. A case that names
    the solid in solid.executable must get exactly this solid, whatever its
    solid.model: no edit of cosph is needed to run it."""

    def test_the_launcher_plans_this_solid_for_a_case_naming_it(self):
        folder = tempfile.mkdtemp(prefix="cosph_conf_plan_")
        try:
            path = os.path.join(folder, "case.pbtxt")
            with open(path, "w") as f:
                f.write(case_text((0, 0, 0.02, 0.02)).replace(
                    "fluid { spacing: %r density: 1000 }\n" % DX, ""))   # the solid alone
            code, programs, err = planned_programs(path)
            self.assertEqual(code, 0, err)
            self.assertEqual(programs, [SOLID], "cosph-case plan would start another program")
            print(f"\n  cosph-case plan: {programs[0]}", file=sys.stderr)
        finally:
            shutil.rmtree(folder, ignore_errors=True)


class BadInput(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="cosph_conf_bad_")
        self.processes = []

    def tearDown(self):
        for p in self.processes:
            p.stop()
        shutil.rmtree(self.dir, ignore_errors=True)

    def start_solid(self, case):
        path = os.path.join(self.dir, "case.pbtxt")
        with open(path, "w") as f:
            f.write(case)
        p = Process("solid", [SOLID, "--case", path, "--out", os.path.join(self.dir, "out"),
                              "--endpoint", "ipc://" + os.path.join(self.dir, "nobody.sock")],
                    self.dir)
        self.processes.append(p)
        return path, p

    def test_bad_parameter_is_refused_naming_file_and_field(self):
        path, solid = self.start_solid(case_text((0, 0, 0.02, 0.01), poisson=0.6))
        start = time.monotonic()
        code = solid.wait(5.0)
        self.assertIsNotNone(code, "the solid did not refuse poisson_ratio 0.6 within 5 s")
        self.assertNotEqual(code, 0, solid.log())
        message = solid.log()
        self.assertIn(path, message, "the message must name the case file")
        self.assertIn("poisson_ratio", message, "the message must name the field")
        print(f"\n  bad parameter refused in {time.monotonic() - start:.2f} s: "
              f"{solid.err().strip().splitlines()[-1]}", file=sys.stderr)

    def test_gives_up_when_no_coupler_answers(self):
        timeout = 1.0
        _, solid = self.start_solid(case_text(PushedFreeBar.BAR, timeout=timeout))
        start = time.monotonic()
        code = solid.wait(timeout + GRACE_S)
        elapsed = time.monotonic() - start
        self.assertIsNotNone(code, f"the solid still waits {timeout + GRACE_S} s after starting "
                                   f"with coupling.timeout {timeout} s and no coupler")
        self.assertNotEqual(code, 0, solid.log())
        self.assertRegex(solid.err(), re.compile("coupler", re.IGNORECASE),
                         "the message must say that the coupler did not answer")
        self.assertFalse(solid.group_alive(), "the solid left a process behind")
        print(f"\n  no coupler: gave up after {elapsed:.2f} s: "
              f"{solid.err().strip().splitlines()[-1]}", file=sys.stderr)


class PushedFreeBar(unittest.TestCase):
    """A free bar (no clamp, no gravity) right of x = 0, pushed in +x by the
    dummy fluid's pressure P. Whatever the solid's own forces do inside the
    bar, they cannot move its centre of mass: only the accelerations the
    coupler sends can, so the centre of mass must move exactly as the force
    the coupler records (coupling.csv, every step) integrated twice says."""

    THICK_BAR = (0.0, 0.0, 0.02, 0.02)   # m: 8 x 8 particles
    # m: 2 spacings thick, standing out of the fluid above and below (not all is
    # sent; the push is symmetric in y).
    THIN_BAR = (0.0, -0.01, 0.005, 0.03)
    FLUID_HEIGHT = 0.02            # m
    BAR = THICK_BAR                # main() sets THIN_BAR with --thin
    FLUID_PARTICLES = 64           # 8 x 8, x in [-0.02, 0], y in [0, 0.02]
    END_TIME = 0.01                # s: about 430 steps; the bar moves about 1.8 mm
    TOLERANCE = 0.01               # relative, on the centre of mass's velocity and displacement

    @classmethod
    def setUpClass(cls):
        case = case_text(cls.BAR, tip=(cls.BAR[2], 0.5 * cls.FLUID_HEIGHT), end_time=cls.END_TIME, timeout=2.0)
        cls.coupled = CoupledRun("bar", case, cls.FLUID_PARTICLES)
        cls.codes = cls.coupled.wait_all(FINISH_S)
        print(f"\n  pushed free bar: exit codes {cls.codes} in {cls.coupled.seconds:.1f} s",
              file=sys.stderr)

    @classmethod
    def tearDownClass(cls):
        cls.coupled.close()

    def setUp(self):
        self.assertEqual(self.codes, [0, 0, 0], self.coupled.logs())

    def test_handshake_and_run_to_end_time(self):
        series, _ = read_csv(os.path.join(self.coupled.out, "timeseries.csv"))
        self.assertAlmostEqual(series["t"][-1], self.END_TIME, delta=1e-9 * self.END_TIME)
        self.assertGreater(len(series["t"]), 10)
        for p in self.coupled.processes:
            self.assertFalse(p.group_alive(), f"{p.name} (pid {p.pid}) left a process behind")

    def test_interface_is_well_formed(self):
        c, _ = read_csv(os.path.join(self.coupled.out, "coupling.csv"))
        n_solid = interface_particles(self.BAR)
        sent = c["solid_interface_particles"]
        self.assertTrue(np.all(sent > 0), "the solid sent no interface particles")
        # The coupler asks for the particles near the fluid (its bounds grown by
        # about 3 h): the 8-particle-long bar must not be sent whole.
        self.assertTrue(np.all(sent < n_solid),
                        f"the solid sent {sent.max():.0f} of its {n_solid} particles: it must "
                        f"send only those inside CouplingStep.send_region")
        self.assertTrue(np.all(c["fluid_interface_particles"] > 0))
        self.assertTrue(np.all(c["pairs"] > 0), "no fluid-solid pair found at some step")
        for axis in "xy":
            fluid, solid = c[f"force_on_fluid_{axis}"], c[f"force_on_solid_{axis}"]
            scale = np.max(np.abs(c["force_on_fluid_x"]))
            self.assertLess(np.max(np.abs(fluid + solid)) / scale, 1e-8,
                            f"cross-phase forces in {axis} do not cancel")
        self.assertTrue(np.all(c["force_on_solid_x"] > 0), "the fluid must push the bar in +x")
        print(f"\n  interface: {sent.min():.0f}-{sent.max():.0f} of {n_solid} solid particles "
              f"sent, {c['pairs'].min():.0f}-{c['pairs'].max():.0f} pairs, force on the bar "
              f"{c['force_on_solid_x'][0]:.2f} N/m at t = 0 (P H = "
              f"{PRESSURE * self.FLUID_HEIGHT:.2f} N/m)", file=sys.stderr)

    def test_tip_gauges_with_units(self):
        _, units = read_csv(os.path.join(self.coupled.out, "timeseries.csv"))
        for gauge in ("tip_dx", "tip_dy"):
            self.assertIn(gauge, units, f"timeseries.csv has no {gauge} column: the solid "
                                        f"must send a gauge named {gauge}")
            self.assertEqual(units[gauge], "m", f"unit of {gauge}")

    def test_snapshots_written_at_start_and_end(self):
        index = os.path.join(self.coupled.out, "solid.xdmf")
        self.assertTrue(os.path.isfile(index), "no solid.xdmf")
        files = snapshots(self.coupled.out)
        self.assertGreaterEqual(len(files), 2, "want a snapshot at t = 0 and one at end_time")
        for path in files:
            self.assertTrue(os.path.isfile(path), f"solid.xdmf names {path}, which is missing")
        first, last = read_snapshot(files[0]), read_snapshot(files[-1])
        self.assertAlmostEqual(first["time"], 0.0, delta=1e-12)
        self.assertAlmostEqual(last["time"], self.END_TIME, delta=1e-9 * self.END_TIME)
        self.assertEqual(last["position"].shape[0], solid_particles(self.BAR))
        self.assertTrue(np.all(np.isfinite(last["position"])))

    def test_centre_of_mass_moves_by_the_delivered_impulse(self):
        c, _ = read_csv(os.path.join(self.coupled.out, "coupling.csv"))
        F, dt = c["force_on_solid_x"], c["dt"]
        # The coupler applies the force of the state at t_k over the step that
        # follows; kick-drift-kick (half of it before the drift, half after)
        # gives the centre of mass this velocity and displacement. Another
        # consistent integrator differs by O(dt / end_time), about 0.2 % here.
        x0, y0, x1, y1 = self.BAR
        M = DENSITY * (x1 - x0) * (y1 - y0)
        v = x = 0.0
        for k in range(len(F) - 1):
            v_half = v + 0.5 * F[k] * dt[k] / M
            x += v_half * dt[k]
            v = v_half + 0.5 * F[k + 1] * dt[k] / M
        files = snapshots(self.coupled.out)
        first, last = read_snapshot(files[0]), read_snapshot(files[-1])
        m = last.get("mass", np.ones(len(last["position"])))
        centre = lambda snap: np.average(snap["position"][:, :2], axis=0, weights=m)
        moved = centre(last) - centre(first)
        error_x = moved[0] / x - 1.0
        report = (f"centre of mass moved {moved[0] * 1e3:.6f} mm, the impulse says "
                  f"{x * 1e3:.6f} mm (error {100 * error_x:+.2e} %)")
        if "velocity" in last:
            velocity = np.average(last["velocity"][:, :2], axis=0, weights=m)
            error_v = velocity[0] / v - 1.0
            report += (f"; velocity {velocity[0]:.6f} m/s, impulse / M = {v:.6f} m/s "
                       f"(error {100 * error_v:+.2e} %)")
            self.assertLess(abs(error_v), self.TOLERANCE, report)
        print("\n  " + report, file=sys.stderr)
        self.assertLess(abs(error_x), self.TOLERANCE, report)
        self.assertLess(abs(moved[1]), self.TOLERANCE * abs(moved[0]),
                        f"a push in x moved the centre of mass by {moved[1]:.3g} m in y")


class Cantilever(unittest.TestCase):
    """A cantilever standing on a clamp at y < 0, 10 mm thick (8 particles),
    its free length L = 50 mm loaded on its left face by the dummy fluid's
    pressure P. The load comes on at once, so the tip swings about the static
    deflection: the mean tip_dx over the first swing (up to twice the time of
    the first peak) is compared with Timoshenko beam theory for a uniform
    load q = P per unit length, in plane strain (E' = E / (1 - nu^2)):
        delta = q L^4 / (8 E' I) + q L^2 / (2 kappa G t),  I = t^3 / 12, kappa = 5/6.
    E = 100 MPa keeps delta (about 0.09 mm) small against the 1.25 mm gap to
    the fluid, whose push falls off as the beam moves away (the coupler's
    force on the beam drops about 4 % over the swing)."""

    DX = 0.00125                  # m
    L, T = 0.05, 0.01             # m: free length, thickness
    CLAMP = 0.0075                # m: clamped depth below y = 0 (6 rows)
    E = 1e8                       # Pa
    THIN_T, THIN_E = 0.005, 8e8   # m, Pa: with --thin (main() sets them), the same E' T^3
    END_TIME = 0.006              # s: 1.2 periods of the first bending mode
    TOLERANCE = 0.15              # relative, on the mean tip deflection

    @classmethod
    def setUpClass(cls):
        L, T, C = cls.L, cls.T, cls.CLAMP
        case = case_text((0.0, -C, T, L), clamp=(-cls.DX, -C, T + cls.DX, 0.0), tip=(T / 2, L),
                         youngs_modulus=cls.E, end_time=cls.END_TIME, dx=cls.DX, timeout=2.0)
        rows = int(round(L / cls.DX))   # the dummy fluid covers the free length, 0 <= y <= L
        cls.coupled = CoupledRun("cantilever", case, rows * rows, dx=cls.DX)
        cls.codes = cls.coupled.wait_all(FINISH_S)
        print(f"\n  cantilever: exit codes {cls.codes} in {cls.coupled.seconds:.1f} s", file=sys.stderr)

    @classmethod
    def tearDownClass(cls):
        cls.coupled.close()

    def test_mean_tip_deflection_matches_beam_theory(self):
        self.assertEqual(self.codes, [0, 0, 0], self.coupled.logs())
        series, _ = read_csv(os.path.join(self.coupled.out, "timeseries.csv"))
        t, tip = series["t"], series["tip_dx"]
        nu, E, L, T = POISSON, self.E, self.L, self.T
        E_plane = E / (1.0 - nu ** 2)
        G = E / (2.0 * (1.0 + nu))
        bending = PRESSURE * L ** 4 / (8.0 * E_plane * T ** 3 / 12.0)
        shear = PRESSURE * L ** 2 / (2.0 * 5.0 / 6.0 * G * T)
        expected = bending + shear
        peak = int(np.argmax(tip))
        swing = t <= 2.0 * t[peak]
        self.assertLess(2.0 * t[peak], t[-1],
                        f"the tip had not swung back by end_time (first peak at "
                        f"{t[peak] * 1e3:.2f} ms): the beam is far too soft")
        mean = np.trapz(tip[swing], t[swing]) / t[swing][-1]
        error = mean / expected - 1.0
        print(f"\n  cantilever: mean tip deflection {mean * 1e6:.2f} um over the first swing "
              f"({2e3 * t[peak]:.2f} ms), Timoshenko {expected * 1e6:.2f} um "
              f"(bending {bending * 1e6:.2f}): error {100 * error:+.1f} %, "
              f"half the first peak {100 * (tip[peak] / 2 / expected - 1):+.1f} %",
              file=sys.stderr)
        self.assertLess(abs(error), self.TOLERANCE)


class PeerDies(unittest.TestCase):
    """The dummy fluid is killed (SIGKILL) mid-run: the solid must stop with an
    error, not hang, within the coupling timeout and a grace, and leave no
    process of its own behind."""

    TIMEOUT = 1.0   # s, coupling.timeout

    def test_solid_exits_non_zero_when_the_fluid_is_killed(self):
        case = case_text(PushedFreeBar.BAR, tip=(PushedFreeBar.BAR[2], 0.01), end_time=10.0, timeout=self.TIMEOUT,
                         output_interval=1e-4, snapshot_interval=10.0)
        run = CoupledRun("peer_dies", case, PushedFreeBar.FLUID_PARTICLES)
        try:
            coupling_csv = os.path.join(run.out, "coupling.csv")
            deadline = time.monotonic() + min(FINISH_S, 120.0)
            while time.monotonic() < deadline:   # until the run is under way
                if os.path.exists(coupling_csv):
                    with open(coupling_csv) as f:
                        if sum(1 for _ in f) > 5:
                            break
                self.assertIsNone(run.solid.proc.poll(), run.logs())
                time.sleep(0.05)
            else:
                self.fail("the coupled run did not get going\n" + run.logs())
            os.kill(run.fluid.pid, signal.SIGKILL)
            killed = time.monotonic()
            code = run.solid.wait(self.TIMEOUT + GRACE_S)
            elapsed = time.monotonic() - killed
            self.assertIsNotNone(code, f"the solid still runs {self.TIMEOUT + GRACE_S} s after "
                                       f"the fluid died\n" + run.logs())
            self.assertNotEqual(code, 0, run.logs())
            self.assertTrue(run.solid.err().strip(), "the solid stopped without a message")
            self.assertFalse(run.solid.group_alive(),
                             f"a process of the solid's group (pid {run.solid.pid}) is left")
            self.assertNotEqual(run.coupler.wait(GRACE_S), 0, run.logs())
            print(f"\n  fluid killed: the solid exited {code} after {elapsed:.2f} s: "
                  f"{run.solid.err().strip().splitlines()[-1]}", file=sys.stderr)
        finally:
            run.close()


def default_model(solid):
    return {"cosph-solid-jaumann": "jaumann", "cosph-solid-tl": "total_lagrangian",
            "cosph-solid-shell": "shell"}.get(os.path.basename(solid))


def main():
    global SOLID, MODEL, BIN, THIN
    parser = argparse.ArgumentParser(
        description="Conformance suite for a cosph solid executable.",
        epilog="Other arguments go to unittest (e.g. -v, PushedFreeBar).")
    parser.add_argument("--solid", required=True, help="the solid executable under test")
    parser.add_argument("--model", help="solid.model to write into the cases "
                                        "(default: from the executable's name, else left out)")
    parser.add_argument("--bin", help="folder with cosph-case, cosph-coupler and cosph-dummy "
                                      "(default: the solid's folder, else build/bin)")
    parser.add_argument("--thin", action="store_true",
                        help="run the bodies as thin plates (default for solid.model shell)")
    args, rest = parser.parse_known_args()
    SOLID = os.path.abspath(args.solid)
    if not (os.path.isfile(SOLID) and os.access(SOLID, os.X_OK)):
        parser.error(f"--solid {args.solid}: not an executable file")
    MODEL = args.model if args.model is not None else default_model(SOLID)
    THIN = args.thin or MODEL == "shell"
    if THIN:
        PushedFreeBar.BAR = PushedFreeBar.THIN_BAR
        Cantilever.T, Cantilever.E = Cantilever.THIN_T, Cantilever.THIN_E
    candidates = [args.bin] if args.bin else [os.path.dirname(SOLID),
                                              os.path.join(REPO, "build", "bin")]
    for folder in candidates:
        if all(os.access(os.path.join(folder, exe), os.X_OK)
               for exe in ("cosph-case", "cosph-coupler", "cosph-dummy")):
            BIN = os.path.abspath(folder)
            break
    else:
        parser.error(f"no cosph-case, cosph-coupler and cosph-dummy in {', '.join(candidates)} "
                     f"(give --bin)")
    print(f"solid under test: {SOLID} (solid.model: {MODEL or 'not set'}"
          f"{', thin bodies' if THIN else ''}), coupler and dummy from {BIN}", file=sys.stderr)
    unittest.main(argv=[sys.argv[0]] + rest)


if __name__ == "__main__":
    main()
