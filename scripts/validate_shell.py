#!/usr/bin/python3
"""Validates the reduced-dimension shell (cosph-solid-shell) in vacuum.

The Antoci plate alone (cases/shell_plate.pbtxt: L = 0.079 m, t = 5 mm,
E = 12 MPa, nu = 0.4, rho = 1100 kg/m^3, clamped), started with its first
bending mode, at 4, 8, 16 and 32 particles along the free length. The period
of the free end (between downward zero crossings of tip_dy, averaged over
about three periods) is compared with two references:
  - Euler-Bernoulli in plane strain (the issue's target, 1 % at 8 along),
        omega^2 = E' t^2 k^4 / (12 rho),  E' = E / (1 - nu^2),  kL = 1.8751;
  - the Timoshenko beam the shell discretises (shear correction 5/6 and
    rotary inertia), its first root found here by shooting: the limit the
    shell must converge to.
Writes docs/results/shell.md and docs/figures/shell_period.png, and each
run's wall and CPU time and |period error| against Timoshenko to
docs/results/plate_in_vacuum_shell_points.json for scripts/speed_accuracy.py.

usage: scripts/validate_shell.py [--bin DIR]
"""
import argparse
import math
import pathlib
import sys
import tempfile

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import cosph_results as cr  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "shell_plate.pbtxt"
L, T_THICK, E, NU, RHO = 0.079, 0.005, 12.0e6, 0.4, 1100.0
SHEAR_CORRECTION = 5.0 / 6.0
RESOLUTIONS = [4, 8, 16, 32]
FIRST_ROOT = 1.8751040687  # cos kL cosh kL = -1


def euler_bernoulli_period():
    k = FIRST_ROOT / L
    omega = math.sqrt(E / (1 - NU * NU) * T_THICK**2 * k**4 / (12 * RHO))
    return 2 * math.pi / omega


def beam_periods_of(youngs_modulus=None, poisson_ratio=None, length=None, thickness=None,
                    density=None):
    """(Euler-Bernoulli, Timoshenko) first periods of a clamped-free plate in plane
    strain that differs from this one in the quantities given (the rest this
    plate's)."""
    global E, NU, L, T_THICK, RHO
    kept = E, NU, L, T_THICK, RHO
    E, NU, L, T_THICK, RHO = [kept[k] if value is None else value for k, value in enumerate(
        (youngs_modulus, poisson_ratio, length, thickness, density))]
    try:
        return euler_bernoulli_period(), timoshenko_period()
    finally:
        E, NU, L, T_THICK, RHO = kept


def timoshenko_period(steps=4000):
    """First period of the clamped-free Timoshenko beam in plane strain.

    With W and Psi the amplitudes of deflection and section rotation,
        EI Psi'' + kGA (W' - Psi) + rho I omega^2 Psi = 0,
        kGA (W'' - Psi') + rho A omega^2 W = 0,
    W = Psi = 0 at the clamp, M = EI Psi' = 0 and Q = kGA (W' - Psi) = 0 at the
    free end. Two solutions from the clamp (W'(0), Psi'(0)) = (1, 0), (0, 1) are
    integrated with RK4; omega is the root of the 2x2 determinant of the free
    end's (M, Q), bracketed near Euler-Bernoulli and bisected."""
    Ep = E / (1 - NU * NU)
    G = E / (2 * (1 + NU))
    EI, kGA = Ep * T_THICK**3 / 12, SHEAR_CORRECTION * G * T_THICK
    rA, rI = RHO * T_THICK, RHO * T_THICK**3 / 12

    def end_determinant(omega):
        def rhs(y):  # y = (W, W', Psi, Psi') for both solutions, shape (4, 2)
            W, dW, Psi, dPsi = y
            return np.array([dW, dPsi - rA * omega**2 / kGA * W, dPsi,
                             -(rI * omega**2 * Psi + kGA * (dW - Psi)) / EI])
        y = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0]])
        dx = L / steps
        for _ in range(steps):
            k1 = rhs(y)
            k2 = rhs(y + 0.5 * dx * k1)
            k3 = rhs(y + 0.5 * dx * k2)
            k4 = rhs(y + dx * k3)
            y = y + dx / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        W, dW, Psi, dPsi = y
        M, Q = dPsi, dW - Psi
        return M[0] * Q[1] - M[1] * Q[0]

    omega_eb = 2 * math.pi / euler_bernoulli_period()
    low, high = 0.9 * omega_eb, 1.0001 * omega_eb
    f_low, f_high = end_determinant(low), end_determinant(high)
    if f_low * f_high > 0:
        sys.exit("the Timoshenko root is not bracketed near Euler-Bernoulli")
    for _ in range(60):
        middle = 0.5 * (low + high)
        f_middle = end_determinant(middle)
        if f_low * f_middle <= 0:
            high = middle
        else:
            low, f_low = middle, f_middle
    return 2 * math.pi / (0.5 * (low + high))


def run(binary, n, out):
    dx = L / n
    settings = [f"solid.spacing={dx!r}", f"solid.body[0].min.x={-4 * dx!r}",
                f"solid.clamp[0].min.x={-4 * dx!r}", "run.end_time=0.25",
                "run.snapshot_interval=1"]
    command = [binary, "--case", CASE, "--out", out]
    for s in settings:
        command += ["--set", s]
    wall, cpu = cr.timed_run(command, str(out))
    period, t, y = tip_period(out / "timeseries.csv", f"n = {n}")
    return period, t, y, wall, cpu


def tip_period(timeseries, name):
    """The free end's period (mean time between downward zero crossings of
    tip_dy), with the time series t and tip_dy it was read from."""
    data = np.genfromtxt(timeseries, delimiter=",", names=True)
    t, y = data["t_s"], data["tip_dy_m"]
    down = np.where((y[:-1] > 0) & (y[1:] <= 0))[0]
    crossings = t[down] + (t[down + 1] - t[down]) * y[down] / (y[down] - y[down + 1])
    if len(crossings) < 2:
        sys.exit(f"{name}: fewer than two downward crossings of tip_dy")
    return float(np.mean(np.diff(crossings))), t, y


ERROR_NAME = "plate in vacuum: |period error| vs Timoshenko (%)"


def period_point(series, label, period, T_timoshenko, wall, cpu):
    """A run of the plate in vacuum for scripts/speed_accuracy.py: its exact
    reference is the Timoshenko beam's period."""
    return {"series": f"plate in vacuum, {series}", "label": label, "wall_s": wall,
            "cpu_s": cpu, "error": 100 * abs(period / T_timoshenko - 1),
            "error_name": ERROR_NAME, "exact": True}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=str(ROOT / "build" / "bin"))
    args = parser.parse_args()
    binary = pathlib.Path(args.bin) / "cosph-solid-shell"
    T_eb, T_timoshenko = euler_bernoulli_period(), timoshenko_period()
    rows = []
    fig, ax = plt.subplots(figsize=(7, 4))
    with tempfile.TemporaryDirectory() as folder:
        for n in RESOLUTIONS:
            out = pathlib.Path(folder) / f"n{n}"
            period, t, y, wall, cpu = run(binary, n, out)
            rows.append((n, period, wall, cpu))
            ax.plot(t, y * 1000, label=f"{n} along")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("tip deflection [mm]")
    ax.set_title(f"Antoci plate in vacuum, shell; Euler-Bernoulli T = {T_eb:.4f} s")
    ax.legend()
    figure = ROOT / "docs" / "figures" / "shell_period.png"
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120, bbox_inches="tight")

    lines = ["Written by `scripts/validate_shell.py`. The Antoci plate alone "
             "(`cases/shell_plate.pbtxt`), first bending mode; the period of the free end "
             f"against Euler-Bernoulli in plane strain, T = {T_eb:.5f} s, and against the "
             f"Timoshenko beam (shear correction 5/6, rotary inertia), T = {T_timoshenko:.5f} s "
             f"({100 * (T_timoshenko / T_eb - 1):+.2f} %), the limit the shell converges to.", "",
             "| particles along L | period [s] | vs Euler-Bernoulli | vs Timoshenko "
             "| wall time [s] | CPU time [s] |",
             "|---:|---:|---:|---:|---:|---:|"]
    for n, period, wall, cpu in rows:
        lines.append(f"| {n} | {period:.5f} | {100 * (period / T_eb - 1):+.2f} % "
                     f"| {100 * (period / T_timoshenko - 1):+.2f} % | {wall:.2f} | {cpu:.2f} |")
    lines += ["", "Wall and CPU times are for one thread each on a shared two-core machine; "
              "other jobs running at the same time inflate the wall time more than the CPU time.",
              ""]
    table = ROOT / "docs" / "results" / "shell.md"
    table.write_text("\n".join(lines))
    print("\n".join(lines))
    cr.write_points("plate_in_vacuum_shell", [
        period_point("shell", f"{n} along", period, T_timoshenko, wall, cpu)
        for n, period, wall, cpu in rows])


if __name__ == "__main__":
    main()
