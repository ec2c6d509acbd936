#!/usr/bin/python3
"""Wave flume (cases/wave_flume.pbtxt) against linear wave-maker theory.

Runs the case for each wave period and spacing, the piston's stroke
S = 2 amplitude kept, its ramp one period long, and measures the first-order
wave height H at the level gauge x = 1 m (timeseries.csv level0): the first
harmonic of a least-squares fit over whole periods after the ramp and the
wave train's front have passed, and before a reflection from the beach's
shoreline can return (wave_theory.gauge_window). Compares H/S with Biesel's
transfer function H/S = 2 (cosh 2kd - 1) / (sinh 2kd + 2kd) (Dean &
Dalrymple 1991, ch. 6; validation/reference/README.md) for the still depth d
the run has (the gauge's level at t = 0: a spacing that does not divide
0.25 m rounds the water's rows). Goal: within 5 %.

The beach's reflection: the gauges at 1 and 1.3 m (level0, level2) separate
the incident and reflected waves (Goda & Suzuki 1976;
wave_theory.incident_and_reflected), over the same window (the incident
height with the toe's early reflection taken out) and over two periods once
the shoreline's reflection is steady at both (wave_theory.reflection_start):
the measured reflection coefficient, against Battjes' Kr = 0.1 xi^2
(wave_theory.beach_reflection). --no-reflection ends the runs with the
first window instead.

Alongside, what tells generation from propagation: the height at the gauge
x = 2 m (level1, over its own window) over the first, and the mean distance
of each water particle to its nearest neighbour in the last snapshot (x from
1.5 to 3 m), in spacings: 1 on the lattice, 1/2 when the particles have
paired up. The case as it is runs at every spacing; with --previous, also
the settings the case had before (cubic spline, h = 1.3 dx, artificial
viscosity 0.02) at the default spacing, over the first window only.
Writes docs/figures/wave_flume.png and docs/results/wave_flume.md.

--points instead runs the speed-accuracy series: T = 1 s over the first
window only, on one thread (run.threads=1, so that its wall time compares
with the other exact references'), at the spacings of POINT_SPACINGS, and
writes docs/results/wave_flume_points.json (|height error| against Biesel,
wall and CPU time) for scripts/speed_accuracy.py; the table and the figure
are left as they are.

usage: /usr/bin/python3 scripts/validate_wave_flume.py [--periods 1.0 1.3]
           [--spacings 0.02 0.01] [--finer 0.005] [--previous] [--no-reflection]
           [--reuse] [--points]
"""
import glob
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr
import wave_theory as wt

# cases/wave_flume.pbtxt
DEFAULT_SPACING = 0.01  # m
DEPTH = 0.25  # m, the still depth the case draws
BEACH = wt.Beach(DEPTH, toe_x=3.0, slope=0.1)
AMPLITUDE = 0.01  # m: S/2
GAUGES = (1.0, 2.0, 1.3)  # m: level_probes[0], [1], [2]
REFLECTION_PERIODS = 2  # the late window's length
GOAL = 0.05
PREVIOUS = {"kernel": "cubic_spline", "h_factor": 1.3, "artificial_viscosity": 0.02}
PAIRING_STRIP = (1.5, 3.0)  # m
# The speed-accuracy series: the table's spacings, 20 mm and the case's
# 10 mm, with 25 and 12.5 mm between and beyond (they divide the depth). The
# four take about six minutes on one thread; 6.25 mm would take twice that
# again.
POINT_PERIOD = 1.0  # s
POINT_SPACINGS = (0.025, 0.02, 0.0125, 0.01)  # m


def mean_nearest_distance(out, spacing):
    """Mean distance from each water particle in PAIRING_STRIP to its nearest
    neighbour in the last snapshot, in spacings."""
    last = sorted(glob.glob(os.path.join(out, "fluid_*.h5")))[-1]
    with h5py.File(last, "r") as f:
        xy = f["position"][:, :2][f["kind"][:] == 0]
    reach = 3 * spacing
    x0, x1 = PAIRING_STRIP
    centres = xy[(xy[:, 0] >= x0) & (xy[:, 0] < x1)]
    others = xy[(xy[:, 0] >= x0 - reach) & (xy[:, 0] < x1 + reach)]
    nearest = []
    for chunk in np.array_split(centres, max(1, len(centres) // 500)):
        d2 = ((chunk[:, None, :] - others[None, :, :]) ** 2).sum(axis=2)
        d2[d2 == 0] = np.inf  # the particle itself
        nearest.append(np.sqrt(d2.min(axis=1)))
    return float(np.mean(np.concatenate(nearest))) / spacing


def whole_periods(t_from, t_to, t_end, period):
    """The window cut to the whole periods a run that ends at t_end has."""
    return t_from, t_from + period * np.floor((min(t_to, t_end) - t_from) / period + 1e-9)


def measure(out, period, spacing, label, run_settings, reuse, reflection):
    """One run: (table row, series, window, late window, H, error, theory, depth,
    wall time)."""
    # The windows use the case's depth and Biesel's height for it: they are
    # travel times, which the few per cent of either do not move by a period.
    nominal = wt.biesel_height_over_stroke(period, DEPTH) * 2 * AMPLITUDE
    windows = [wt.gauge_window(period, period, x, BEACH, nominal) for x in GAUGES]
    t_from, t_to = windows[0]
    assert t_to - t_from >= 2 * period - 1e-9, f"T = {period} s: window under 2 periods"
    # Steady at both reflection gauges: the later is the one nearer the piston.
    late_from = wt.reflection_start(period, period, min(GAUGES[0], GAUGES[2]), BEACH)
    late_to = late_from + REFLECTION_PERIODS * period
    end = late_to if reflection else t_to
    settings = [f"fluid.spacing={spacing}", f"fluid.moving_walls[0].piston.period={period}",
                f"fluid.moving_walls[0].piston.ramp_time={period}",
                f"run.end_time={end + 0.05:.3f}"] + run_settings
    wall = cr.logged_wall_time(out) if reuse else cr.run_case("wave_flume", out, settings)
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    t, t_end = series["t"], series["t"][-1]
    # A run ended early by hand (a fine spacing, for time) keeps the whole
    # periods it has, at least two.
    t_from, t_to = whole_periods(t_from, t_to, t_end, period)
    assert t_to - t_from >= 2 * period - 1e-9, f"{out}: ends before two periods in the window"
    depth = series["level0"][0]  # the still level of the lattice as drawn
    height, mean = wt.first_harmonic_height(t, series["level0"], period, t_from, t_to)
    theory = wt.biesel_height_over_stroke(period, depth) * 2 * AMPLITUDE
    error = height / theory - 1
    pair = (series["level0"], series["level2"], GAUGES[0], GAUGES[2], period, depth)
    incident, reflected = wt.incident_and_reflected(t, *pair, t_from, t_to)
    # The second gauge's window, cut to whole periods within the run.
    far_from, far_to = whole_periods(*windows[1], t_end, period)
    far = (wt.first_harmonic_height(t, series["level1"], period, far_from, far_to)[0]
           if far_to - far_from >= period - 1e-9 else None)
    late = None
    if t_end >= late_to - 1e-9:
        late_incident, late_reflected = wt.incident_and_reflected(t, *pair, late_from, late_to)
        late = (late_from, late_to)
    kd = wt.wavenumber(period, depth) * depth
    battjes = wt.beach_reflection(BEACH.slope, period, theory)
    row = [f"{1e3 * spacing:g}", label, f"{period:g}", f"{1e3 * depth:.1f}", f"{kd:.2f}",
           f"{t_from:.2f}-{t_to:.2f}", f"{1e3 * theory:.2f}", f"{1e3 * height:.2f}",
           f"{100 * error:+.1f} %", "yes" if abs(error) <= GOAL else "no",
           f"{1e3 * incident:.2f} ({100 * (incident / theory - 1):+.1f} %)",
           f"{reflected / incident:.2f}",
           f"{far / height:.2f}" + (" (1 period)" if far_to - far_from < 2 * period - 1e-9 else "")
           if far else "-",
           f"{battjes:.2f}",
           (f"{late_reflected / late_incident:.2f} ({late_from:.1f}-{late_to:.1f} s)"
            if late else "-"),
           f"{mean_nearest_distance(out, spacing):.2f}",
           int(series["water_particles"][0]), f"{wall:.0f} s" if wall else "-"]
    return row, series, (t_from, t_to), late, height, error, theory, depth, wall


def write_points(out, reuse):
    """docs/results/wave_flume_points.json: the runs of POINT_SPACINGS."""
    points = []
    for spacing in POINT_SPACINGS:
        run = os.path.join(out, f"T_{POINT_PERIOD:g}_dx_{spacing:g}")
        row, *_, error, _theory, _depth, wall = measure(
            run, POINT_PERIOD, spacing, "the case", ["run.threads=1"], reuse, False)
        # The launcher's clocks, run now or reused: the same measure for each.
        wall = cr.logged_wall_time(run) or wall
        cpu = sum(cr.logged_cpu_times(run).values()) or None
        points.append({"series": "wave flume, the case", "label": f"{1e3 * spacing:g} mm",
                       "wall_s": wall, "cpu_s": cpu, "error": 100 * abs(error),
                       "error_name": f"wave flume, T = {POINT_PERIOD:g} s: "
                                     "|wave height error| vs Biesel (%)",
                       "exact": True})
        print(f"{1e3 * spacing:g} mm: error {100 * error:+.2f} %, H at 2 m / H at 1 m "
              f"{row[12]}, wall {wall:.0f} s, CPU {cpu} s", flush=True)
    print("wrote", cr.write_points("wave_flume", points))


def main():
    parser = cr.script_arguments(__doc__, "validation/wave_flume")
    parser.add_argument("--periods", type=float, nargs="+", default=[1.0, 1.3])
    parser.add_argument("--spacings", type=float, nargs="+", default=[0.02, 0.01])
    parser.add_argument("--finer", type=float, nargs="*", default=[],
                        help="spacings run at the first period only (for time)")
    parser.add_argument("--previous", action="store_true",
                        help="also run the previous settings (cubic spline, h = 1.3 dx, A = 0.02) at 10 mm")
    parser.add_argument("--no-reflection", dest="reflection", action="store_false",
                        help="end the runs with the first window: no measured reflection")
    parser.add_argument("--points", action="store_true",
                        help="run the speed-accuracy series only (into OUT/points)")
    args = parser.parse_args()
    if args.points:
        write_points(os.path.join(args.out, "points"), args.reuse)
        return

    runs = [(dx, "the case", []) for dx in sorted(args.spacings, reverse=True)]
    finer = [(dx, "the case", []) for dx in sorted(args.finer, reverse=True)]
    if args.previous:
        runs.append((DEFAULT_SPACING, "previous: cubic spline, h = 1.3 dx, A = 0.02",
                     [f"fluid.{key}={value}" for key, value in PREVIOUS.items()]))
    fig, axes = plt.subplots(len(args.periods), 1, figsize=(13, 3.0 * len(args.periods)),
                             squeeze=False)
    rows = []
    for ax, period in zip(axes[:, 0], args.periods):
        late_window = None  # the runs that measured the reflection share it
        for spacing, label, settings in runs + (finer if period == args.periods[0] else []):
            name = f"T_{period:g}_dx_{spacing:g}" + ("_previous" if settings else "")
            # The previous settings are there for the height only.
            row, series, (t_from, t_to), late, height, error, theory, depth, _ = measure(
                os.path.join(args.out, name), period, spacing, label, settings, args.reuse,
                args.reflection and not settings)
            late_window = late or late_window
            rows.append(row)
            ax.plot(series["t"], 1e3 * (series["level0"] - depth), lw=0.8,
                    ls=":" if settings else "-",
                    label=f"dx = {1e3 * spacing:g} mm{', ' + label if settings else ''}: "
                          f"H = {1e3 * height:.1f} mm ({100 * error:+.1f} %)")
        ax.axvspan(t_from, t_to, color="C7", alpha=0.12, label="fitted window")
        if late_window:
            ax.axvspan(*late_window, color="C1", alpha=0.12, label="reflection window")
        for sign in (1, -1):
            ax.axhline(sign * 500 * theory, color="k", ls="--", lw=0.8,
                       label="Biesel: H/2 = %.1f mm" % (500 * theory) if sign > 0 else None)
        ax.set(xlabel="t (s)", ylabel="eta at x = 1 m (mm)",
               title=f"Wave flume, T = {period:g} s, S = {2e3 * AMPLITUDE:g} mm")
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    figure = os.path.join(cr.FIGURES, "wave_flume.png")
    fig.savefig(figure, dpi=110)
    table = cr.write_table(
        "wave_flume",
        ["spacing (mm)", "run", "period T (s)", "still depth d (mm)", "kd", "window (s)",
         "Biesel H (mm)", "cosph H (mm)", "error", "within 5 %",
         "incident H, gauges at 1 and 1.3 m (mm)", "reflected / incident, same window",
         "H at 2 m / H at 1 m",
         "Battjes Kr", "measured Kr (window)",
         "nearest neighbour / dx", "water particles", "wall time"],
        rows,
        preamble=f"First-order wave height at the level gauge x = {GAUGES[0]:g} m of "
                 f"cases/wave_flume.pbtxt (stroke S = {2e3 * AMPLITUDE:g} mm), against Biesel's "
                 "piston transfer function for the still depth of the run; the incident height "
                 "with the reflection taken out (two gauges, Goda & Suzuki 1976) over the same "
                 "window; the beach's reflection coefficient, expected (Battjes 1974) and "
                 "measured once its reflection is steady at the gauges. Produced by "
                 "`scripts/validate_wave_flume.py`; wall times as the launcher logged them, on a "
                 "shared machine: compare them within the table only.")
    print(open(table).read())
    print("wrote", figure)


if __name__ == "__main__":
    main()
