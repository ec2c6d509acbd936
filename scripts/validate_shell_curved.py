#!/usr/bin/python3
"""Validates the shell (cosph-solid-shell) on a curved mid-line: a quarter
circle under a dead end load, from small to large deflection.

The plate of cases/shell_curved.pbtxt: a quarter circle of radius R = 0.1 m,
t = 5 mm (R / t = 20), clamped at one end (heading +x at the origin, curving
up round the centre (0, R) to its free end at (R, R)), E = 10 MPa, nu = 0.3,
plane strain, under a dead downward end load F = alpha EI / R^2 ramped slowly;
the free end's displacement, averaged over the last 0.5 s of the run, is
compared with
  - the exact large-deflection shape of a curved rod (Kirchhoff: inextensible,
    no shear): theta' = 1 / R + M / EI along the arc, M(s) = (x_B - x(s)) x F
    with x_B the loaded end, integrated by RK4 from the free end (M = 0) to the
    clamp and shot on the free end's angle until the clamp's angle is 0;
  - linear theory (Castigliano on bending, stretching and shear energy;
    tests/solid/shell/test_shell.cpp has the same formula):
    u = R F ((R^2 / 2) / EI - 1 / (2 EA) + 1 / (2 GA),
             -(R^2 (3 pi / 4 - 2) / EI + pi / (4 EA) + pi / (4 GA))).
The rod leaves out stretching and shear, of relative size (t / R)^2 / 12 =
2e-4 here. Linear theory breaks as the deflection grows: the load's lever
arms change with the shape at first order in u / R.
Writes docs/results/shell_curved.md and docs/figures/shell_curved.png.

usage: scripts/validate_shell_curved.py [--bin DIR]
"""
import argparse
import math
import pathlib
import tempfile

import numpy as np
import matplotlib

import cosph_results as cr

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "shell_curved.pbtxt"
R, T_THICK, E, NU = 0.1, 0.005, 10.0e6, 0.3
E_PLANE = E / (1 - NU * NU)
EI, EA = E_PLANE * T_THICK**3 / 12, E_PLANE * T_THICK
GA = 5.0 / 6.0 * E / (2 * (1 + NU)) * T_THICK
ARC = 0.5 * math.pi * R
RAMP, END, AVERAGE = 1.1, 1.6, 0.5  # s: load ramp, run's end, averaging window
LOADS = [0.02, 0.2, 0.5, 1.0, 2.0]  # alpha = F R^2 / EI
RESOLUTIONS = [16, 32]  # particles along the arc (the case: about 16)
TARGET = 2.0  # %, as the elastica's


def rod(alpha, steps=400):
    """The free end's displacement (x, y) / R of the curved Kirchhoff rod."""
    Fx, Fy = 0.0, -alpha * EI / R**2

    def rhs(px, py, theta):  # position relative to the free end, tangent angle
        moment = -(px * Fy - py * Fx)  # (x_B - x) x F with x_B - x = -p
        return math.cos(theta), math.sin(theta), 1 / R + moment / EI

    def clamp_state(theta_end):
        state, h = (0.0, 0.0, theta_end), -ARC / steps
        for _ in range(steps):
            k1 = rhs(*state)
            k2 = rhs(*(q + 0.5 * h * k for q, k in zip(state, k1)))
            k3 = rhs(*(q + 0.5 * h * k for q, k in zip(state, k2)))
            k4 = rhs(*(q + h * k for q, k in zip(state, k3)))
            state = tuple(q + h / 6 * (a + 2 * b + 2 * c + d)
                          for q, a, b, c, d in zip(state, k1, k2, k3, k4))
        return state

    # The clamp's angle grows with the free end's: bisection on the latter,
    # from straight down past the unloaded pi / 2 to beyond it.
    low, high = -math.pi, math.pi / 2 + 0.01
    for _ in range(50):
        middle = 0.5 * (low + high)
        if clamp_state(middle)[2] < 0.0:
            low = middle
        else:
            high = middle
    px, py, _ = clamp_state(0.5 * (low + high))
    # The clamp is at the origin: the free end is at -p, at rest at (R, R).
    return np.array([-px - R, -py - R]) / R


def linear(alpha):
    """Castigliano's displacement (x, y) / R under (0, -alpha EI / R^2)."""
    F = alpha * EI / R**2
    x = -R * F * (-(R * R / 2) / EI + 0.5 / EA - 0.5 / GA)
    y = -R * F * (R * R * (3 * math.pi / 4 - 2) / EI + math.pi / 4 / EA + math.pi / 4 / GA)
    return np.array([x, y]) / R


def run(binary, n, alpha, out):
    ds = ARC / n
    settings = [f"solid.spacing={ds!r}", f"solid.body[0].band.point[0].x={-4 * ds!r}",
                f"solid.clamp[0].min.x={-5 * ds!r}", f"solid.clamp[0].max.x={0.25 * ds!r}",
                f"solid.end_load.force.y={-alpha * EI / R**2!r}",
                f"solid.end_load.ramp_time={RAMP!r}", "run.snapshot_interval=10"]
    return np.array(cr.shell_alone_means(binary, CASE, settings, out, END, AVERAGE,
                                         ["tip_dx", "tip_dy"])) / R


def error(value, exact):
    """The displacement's error as a percentage of the exact displacement's size."""
    return 100 * float(np.linalg.norm(value - exact) / np.linalg.norm(exact))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=str(ROOT / "build" / "bin"))
    args = parser.parse_args()
    binary = pathlib.Path(args.bin) / "cosph-solid-shell"
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for n in RESOLUTIONS:
            for alpha in LOADS:
                exact, straight_line = rod(alpha), linear(alpha)
                shell = run(binary, n, alpha, pathlib.Path(folder) / f"n{n}_a{alpha}")
                rows.append((n, alpha, exact, straight_line, shell))
    worst = max(error(shell, exact) for n, _, exact, _, shell in rows if n == RESOLUTIONS[-1])

    fig, ax = plt.subplots(figsize=(7, 4))
    alphas = np.linspace(0.0, max(LOADS), 21)[1:]
    curves = np.array([rod(a) for a in alphas])
    lines = np.array([linear(a) for a in alphas])
    for q, name in enumerate(["horizontal u_x / R", "vertical -u_y / R"]):
        sign = 1 if q == 0 else -1
        line, = ax.plot(alphas, sign * curves[:, q], label=f"{name}, curved rod (exact)")
        ax.plot(alphas, sign * lines[:, q], "--", color=line.get_color(),
                label=f"{name}, linear theory")
        for n, marker in zip(RESOLUTIONS, "os"):
            points = [(a, sign * sh[q]) for m, a, _, _, sh in rows if m == n]
            ax.plot(*zip(*points), marker, color=line.get_color(), fillstyle="none",
                    label=f"shell, {n} along the arc" if q == 0 else None)
    ax.set_xlabel("load alpha = F R^2 / EI")
    ax.set_title("Quarter-circle cantilever under a dead end load")
    ax.legend(fontsize=8)
    fig.savefig(pathlib.Path(cr.FIGURES) / "shell_curved.png", dpi=120, bbox_inches="tight")

    text = ["Written by `scripts/validate_shell_curved.py`. A quarter-circle cantilever shell "
            "(`cases/shell_curved.pbtxt`, R / t = 20) under a dead downward end load "
            "F = alpha EI / R^2 ramped over 1.1 s, the free end averaged over the last 0.5 s, "
            "against the curved rod's exact large-deflection shape (computed by the script) "
            "and linear theory (Castigliano). Errors are of the displacement vector, as a "
            "percentage of the exact displacement's size. Largest error at "
            f"{RESOLUTIONS[-1]} along the arc: {worst:.2f} % (target, as the elastica's: "
            f"{TARGET:.0f} %).", "",
            "| particles along the arc | alpha | u / R, exact | shell | error | "
            "linear theory | its error |",
            "|---:|---:|---:|---:|---:|---:|---:|"]

    def pair(u):
        return f"({u[0]:+.4f}, {u[1]:+.4f})"

    for n, alpha, exact, straight_line, shell in rows:
        text.append(f"| {n} | {alpha:g} | {pair(exact)} | {pair(shell)} | "
                    f"{error(shell, exact):.2f} % | {pair(straight_line)} | "
                    f"{error(straight_line, exact):.1f} % |")
    text.append("")
    (pathlib.Path(cr.RESULTS) / "shell_curved.md").write_text("\n".join(text))
    print("\n".join(text))


if __name__ == "__main__":
    main()
