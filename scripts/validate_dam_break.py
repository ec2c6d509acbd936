#!/usr/bin/python3
"""Dam break (the study's scene 1) against Martin & Moyce 1952 and Koshizuka & Oka 1996.

Runs cases/dam_break.pbtxt at three spacings, measures the RMS relative error
of the surge front z/a over the experimental points with T = t sqrt(2g/a) <= 3.1,
and writes docs/figures/dam_break_front.png and docs/results/dam_break.md.

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


def dimensionless(series):
    T = series["t"] * np.sqrt(2 * G / COLUMN_WIDTH)
    return T, series["front"] / COLUMN_WIDTH, series["height"] / COLUMN_WIDTH


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
    rows, points = [], []
    for dx in args.spacings:
        out = os.path.join(args.out, f"dx_{dx:g}")
        wall = cr.run_case("dam_break", out, [f"fluid.spacing={dx}"])
        series = cr.read_csv(os.path.join(out, "timeseries.csv"))
        T, Z, H = dimensionless(series)
        rms, worst = cr.rms_relative_error(T, Z, T_exp[window], Z_exp[window])
        particles = int(series["water_particles"][0])
        rows.append([f"{dx * 1e3:g}", particles, f"{100 * rms:.1f} %", f"{100 * worst:.1f} %",
                     f"{wall:.1f} s", cr.spray_removed(series)])
        points.append({"series": "dam break", "label": f"dx = {dx * 1e3:g} mm", "wall_s": wall,
                       "error": 100 * rms, "error_name": "front RMS rel. error (%)"})
        label = f"cosph, dx = {dx * 1e3:g} mm ({particles} particles): RMS {100 * rms:.1f} %"
        ax_front.plot(T, Z, label=label)
        ax_height.plot(T, H / 2, label=f"dx = {dx * 1e3:g} mm")
    cr.write_points("dam_break", points)
    rows.append(["Koshizuka & Oka MPS", "", f"{100 * mps_rms:.1f} %", f"{100 * mps_max:.1f} %", "",
                 ""])

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

    table = cr.write_table(
        "dam_break",
        ["spacing (mm)", "water particles", "RMS rel. error (T <= 3.1)", "max rel. error",
         "wall time (2 cores)", "water left as spray"],
        rows,
        preamble="Front z/a against Martin & Moyce 1952, produced by "
                 "`scripts/validate_dam_break.py`.")
    print(open(table).read())
    print("wrote", figure)


if __name__ == "__main__":
    main()
