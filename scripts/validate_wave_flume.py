#!/usr/bin/python3
"""Wave flume (cases/wave_flume.pbtxt) against linear wave-maker theory.

Runs the case for each wave period, the piston's stroke S = 2 amplitude kept,
its ramp one period long, and measures the first-order wave height H at the
level gauge x = 1 m (timeseries.csv level0): the first harmonic of a
least-squares fit over whole periods after the ramp and the wave train's
front have passed, and before a reflection from the far wall can return
(wave_theory.gauge_window). Compares H/S with Biesel's transfer function
H/S = 2 (cosh 2kd - 1) / (sinh 2kd + 2kd) (Dean & Dalrymple 1991, ch. 6;
validation/reference/README.md). Goal: within 5 %.
Writes docs/figures/wave_flume.png and docs/results/wave_flume.md.

usage: /usr/bin/python3 scripts/validate_wave_flume.py [--periods 1.0 1.3] [--spacing 0.01]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr
import wave_theory as wt

# cases/wave_flume.pbtxt
DEPTH = 0.25  # m
FLUME_LENGTH = 6.0  # m, piston face to far wall
AMPLITUDE = 0.01  # m: S/2
GAUGE_X = 1.0  # m: level_probes[0]
GOAL = 0.05


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--periods", type=float, nargs="+", default=[1.0, 1.3])
    parser.add_argument("--spacing", type=float, default=0.01)
    parser.add_argument("--out", default=os.path.join(cr.REPO, "out", "validation", "wave_flume"))
    parser.add_argument("--reuse", action="store_true", help="read the runs already in --out")
    args = parser.parse_args()

    stroke = 2 * AMPLITUDE
    fig, axes = plt.subplots(len(args.periods), 1, figsize=(9, 2.8 * len(args.periods)),
                             squeeze=False)
    rows = []
    for ax, period in zip(axes[:, 0], args.periods):
        t_from, t_to = wt.gauge_window(period, DEPTH, period, GAUGE_X, FLUME_LENGTH)
        assert t_to - t_from >= 2 * period - 1e-9, f"T = {period} s: window under 2 periods"
        out = os.path.join(args.out, f"T_{period:g}_dx_{args.spacing:g}")
        settings = [f"fluid.spacing={args.spacing}",
                    f"fluid.moving_walls[0].piston.period={period}",
                    f"fluid.moving_walls[0].piston.ramp_time={period}",
                    f"run.end_time={t_to + 0.05:.3f}"]
        wall = cr.logged_wall_time(out) if args.reuse else cr.run_case("wave_flume", out, settings)
        series = cr.read_csv(os.path.join(out, "timeseries.csv"))
        t, level = series["t"], series["level0"]
        height, mean = wt.first_harmonic_height(t, level, period, t_from, t_to)
        theory = wt.biesel_height_over_stroke(period, DEPTH) * stroke
        error = height / theory - 1
        kd = wt.wavenumber(period, DEPTH) * DEPTH
        rows.append([f"{period:g}", f"{kd:.2f}", f"{2 * np.pi / wt.wavenumber(period, DEPTH):.2f}",
                     f"{t_from:.2f}-{t_to:.2f}", f"{1e3 * theory:.2f}", f"{1e3 * height:.2f}",
                     f"{100 * error:+.1f} %", "yes" if abs(error) <= GOAL else "no",
                     f"{1e3 * (mean - DEPTH):+.2f}", int(series["water_particles"][0]),
                     f"{wall:.0f} s" if wall else "-"])
        ax.plot(t, 1e3 * (level - DEPTH), lw=0.8, label=f"level at x = {GAUGE_X:g} m (cosph)")
        ax.axvspan(t_from, t_to, color="C1", alpha=0.12,
                   label=f"fitted: H = {1e3 * height:.1f} mm ({100 * error:+.1f} %)")
        for sign in (1, -1):
            ax.axhline(sign * 500 * theory, color="k", ls="--", lw=0.8,
                       label="Biesel: H/2 = %.1f mm" % (500 * theory) if sign > 0 else None)
        ax.set(xlabel="t (s)", ylabel="eta (mm)",
               title=f"Wave flume, T = {period:g} s, kd = {kd:.2f}, S = {1e3 * stroke:g} mm, "
                     f"dx = {1e3 * args.spacing:g} mm")
        ax.legend(fontsize=7.5, loc="lower right")
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    figure = os.path.join(cr.FIGURES, "wave_flume.png")
    fig.savefig(figure, dpi=110)
    table = cr.write_table(
        "wave_flume",
        ["period T (s)", "kd", "wavelength (m)", "window (s)", "Biesel H (mm)", "cosph H (mm)",
         "error", "within 5 %", "mean level - d (mm)", "water particles", "wall time"],
        rows,
        preamble=f"First-order wave height at the level gauge x = {GAUGE_X:g} m of "
                 f"cases/wave_flume.pbtxt (d = {DEPTH:g} m, stroke S = {1e3 * stroke:g} mm, "
                 f"spacing {1e3 * args.spacing:g} mm), against Biesel's piston transfer function. "
                 "Produced by `scripts/validate_wave_flume.py`.")
    print(open(table).read())
    print("wrote", figure)


if __name__ == "__main__":
    main()
