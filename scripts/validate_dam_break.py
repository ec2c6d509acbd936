#!/usr/bin/python3
"""Dam break (the study's scene 1) against Martin & Moyce 1952 and Koshizuka & Oka 1996.

Runs cases/dam_break.pbtxt at three spacings, until the surge has struck the
far wall and run back (the case's end time), and measures
  - the RMS relative error of the surge front z/a over the experimental points
    with T = t sqrt(2g/a) <= 3.1;
  - the pressure sensors' mean and noise after the impact (issue 38): at the
    far wall (probe1) and on the floor (probe0), over t = 0.35-0.55 s, the
    noise being the RMS about the sensor's own running mean over
    0.1 sqrt(H/g), both in units of rho0 g H (H = 0.288 m);
and the floor sensor's in the still tank (the tank filled to H, 8 mm).
Writes docs/figures/dam_break_front.png, docs/figures/dam_break_pressure.png
and docs/results/dam_break.md.

usage: /usr/bin/python3 scripts/validate_dam_break.py [--spacings 0.008 0.004 0.002]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr

COLUMN_WIDTH = 0.144  # a, m (cases/dam_break.pbtxt)
G = 9.81
T_LAST = 3.1  # the comparison window of the issue
H = 0.288  # the column's height, m
RHO0_G_H = 1000.0 * G * H  # Pa
NOISE_WINDOW = 0.1 * np.sqrt(H / G)  # s, the running mean's width (17 ms)
AFTER_IMPACT = (0.35, 0.55)  # s: the surge has struck the far wall (0.26 s); quasi-steady load
OUTPUT_INTERVAL = 0.0005  # s: 34 rows to the running mean's width
STILL_TANK = ["fluid.water[0].max.x=0.576"]  # the dam break's tank filled to H


def dimensionless(series):
    T = series["t"] * np.sqrt(2 * G / COLUMN_WIDTH)
    return T, series["front"] / COLUMN_WIDTH, series["height"] / COLUMN_WIDTH


def front_error(series, experiment):
    """(RMS, largest) relative error of the run's front against Martin & Moyce
    (EXPERIMENT, martin_moyce_n2_front.csv) over T <= T_LAST."""
    T, Z, _ = dimensionless(series)
    T_exp, Z_exp = experiment["T_t_sqrt_2g_over_a"], experiment["Z_z_over_a"]
    window = T_exp <= T_LAST
    return cr.rms_relative_error(T, Z, T_exp[window], Z_exp[window])


def sensor_noise(series, probe):
    """(mean, noise) of timeseries column probeK_pressure after the impact, in rho0 g H."""
    return cr.pressure_noise(series["t"], series[f"{probe}_pressure"], NOISE_WINDOW, RHO0_G_H,
                             *AFTER_IMPACT)


def draw_pressure(runs, path):
    """The far-wall sensor against time, with its running mean, one panel per spacing."""
    fig, axes = plt.subplots(len(runs), 1, figsize=(8, 2.6 * len(runs)), sharex=True,
                             squeeze=False)
    for ax, (label, series) in zip(axes[:, 0], runs):
        t, p = series["t"], series["probe1_pressure"] / RHO0_G_H
        width = int(round(NOISE_WINDOW / np.median(np.diff(t))))
        mean, inner = cr.running_mean(p, width)
        level, noise = sensor_noise(series, "probe1")
        ax.plot(t, p, lw=0.6, color="0.6", label="far-wall sensor (probe1)")
        ax.plot(t[inner], mean, color="C0",
                label=f"running mean over {1e3 * NOISE_WINDOW:.0f} ms")
        ax.axvspan(*AFTER_IMPACT, color="C1", alpha=0.12,
                   label=f"measured: mean {level:.2f}, noise {noise:.3f}")
        ax.set(ylabel="P / (rho0 g H)", title=f"Dam break, {label}", ylim=(-0.5, 2.5))
        ax.legend(fontsize=7.5, loc="upper right")
    axes[-1, 0].set(xlabel="t (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spacings", type=float, nargs="+", default=[0.008, 0.004, 0.002])
    parser.add_argument("--out", default=os.path.join(cr.REPO, "out", "validation", "dam_break"))
    args = parser.parse_args()

    experiment = cr.reference("martin_moyce_n2_front.csv")
    T_exp, Z_exp = experiment["T_t_sqrt_2g_over_a"], experiment["Z_z_over_a"]
    window = T_exp <= T_LAST
    mps = cr.reference("koshizuka_oka_front.csv")
    T_mps, Z_mps = mps["T_t_sqrt_2g_over_L"], mps["Z_z_over_L"]
    mps_rms, mps_max = cr.rms_relative_error(T_mps, Z_mps, T_exp[window], Z_exp[window])

    fig, (ax_front, ax_height) = plt.subplots(1, 2, figsize=(11, 4.5))
    rows, points, pressure_runs = [], [], []
    for dx in args.spacings:
        out = os.path.join(args.out, f"dx_{dx:g}")
        wall = cr.run_case("dam_break", out,
                           [f"fluid.spacing={dx}", f"run.output_interval={OUTPUT_INTERVAL}"])
        series = cr.read_csv(os.path.join(out, "timeseries.csv"))
        pressure_runs.append((f"dx = {dx * 1e3:g} mm", series))
        T, Z, H = dimensionless(series)
        rms, worst = front_error(series, experiment)
        particles = int(series["water_particles"][0])
        far_wall, floor = sensor_noise(series, "probe1"), sensor_noise(series, "probe0")
        rows.append([f"{dx * 1e3:g}", particles, f"{100 * rms:.1f} %", f"{100 * worst:.1f} %",
                     f"{far_wall[0]:.2f}", f"{far_wall[1]:.3f}", f"{floor[0]:.2f}",
                     f"{floor[1]:.3f}", f"{wall:.1f} s", cr.spray_removed(series)])
        points.append({"series": "dam break", "label": f"dx = {dx * 1e3:g} mm", "wall_s": wall,
                       "error": 100 * rms, "error_name": "front RMS rel. error (%)"})
        label = f"cosph, dx = {dx * 1e3:g} mm ({particles} particles): RMS {100 * rms:.1f} %"
        ax_front.plot(T, Z, label=label)
        ax_height.plot(T, H / 2, label=f"dx = {dx * 1e3:g} mm")
    cr.write_points("dam_break", points)
    rows.append(["Koshizuka & Oka MPS", "", f"{100 * mps_rms:.1f} %", f"{100 * mps_max:.1f} %", "",
                 "", "", "", "", ""])
    still = os.path.join(args.out, "still_tank")
    wall = cr.run_case("dam_break", still, STILL_TANK + [f"run.output_interval={OUTPUT_INTERVAL}"])
    series = cr.read_csv(os.path.join(still, "timeseries.csv"))
    floor = sensor_noise(series, "probe0")
    rows.append(["still tank, 8", int(series["water_particles"][0]), "", "", "", "",
                 f"{floor[0]:.2f}", f"{floor[1]:.3f}", f"{wall:.1f} s", cr.spray_removed(series)])

    ax_front.plot(T_exp, Z_exp, "ko", label="Martin & Moyce 1952 (experiment)")
    ax_front.plot(T_mps, Z_mps, "k--", label=f"Koshizuka & Oka 1996: RMS {100 * mps_rms:.1f} %")
    ax_front.axvline(T_LAST, color="0.8", lw=0.8)
    ax_front.set(xlabel="T = t sqrt(2g/a)", ylabel="front z/a", xlim=(0, 3.6), ylim=(1, 4.2),
                 title="Dam break: surge front")
    ax_front.legend(fontsize=7.5)
    ax_height.set(xlabel="T = t sqrt(2g/a)", ylabel="height at the left wall / 2a",
                  xlim=(0, 3.6), title="Residual column height")
    ax_height.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    figure = os.path.join(cr.FIGURES, "dam_break_front.png")
    fig.savefig(figure, dpi=110)

    pressure_figure = os.path.join(cr.FIGURES, "dam_break_pressure.png")
    draw_pressure(pressure_runs, pressure_figure)

    table = cr.write_table(
        "dam_break",
        ["spacing (mm)", "water particles", "RMS rel. error (T <= 3.1)", "max rel. error",
         "far wall: mean", "noise", "floor: mean", "noise", "wall time (2 cores)",
         "water left as spray"],
        rows,
        preamble="Front z/a against Martin & Moyce 1952, and the pressure sensors after the "
                 f"impact (t = {AFTER_IMPACT[0]:g}-{AFTER_IMPACT[1]:g} s): mean, and noise as the "
                 f"RMS about the running mean over 0.1 sqrt(H/g) = {1e3 * NOISE_WINDOW:.0f} ms, "
                 "both over rho0 g H (H = 0.288 m). Far wall: probe1, 16 mm up; floor: probe0, "
                 "under the column. Produced by `scripts/validate_dam_break.py`.")
    print(open(table).read())
    print("wrote", figure, pressure_figure)


if __name__ == "__main__":
    main()
