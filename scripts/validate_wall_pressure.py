#!/usr/bin/python3
"""The pressure on a wall struck by a dam break, against Buchner's experiment.

Runs cases/dam_break_wall_pressure.pbtxt (H = 0.6 m, sensor P1 on the far
wall 0.16 m up; validation/reference/buchner2002_wall_pressure_p1.csv) for
each option of the water's dissipation, kernel and shifting that
pressure_noise.py compares (its OPTIONS), at H / 50 = 12 mm, and at
H / 100 = 6 mm for delta-SPH (the earlier default), the Riemann solver with the
Wendland C2 kernel with walls damping along their normal (the default water,
DEFAULT_WATER), and the option quietest on the
plateau at 12 mm. For each run, in t* = t sqrt(g/H)
and p / (rho g H):
  - the RMS difference from the experiment over its whole record
    (t* = 2.0-7.3), of the sensor as read and of its running mean over
    0.1 sqrt(H/g) (the load without the noise);
  - the plateau between the two impacts (t* = 3.3-5.2): the mean against
    the experiment's, and the noise, the RMS about the running mean
    (cosph_results.pressure_noise, as the dam break's sensors are measured);
  - the first time the running mean passes 0.2 (the experiment's rise);
  - wall and CPU time, one thread.
The same runs, with the other walls of fluid.wall_friction too ("none":
free-slip; "normal": damping along their normal only) for the options of
WALLS_OF, against a converged two-dimensional solution
of this flow (De Courcy et al. 2024, H / dx = 400;
validation/reference/decourcy2024_wall_pressure_*.csv) at its four sensors on
the far wall, 6, 30, 60 and 160 mm up: the RMS difference of each sensor's
running mean, the load after the impact at the lowest, and when the impact
reaches it. And the dam break's front against Martin & Moyce (the front's
RMS relative error, T <= 3.1) and its far-wall sensor at 8 and 4 mm, for
every water with the walls' friction and with walls damping along their
normal, those of WALLS_OF also with free-slip walls, with each
run's CPU time per simulated second.
Writes docs/results/wall_pressure.md, wall_pressure_2d_reference.md,
wall_friction_front.md and docs/figures/wall_pressure.png,
wall_pressure_2d_reference.png.

usage: /usr/bin/python3 scripts/validate_wall_pressure.py [--out DIR] [--reuse]
"""
import functools
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cosph_results as cr  # noqa: E402
import validate_dam_break as dam  # noqa: E402
from pressure_noise import OPTIONS  # noqa: E402

CASE = "dam_break_wall_pressure"
H, G, RHO0 = 0.6, 9.81, 1000.0
T_SCALE, P_SCALE = np.sqrt(H / G), RHO0 * G * H
NOISE_WINDOW = 0.1 * T_SCALE  # s, as the dam break's sensors
RECORD = (2.0, 7.3)           # t*: the experiment's record
PLATEAU = (3.3, 5.2)          # t*: between the impact and the jet's return
RISE = 0.2                    # p / (rho g H)
COARSE, FINE = 0.012, 0.006   # m: H / 50, H / 100
# delta-SPH (the earlier default), the Riemann solver with the Wendland C2
# kernel (the cheapest option quieter than delta-SPH with either walls; with
# walls damping along their normal, the default water) and the quietest option
# on the plateau (WALLS_OF) again with the other walls of fluid.wall_friction:
# (key suffix, label suffix, settings).
WALLS = [("_free_slip", ", free-slip walls", ["fluid.wall_friction=none"]),
         ("_normal", ", walls damping along their normal only", ["fluid.wall_friction=normal"])]
FREE_SLIP_SUFFIX = WALLS[0][0]
WALLS_OF = ("delta_sph", "riemann_wendland", "riemann_wendland_2dx")
DEFAULT_WATER = "riemann_wendland_normal"  # docs/physics.md, "Choice of water"
# De Courcy et al. 2024's sensors: (timeseries column, height in mm, file).
REFERENCE_2D = [(f"probe{k}_pressure", mm, f"decourcy2024_wall_pressure_y{mm:03d}mm.csv")
                for k, mm in ((1, 6), (2, 30), (3, 60), (0, 160))]
RECORD_2D = (2.3, 7.0)        # t*: its record
IMPACT = 0.5                  # p / (rho g H): the impact has reached the lowest sensor


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
    rms_read = cr.rms_error(t_star, p_star, t_exp[record], p_exp[record])
    rms_load = cr.rms_error(t_star[inner], load_star, t_exp[record], p_exp[record])
    mean, noise = cr.pressure_noise(t, p, NOISE_WINDOW, P_SCALE, PLATEAU[0] * T_SCALE,
                                    PLATEAU[1] * T_SCALE)
    rise = t_star[inner][np.argmax(load_star > RISE)] if np.any(load_star > RISE) else np.nan
    return {"rms_read": rms_read, "rms_load": rms_load, "mean": mean, "noise": noise,
            "rise": rise, "t": t_star, "p": p_star, "wall": cr.logged_wall_time(out),
            "cpu": sum(cr.logged_cpu_times(out).values()),
            "against_2d": against_reference_2d(series, width)}


@functools.cache
def reference_2d():
    """De Courcy et al. 2024's sensors: [(column, mm, t*, p*)], each sorted in
    time (a curve traced off a figure steps back here and there)."""
    curves = []
    for column, mm, name in REFERENCE_2D:
        series = cr.reference(name)
        order = np.argsort(series["t_sqrt_g_over_H"], kind="stable")
        curves.append((column, mm, series["t_sqrt_g_over_H"][order],
                       series["p_over_rho_g_H"][order]))
    return curves


def window_mean(t, p, window):
    """The time mean of the curve (t, p) over WINDOW = (from, to)."""
    samples = np.linspace(window[0], window[1], 400)
    return float(np.mean(np.interp(samples, t, p)))


def against_reference_2d(series, width):
    """For each of De Courcy's sensors: the RMS difference of this run's running
    mean from the reference over its record, and the load after the impact
    (run, reference); and when the running mean at the lowest sensor first
    passes IMPACT (run, reference)."""
    t_star = series["t"] / T_SCALE
    sensors = []
    for column, mm, t_ref, p_ref in reference_2d():
        load, inner = cr.running_mean(series[column] / P_SCALE, width)
        t_load = t_star[inner]
        record = (t_ref >= RECORD_2D[0]) & (t_ref <= min(RECORD_2D[1], t_load[-1]))
        rms = cr.rms_error(t_load, load, t_ref[record], p_ref[record])
        sensors.append({"mm": mm, "rms": rms, "load": window_mean(t_load, load, PLATEAU),
                        "load_ref": window_mean(t_ref, p_ref, PLATEAU), "t": t_load,
                        "p": load, "impact": t_load[np.argmax(load > IMPACT)],
                        "impact_ref": t_ref[np.argmax(p_ref > IMPACT)]})
    return sensors


def quietest(results):
    """The option with the least plateau noise at the coarse spacing."""
    noise = {key: r["noise"] for (spacing, key), r in results.items()
             if spacing == COARSE and r is not None and np.isfinite(r["noise"])}
    return min(noise, key=noise.get) if noise else None


def plateau_of_experiment(t_exp, p_exp):
    """The experiment's load on the plateau, a time mean as the 2-D reference's
    (its points are not evenly spaced in time)."""
    return window_mean(t_exp, p_exp, PLATEAU)


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
    options = OPTIONS + [(key + suffix, label + label_suffix, settings + walls)
                         for key, label, settings in OPTIONS if key in WALLS_OF
                         for suffix, label_suffix, walls in WALLS]
    for spacing in (COARSE, FINE):
        for key, label, settings in options:
            fine = ("delta_sph", "delta_sph" + FREE_SLIP_SUFFIX, "riemann_wendland_normal",
                    "riemann_wendland_2dx", "riemann_wendland_2dx_normal", quietest(results))
            if spacing == FINE and key not in fine:
                continue
            out = os.path.join(args.out, f"{key}_{1e3 * spacing:g}mm")
            _, failure = cr.run_or_reuse(CASE, out, settings + [
                f"fluid.spacing={spacing}", "run.threads=1", "run.snapshot_interval=1"],
                args.reuse and os.path.exists(os.path.join(out, "timeseries.csv")))
            measured = measure(out, t_exp, p_exp) if os.path.exists(
                os.path.join(out, "timeseries.csv")) else None
            results[(spacing, key)] = measured
            if measured is None:
                print(f"{key} at {spacing}: {failure or 'did not reach the record end'}")
    labels = {key: label + (cr.DEFAULT_WATER_MARK if key == DEFAULT_WATER else "")
              for key, label, _ in options}
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
        "`scripts/pressure_noise.py`, and delta-SPH (the earlier default), the Riemann solver "
        "with the Wendland C2 kernel and the option quietest on the plateau "
        "with the other walls of `fluid.wall_friction` (\"none\": free-slip; \"normal\": "
        "damping along their normal only), at H / 50 = 12 mm, and at "
        "H / 100 = 6 mm for delta-SPH, also with free-slip walls, the Riemann solver with the "
        "Wendland C2 kernel with walls damping along their normal (the default water), and the "
        "quietest, also with "
        "walls damping along their normal. RMS differences "
        f"over the experiment's record (t* {RECORD[0]}-{RECORD[1]}) of the sensor as read and "
        "of its running mean over 0.1 sqrt(H/g) (the load without the noise); the plateau "
        "between the impact and the jet's return, its mean and its noise (RMS about that "
        "running mean); one thread each, on the shared machine.")
    cr.write_table("wall_pressure", header, rows, preamble)
    shown = [(f"{labels[key]}, {1e3 * spacing:g} mm", r) for (spacing, key), r in results.items()
             if r is not None and (spacing == FINE or key == "delta_sph")]
    draw(shown, t_exp, p_exp, os.path.join(cr.FIGURES, "wall_pressure.png"))
    write_against_reference_2d(results, labels)
    write_front(args)
    print("wrote docs/results/wall_pressure.md, wall_pressure_2d_reference.md, "
          "wall_friction_front.md and docs/figures/wall_pressure.png, "
          "wall_pressure_2d_reference.png")


def write_against_reference_2d(results, labels):
    rows = []
    for (spacing, key), r in results.items():
        if r is None:
            continue
        sensors = r["against_2d"]
        lowest = sensors[0]
        rows.append([labels[key], f"{1e3 * spacing:g}"] +
                     [f"{sensor['rms']:.3f}" for sensor in sensors] +
                     [f"{lowest['load']:.2f}", f"{lowest['impact']:.2f}"])
    reference = next(r for r in results.values() if r is not None)["against_2d"]
    rows.append(["De Courcy et al. 2024, H / dx = 400", ""] + ["" for _ in reference] +
                [f"{reference[0]['load_ref']:.2f}", f"{reference[0]['impact_ref']:.2f}"])
    header = (["option", "spacing (mm)"] +
              [f"RMS vs the 2-D solution, {sensor['mm']} mm up" for sensor in reference] +
              [f"load at 6 mm (t* {PLATEAU[0]}-{PLATEAU[1]})",
               f"impact at 6 mm: t* where the load passes {IMPACT}"])
    preamble = (
        "Written by `scripts/validate_wall_pressure.py`. The runs of the table above (and the "
        "delta-SPH, the Riemann solver with the Wendland C2 kernel and the quietest option with "
        "the other walls of `fluid.wall_friction`: "
        "\"none\", free-slip, and \"normal\", damping along their normal only) "
        "against a converged two-dimensional solution of the same flow: De Courcy et al. 2024 "
        "(incompressible delta-SPH, H / dx = 400; validation/reference/"
        "decourcy2024_wall_pressure_*.csv), at its sensors on the far wall 6, 30, 60 and 160 mm "
        "up (the last is Buchner's P1). In t* = t sqrt(g/H) and p / (rho g H): the RMS "
        "difference of each sensor's running mean over 0.1 sqrt(H/g) from the solution over "
        f"t* {RECORD_2D[0]}-{RECORD_2D[1]}; at the lowest sensor, the mean load after the "
        "impact and the time the load first passes "
        f"{IMPACT}.")
    cr.write_table("wall_pressure_2d_reference", header, rows, preamble)
    shown = [(labels[key], r) for (spacing, key), r in results.items()
             if r is not None and spacing == FINE]
    fig, axes = plt.subplots(len(reference), 1, figsize=(9, 2.4 * len(reference)), sharex=True)
    for ax, (column, mm, t_ref, p_ref) in zip(axes, reference_2d()):
        for label, r in shown:
            sensor = next(s for s in r["against_2d"] if s["mm"] == mm)
            ax.plot(sensor["t"], sensor["p"], lw=0.9, label=f"cosph, 6 mm: {label}")
        ax.plot(t_ref, p_ref, "k-", lw=1.2, label="De Courcy et al. 2024 (2-D, H/dx = 400)")
        ax.set_ylabel(f"{mm} mm up: p / (rho g H)")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=7)
    axes[-1].set_xlim(2.0, 7.0)
    axes[-1].set_xlabel("t sqrt(g/H)  (cosph: running mean over 0.1 sqrt(H/g))")
    fig.tight_layout()
    fig.savefig(os.path.join(cr.FIGURES, "wall_pressure_2d_reference.png"), dpi=110)
    plt.close(fig)


def write_front(args):
    """The dam break (cases/dam_break.pbtxt) with either wall friction: its front
    against Martin & Moyce and its far-wall sensor's load and noise after the
    impact, as the dam break's own tables measure them (validate_dam_break.py)."""
    experiment = cr.reference("martin_moyce_n2_front.csv")
    end_time = dam.AFTER_IMPACT[1] + 0.01
    rows = []
    for key, label, settings in OPTIONS:
        # Every water with walls damping along their normal; those of
        # WALLS_OF with free-slip walls too.
        walls_of_water = [w for w in WALLS if key in WALLS_OF or w[0] != FREE_SLIP_SUFFIX]
        for spacing in (0.008, 0.004):
            for walls, suffix, friction in [("dissipation", "", [])] + [
                    (setting[0].split("=")[1], suffix, setting)
                    for suffix, _, setting in walls_of_water]:
                out = os.path.join(args.out, "dam_break", f"{key}{suffix}_{1e3 * spacing:g}mm")
                cr.run_or_reuse("dam_break", out, settings + friction + [
                    f"fluid.spacing={spacing}", f"run.end_time={end_time:.2f}",
                    f"run.output_interval={dam.OUTPUT_INTERVAL}"],
                                args.reuse and os.path.exists(os.path.join(out, "timeseries.csv")))
                series = cr.read_csv(os.path.join(out, "timeseries.csv"))
                rms, worst = dam.front_error(series, experiment)
                mean, noise = dam.sensor_noise(series, "probe1")
                cpu = sum(cr.logged_cpu_times(out).values()) / end_time
                rows.append([label + (cr.DEFAULT_WATER_MARK if key + suffix == DEFAULT_WATER
                                      else ""), walls, f"{1e3 * spacing:g}", f"{100 * rms:.1f} %",
                             f"{100 * worst:.1f} %", f"{mean:.3f}", f"{noise:.3f}", f"{cpu:.1f}"])
    preamble = (
        "Written by `scripts/validate_wall_pressure.py`. The dam break (`cases/dam_break.pbtxt`) "
        "with each water of `scripts/pressure_noise.py` with the walls' friction and with walls "
        "damping along their normal only (`fluid.wall_friction` \"normal\"), and delta-SPH, the "
        "Riemann solver with the Wendland C2 kernel and the quietest option also with free-slip "
        "walls (\"none\"); the default water is the Riemann solver with the Wendland C2 kernel "
        "(h = 1.5 dx) and walls damping along their normal: the front against Martin & Moyce 1952 over T = t sqrt(2g/a) <= "
        f"{dam.T_LAST}, and the far-wall sensor after the impact (t = {dam.AFTER_IMPACT[0]}-"
        f"{dam.AFTER_IMPACT[1]} s), its mean and noise over rho0 g H, as the dam break's own "
        "tables measure them; and the run's CPU time (all threads) per simulated second, whose "
        "ratios give each option's cost (the runs' absolute times come from a shared machine).")
    cr.write_table("wall_friction_front", ["water", "fluid.wall_friction", "spacing (mm)",
                                           "front: RMS rel. error", "largest",
                                           "far-wall sensor: mean", "noise",
                                           "CPU s per simulated s"], rows, preamble)

if __name__ == "__main__":
    main()
