#!/usr/bin/python3
"""The pressure on a wall struck by a dam break, against Buchner's experiment.

Runs cases/dam_break_wall_pressure.pbtxt (H = 0.6 m, sensor P1 on the far
wall 0.16 m up; validation/reference/buchner2002_wall_pressure_p1.csv) for
each option of the water's dissipation, kernel and shifting that
pressure_noise.py compares (its OPTIONS), at H / 50 = 12 mm, and at
H / 100 = 6 mm for the default and for the option quietest on the plateau
at 12 mm. For each run, in t* = t sqrt(g/H)
and p / (rho g H):
  - the RMS difference from the experiment over its whole record
    (t* = 2.0-7.3), of the sensor as read and of its running mean over
    0.1 sqrt(H/g) (the load without the noise);
  - the plateau between the two impacts (t* = 3.3-5.2): the mean against
    the experiment's, and the noise, the RMS about the running mean
    (cosph_results.pressure_noise, as the dam break's sensors are measured);
  - the first time the running mean passes 0.2 (the experiment's rise);
  - wall and CPU time, one thread.
Writes docs/results/wall_pressure.md and docs/figures/wall_pressure.png.

usage: /usr/bin/python3 scripts/validate_wall_pressure.py [--out DIR] [--reuse]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cosph_results as cr  # noqa: E402
from pressure_noise import OPTIONS  # noqa: E402

CASE = "dam_break_wall_pressure"
H, G, RHO0 = 0.6, 9.81, 1000.0
T_SCALE, P_SCALE = np.sqrt(H / G), RHO0 * G * H
NOISE_WINDOW = 0.1 * T_SCALE  # s, as the dam break's sensors
RECORD = (2.0, 7.3)           # t*: the experiment's record
PLATEAU = (3.3, 5.2)          # t*: between the impact and the jet's return
RISE = 0.2                    # p / (rho g H)
COARSE, FINE = 0.012, 0.006   # m: H / 50, H / 100


def experiment():
    series = cr.reference("buchner2002_wall_pressure_p1.csv")
    return series["t_sqrt_g_over_H"], series["p_over_rho_g_H"]


def measure(out, t_exp, p_exp):
    """The row's numbers for the run in OUT, or None if it did not reach the record's end."""
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    t, p = series["t"], series["probe0_pressure"]
    if t[-1] / T_SCALE < RECORD[1]:
        return None
    width = int(round(NOISE_WINDOW / np.median(np.diff(t))))
    load, inner = cr.running_mean(p, width)
    t_star, p_star, load_star = t / T_SCALE, p / P_SCALE, load / P_SCALE
    record = (t_exp >= RECORD[0]) & (t_exp <= RECORD[1])
    rms_read = np.sqrt(np.mean((np.interp(t_exp, t_star, p_star) - p_exp)[record] ** 2))
    rms_load = np.sqrt(np.mean((np.interp(t_exp, t_star[inner], load_star) - p_exp)[record] ** 2))
    mean, noise = cr.pressure_noise(t, p, NOISE_WINDOW, P_SCALE, PLATEAU[0] * T_SCALE,
                                    PLATEAU[1] * T_SCALE)
    rise = t_star[inner][np.argmax(load_star > RISE)] if np.any(load_star > RISE) else np.nan
    return {"rms_read": rms_read, "rms_load": rms_load, "mean": mean, "noise": noise,
            "rise": rise, "t": t_star, "p": p_star, "wall": cr.logged_wall_time(out),
            "cpu": sum(cr.logged_cpu_times(out).values())}


def quietest(results):
    """The option with the least plateau noise at the coarse spacing."""
    noise = {key: r["noise"] for (spacing, key), r in results.items()
             if spacing == COARSE and r is not None and np.isfinite(r["noise"])}
    return min(noise, key=noise.get) if noise else None


def plateau_of_experiment(t_exp, p_exp):
    inside = (t_exp >= PLATEAU[0]) & (t_exp <= PLATEAU[1])
    return float(np.mean(p_exp[inside]))


def draw(runs, t_exp, p_exp, path):
    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 2.6 * len(runs)), sharex=True)
    for ax, (label, result) in zip(np.atleast_1d(axes), runs):
        ax.plot(result["t"], result["p"], lw=0.6, color="tab:blue", label=f"cosph: {label}")
        ax.plot(t_exp, p_exp, "k.-", ms=3, lw=1, label="Buchner 2002 (experiment)")
        ax.set_ylabel("P1 / (rho g H)")
        ax.set_ylim(-0.5, 1.5)
        ax.legend(loc="upper left", fontsize=8)
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[-1].set_xlim(1.5, 7.5)
    np.atleast_1d(axes)[-1].set_xlabel("t sqrt(g/H)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    args = cr.script_arguments(__doc__, "validation/wall_pressure").parse_args()
    t_exp, p_exp = experiment()
    results = {}
    for spacing in (COARSE, FINE):
        for key, label, settings in OPTIONS:
            if spacing == FINE and key not in ("delta_sph", quietest(results)):
                continue
            out = os.path.join(args.out, f"{key}_{1e3 * spacing:g}mm")
            _, failure = cr.run_or_reuse(CASE, out, settings + [
                f"fluid.spacing={spacing}", "run.threads=1", "run.snapshot_interval=1"], args.reuse)
            measured = measure(out, t_exp, p_exp) if os.path.exists(
                os.path.join(out, "timeseries.csv")) else None
            results[(spacing, key)] = measured
            if measured is None:
                print(f"{key} at {spacing}: {failure or 'did not reach the record end'}")
    labels = {key: label for key, label, _ in OPTIONS}
    rows = []
    for (spacing, key), r in results.items():
        if r is None:
            rows.append([labels[key], f"{1e3 * spacing:g}", "stopped", "", "", "", "", "", ""])
            continue
        rows.append([labels[key], f"{1e3 * spacing:g}", f"{r['rms_read']:.3f}",
                     f"{r['rms_load']:.3f}", f"{r['mean']:.3f}", f"{r['noise']:.3f}",
                     f"{r['rise']:.2f}", f"{r['wall']:.0f}" if r["wall"] else "-",
                     f"{r['cpu']:.0f}"])
    exp_mean = plateau_of_experiment(t_exp, p_exp)
    exp_rise = t_exp[np.argmax(p_exp > RISE)]
    rows.append(["Buchner 2002, experiment", "", "", "", f"{exp_mean:.3f}", "", f"{exp_rise:.2f}",
                 "", ""])
    header = ["option", "spacing (mm)", "P1 RMS vs experiment, as read", "its running mean",
              f"plateau mean (t* {PLATEAU[0]}-{PLATEAU[1]})", "plateau noise",
              f"rise: t* where the running mean passes {RISE}", "wall time (s)", "CPU time (s)"]
    preamble = (
        "Written by `scripts/validate_wall_pressure.py`. The dam break of Buchner 2002 "
        "(`cases/dam_break_wall_pressure.pbtxt`: H = 0.6 m, the column 2H long, the far wall "
        "5.366 H away), the pressure sensor P1 on the far wall 0.16 m up, against the "
        "experiment (validation/reference/buchner2002_wall_pressure_p1.csv), in "
        "t* = t sqrt(g/H) and p / (rho g H), for the water's options of "
        "`scripts/pressure_noise.py`, at H / 50 = 12 mm, and at H / 100 = 6 mm for the default "
        "and the option quietest on the plateau at 12 mm. RMS differences "
        f"over the experiment's record (t* {RECORD[0]}-{RECORD[1]}) of the sensor as read and "
        "of its running mean over 0.1 sqrt(H/g) (the load without the noise); the plateau "
        "between the impact and the jet's return, its mean and its noise (RMS about that "
        "running mean); one thread each, on the shared machine.")
    cr.write_table("wall_pressure", header, rows, preamble)
    shown = [(f"{labels[key]}, {1e3 * spacing:g} mm", r) for (spacing, key), r in results.items()
             if r is not None and (spacing == FINE or key == "delta_sph")]
    draw(shown, t_exp, p_exp, os.path.join(cr.FIGURES, "wall_pressure.png"))
    print("wrote docs/results/wall_pressure.md and docs/figures/wall_pressure.png")


if __name__ == "__main__":
    main()
