#!/usr/bin/python3
"""Pressure noise against cost per step: the dissipation options side by side (issue 38).

For each option of fluid.dissipation, fluid.kernel and fluid.shifting (and the
combinations in OPTIONS), the dam break (cases/dam_break.pbtxt, to its end
time) at 8 mm, at 4 mm too for the options quieter at 8 mm than delta-SPH
(the cheap run sorts the candidates), each REALISATIONS times with sound
speeds differing by parts per million (a run is one sample of a chaotic
flow: the medians, and the noise's range), and the still tank (the tank
filled to H, 8 mm):
  - the far-wall sensor's (probe1) mean and noise after the impact, and the
    floor sensor's (probe0), as validate_dam_break.py measures them: over
    t = 0.35-0.55 s, the noise being the RMS about the running mean over
    0.1 sqrt(H/g), both over rho0 g H;
  - the front's RMS relative error against Martin & Moyce (T <= 3.1);
  - the fluid's cost per step: build/bin/cosph-bench on one thread, CPU time of
    the thread (--cpu), the options taken in turn, REPEATS times over, median.
Writes docs/results/pressure_noise.md and docs/figures/pressure_noise.png.

With --convergence instead: the far-wall sensor's mean and noise, the far
wall's force and the front's error for the quiet options at 4, 2 and (the
earlier default, delta-SPH, and the quietest option) 1.5 mm, the runs
ending just after the window: whether delta-SPH's mean, the issue's
reference, is converged.
Writes docs/results/sensor_convergence.md.

usage: /usr/bin/python3 scripts/pressure_noise.py [--out DIR] [--reuse] [--repeats N]
       /usr/bin/python3 scripts/pressure_noise.py --convergence [--out DIR] [--reuse]
"""
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cosph_results as cr  # noqa: E402
import validate_dam_break as dam  # noqa: E402

# The Wendland C2 kernel with h = 1.5 dx: at the cubic spline's 1.3 its
# lattice sum of x (x) grad W is 0.974 I, and a still tank reads 2.7 % over
# hydrostatic pressure (docs/physics.md, "Kernel").
WENDLAND = {"kernel": "wendland_c2", "h_factor": 1.5}
# h = 2 dx: Colagrossi et al. 2013's rule for free-surface gravity flows, as the
# wave flume uses (cases/wave_flume.pbtxt); the dam break's walls are >= 2h deep
# for it at 8 mm and finer.
WENDLAND_2DX = {"kernel": "wendland_c2", "h_factor": 2.0}
RIEMANN = {"dissipation": "riemann"}
SHIFTING = {"shifting": "delta_plus"}
OPTIONS = [  # (key, label, settings): each water spelled out (cr.water)
    ("delta_sph", "delta-SPH (Marrone et al. 2011), the earlier default", cr.water()),
    ("fourtakas", "hydrostatic-free diffusion (Fourtakas et al. 2019)",
     cr.water(dissipation="fourtakas")),
    ("riemann", "Riemann solver with limiter (Zhang, Hu & Adams 2017)", cr.water(**RIEMANN)),
    ("wendland", "delta-SPH, Wendland C2 kernel", cr.water(**WENDLAND)),
    ("shifting", "delta-plus-SPH: delta-SPH and shifting (Sun et al. 2017)",
     cr.water(**SHIFTING)),
    ("riemann_wendland", "Riemann, Wendland C2 kernel", cr.water(**RIEMANN, **WENDLAND)),
    ("riemann_shifting", "Riemann and delta-plus shifting", cr.water(**RIEMANN, **SHIFTING)),
    ("wendland_2dx", "delta-SPH, Wendland C2, h = 2 dx", cr.water(**WENDLAND_2DX)),
    ("riemann_wendland_2dx", "Riemann, Wendland C2, h = 2 dx",
     cr.water(**RIEMANN, **WENDLAND_2DX)),
]
# Timed only: the Wendland C2 kernel at the cubic spline's h, the same
# support and pairs, to tell the kernel's own cost from that of its larger h
# (not an option: its still tank reads 2.7 % high, docs/physics.md, "Kernel").
# And the default water itself: the Riemann row's water with walls damping
# along their normal only, whose runs validate_wall_pressure.py makes
# (docs/results/wall_friction_front.md); the rule is on its step.
COST_ONLY = [("wendland_1.3dx", "Wendland C2 at h = 1.3 dx, the cubic spline's (timed only)",
              cr.water(kernel="wendland_c2")),
             ("default_water", "Riemann, Wendland C2 kernel, walls damping along their normal "
              "(timed only; its runs: docs/results/wall_friction_front.md)"
              + cr.DEFAULT_WATER_MARK,
              cr.water(**RIEMANN, **WENDLAND, wall_friction="normal"))]
SPACINGS = [0.008, 0.004]
BENCH_STEPS = 400
# A run is one sample of a chaotic flow: at 4 mm the same water's noise
# ranged over a factor of two between runs whose sound speed differed by
# parts per million (docs/results/sound_speed_noise.md). Each dam-break row
# is REALISATIONS runs: the first as the settings give it, the others with
# c0 = the code's rule, 10 sqrt(2 g H), times 1 + k PERTURBATION, a change at
# the level of round-off that the flow then amplifies; the table gives
# their medians and the noise's range.
REALISATIONS = 4
PERTURBATION = 1e-6
RULE_C0 = 10 * np.sqrt(2 * dam.G * dam.H)  # m/s (fluid/src/fluid_parameters.cpp)
# The convergence check: (key of OPTIONS, spacings). The finest spacing for the
# earlier default and the quietest option only: a 1.5 mm run takes ~20 min of the
# shared machine.
CONVERGENCE = [("delta_sph", [0.004, 0.002, 0.0015]), ("riemann", [0.004, 0.002]),
               ("riemann_wendland", [0.004, 0.002]), ("wendland_2dx", [0.004, 0.002]),
               ("riemann_wendland_2dx", [0.004, 0.002, 0.0015])]


def run(out, settings, reuse):
    """The run's timeseries, running it unless REUSE finds it already there."""
    series_path = os.path.join(out, "timeseries.csv")
    if not (reuse and os.path.exists(series_path)):
        cr.run_case("dam_break", out, settings + [f"run.output_interval={dam.OUTPUT_INTERVAL}"])
    return cr.read_csv(series_path)


def realisation(settings, k, rule_c0=RULE_C0):
    """The settings of run K of a row: as given for k = 0, else with the sound
    speed (the code's rule unless the settings give one) perturbed."""
    if k == 0:
        return list(settings)
    c0 = float(cr.setting(settings, "fluid.sound_speed") or 0) or rule_c0
    return list(settings) + [f"fluid.sound_speed={c0 * (1 + k * PERTURBATION)!r}"]


def row_of(samples):
    """One row from its runs' measures: medians, and the range of the far-wall
    sensor's noise."""
    def middle(pick):
        return float(np.median([pick(sample) for sample in samples]))
    noise = [sample["far_wall"][1] for sample in samples]
    return {"far_wall": (middle(lambda r: r["far_wall"][0]), float(np.median(noise))),
            "far_wall_range": (min(noise), max(noise)),
            "force": (middle(lambda r: r["force"][0]), middle(lambda r: r["force"][1])),
            "floor": (middle(lambda r: r["floor"][0]), middle(lambda r: r["floor"][1])),
            "front": middle(lambda r: r["front"]),
            "spray": max(sample["spray"] for sample in samples),
            "steps_per_s": middle(lambda r: r["steps_per_s"])}


def far_wall_force_noise(series):
    """(mean, noise) of the far wall's horizontal force (fluid.walls[2]) after
    the impact, over rho0 g H^2: the load the whole wall carries, measured as
    the sensors are."""
    return cr.pressure_noise(series["t"], series["wall2_force_x"], dam.NOISE_WINDOW,
                             dam.RHO0_G_H * dam.H, *dam.AFTER_IMPACT)


def bench_ms_per_step(settings, spacing, steps=BENCH_STEPS):
    """(ms per step of the fluid alone, one thread, the thread's CPU time;
    the pairs a step visits at the end)."""
    command = [os.path.join(cr.REPO, "build", "bin", "cosph-bench"), "--fluid", "--cpu",
               "--threads", "1", "--spacing", str(spacing), "--steps", str(steps)]
    for setting in settings:
        command += ["--set", setting]
    output = subprocess.run(command, check=True, stdout=subprocess.PIPE, text=True).stdout
    row = [line for line in output.splitlines() if line.startswith("fluid")][0]
    return float(row.split()[3]), int(row.split()[5])


def costs(repeats, spacing):
    """{key: (median ms per step, median of its ratios to delta-SPH's, lowest
    ratio, highest, pairs a step visits)}: each option timed in REPEATS pairs
    with delta-SPH (the earlier default), the two alternating, so that the shared machine's load
    falls on both alike."""
    default = []
    result = {}
    for key, _, settings in OPTIONS + COST_ONLY:
        if key == "delta_sph":
            continue
        times, ratios = [], []
        for _ in range(repeats):
            default.append(bench_ms_per_step(OPTIONS[0][2], spacing))
            times.append(bench_ms_per_step(settings, spacing))
            ratios.append(times[-1][0] / default[-1][0])
        result[key] = (float(np.median([ms for ms, _ in times])), float(np.median(ratios)),
                       min(ratios), max(ratios), times[-1][1])
    result["delta_sph"] = (float(np.median([ms for ms, _ in default])), 1.0, 1.0, 1.0,
                           default[-1][1])
    return result


def steps_per_second(series):
    """Steps per simulated second over the whole run, from its time step
    column sampled every output interval."""
    t, dt = series["t"], series["dt"]
    return float(np.sum(np.diff(t) / dt[1:]) / (t[-1] - t[0]))


def draw(rows, cost, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 6.4))
    for ax, (measure, ylabel) in zip(axes, (("far_wall", "far-wall sensor noise / (rho0 g H)"),
                                            ("force", "far-wall force noise / (rho0 g H^2)"))):
        for k, (key, label, _) in enumerate(OPTIONS):
            relative = cost[key][1]
            for dx, marker in zip(SPACINGS, ("o", "s")):
                if (key, dx) not in rows:
                    continue
                ax.plot(relative, rows[(key, dx)][measure][1], marker, color=f"C{k}", ms=8,
                        label=f"{label}, {dx * 1e3:g} mm")
        if measure == "far_wall":
            ax.axhline(0.05, color="0.5", ls="--", lw=0.8, label="target: 0.05 rho0 g H")
        ax.axvline(1.3, color="0.5", ls=":", lw=0.8, label="at most 30 % slower per step")
        ax.set_yscale("log")
        ax.set(xlabel=f"cost per step / delta-SPH's (fluid alone, {SPACINGS[-1] * 1e3:g} mm, "
                      "one thread)", ylabel=ylabel)
    axes[0].set_title("Dam break after the impact: the sensor 16 mm up the far wall", fontsize=9)
    axes[1].set_title("... and the whole far wall's load", fontsize=9)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=6.5)
    fig.tight_layout(rect=(0, 0.24, 1, 1))
    fig.savefig(path, dpi=110)


def convergence(args, experiment):
    """The sensor's and the wall force's means against the spacing for the
    quiet options: whether delta-SPH's mean at 4 mm (the earlier default's,
    the issue's reference) is converged, and where the options' means go."""
    labels = {key: (label, settings) for key, label, settings in OPTIONS}
    end = dam.AFTER_IMPACT[1] + 0.01
    runs = [(key, dx) for key, spacings in CONVERGENCE for dx in spacings]
    results = {}
    for key, dx in sorted(runs, key=lambda run: -run[1]):  # the cheap runs first
        folder = os.path.join(args.out, "convergence", f"{key}_dx_{dx:g}")
        os.makedirs(folder, exist_ok=True)
        series_path = os.path.join(folder, "timeseries.csv")
        if not (args.reuse and os.path.exists(series_path)):
            wall = cr.run_case("dam_break", folder, labels[key][1] + [
                f"fluid.spacing={dx}", f"run.output_interval={dam.OUTPUT_INTERVAL}",
                "run.snapshot_interval=1", f"run.end_time={end}"], timeout=4 * 3600)
            print(key, dx, f"{wall:.0f} s wall", flush=True)
        series = cr.read_csv(series_path)
        results[(key, dx)] = [f"{value:.3f}" for value in (
            *dam.sensor_noise(series, "probe1"), far_wall_force_noise(series)[0])] + [
            f"{100 * dam.front_error(series, experiment)[0]:.1f} %"]
        print(key, dx, results[(key, dx)], flush=True)
    rows = [[labels[key][0], f"{dx * 1e3:g}", *results[(key, dx)]] for key, dx in runs]
    path = cr.write_table(
        "sensor_convergence",
        ["option", "spacing (mm)", "far-wall sensor: mean", "noise", "far-wall force: mean",
         "front: RMS rel. error"],
        rows,
        preamble="The far-wall sensor's mean and noise after the impact (t = "
                 f"{dam.AFTER_IMPACT[0]:g}-{dam.AFTER_IMPACT[1]:g} s, over rho0 g H), the far "
                 "wall's force (over rho0 g H^2) and the front's RMS relative error against "
                 "Martin & Moyce (T <= 3.1) against the spacing, the runs ending at "
                 f"t = {end:g} s. Produced by `scripts/pressure_noise.py --convergence`.")
    print(open(path).read())


def main():
    parser = cr.script_arguments(__doc__, "pressure_noise")
    parser.add_argument("--repeats", type=int, default=5,
                        help="pairs (option, delta-SPH) of the cost measurement per option")
    parser.add_argument("--convergence", action="store_true",
                        help="only the convergence check of the sensor's mean (CONVERGENCE)")
    args = parser.parse_args()

    experiment = cr.reference("martin_moyce_n2_front.csv")
    if args.convergence:
        convergence(args, experiment)
        return
    rows = {}
    for key, label, settings in OPTIONS:
        for dx in SPACINGS:
            coarse = rows.get((key, SPACINGS[0]))
            if dx != SPACINGS[0] and key != "delta_sph" and not (
                    coarse["far_wall"][1] < rows[("delta_sph", SPACINGS[0])]["far_wall"][1]):
                continue  # not quieter than delta-SPH at 8 mm: not a candidate
            samples = []
            for k in range(REALISATIONS):
                # The first run keeps the folder other scripts read.
                folder = os.path.join(args.out, f"{key}_dx_{dx:g}" + (f"_{k}" if k else ""))
                os.makedirs(folder, exist_ok=True)
                series = run(folder, realisation(settings + [f"fluid.spacing={dx}"], k),
                             args.reuse)
                samples.append({"far_wall": dam.sensor_noise(series, "probe1"),
                                "force": far_wall_force_noise(series),
                                "floor": dam.sensor_noise(series, "probe0"),
                                "front": dam.front_error(series, experiment)[0],
                                "spray": cr.spray_removed(series),
                                "steps_per_s": steps_per_second(series)})
                print(key, dx, k, samples[-1], flush=True)
            rows[(key, dx)] = row_of(samples)
        os.makedirs(os.path.join(args.out, f"{key}_still_tank"), exist_ok=True)
        series = run(os.path.join(args.out, f"{key}_still_tank"), settings + dam.STILL_TANK,
                     args.reuse)
        rows[(key, "still")] = {"floor": dam.sensor_noise(series, "probe0")}
    cost = costs(args.repeats, SPACINGS[-1])
    print("ms per step, its ratio to delta-SPH's (median, lowest, highest):", cost, flush=True)

    def per_step(key):
        ms, ratio, lowest, highest, _ = cost[key]
        return f"{ms:.3f} ({ratio:.2f}; {lowest:.2f}-{highest:.2f})"

    def pairs(key):
        return f"{cost[key][4]} ({cost[key][4] / cost['delta_sph'][4]:.2f})"

    def per_simulated_second(key):
        """CPU seconds per simulated second at the finest spacing: the cost per
        step times the steps the run took (a larger h takes longer steps)."""
        fine, default = rows.get((key, SPACINGS[-1])), rows[("delta_sph", SPACINGS[-1])]
        if fine is None:
            return ""
        ratio = cost[key][1] * fine["steps_per_s"] / default["steps_per_s"]
        return f"{cost[key][0] * fine['steps_per_s'] / 1e3:.1f} ({ratio:.2f})"

    table = []
    for key, label, _ in OPTIONS:
        for dx in SPACINGS:
            finest = dx == SPACINGS[-1]
            if (key, dx) not in rows:
                table.append([label, f"{dx * 1e3:g}", "not run: no quieter than delta-SPH at "
                              f"{SPACINGS[0] * 1e3:g} mm", "", "", "", "", "", "", "",
                              per_step(key) if finest else "", pairs(key) if finest else "",
                              ""])
                continue
            r = rows[(key, dx)]
            table.append([label, f"{dx * 1e3:g}", f"{r['far_wall'][0]:.3f}",
                          f"{r['far_wall'][1]:.3f} ({r['far_wall_range'][0]:.3f}-"
                          f"{r['far_wall_range'][1]:.3f})",
                          f"{r['force'][0]:.3f}", f"{r['force'][1]:.3f}",
                          f"{r['floor'][0]:.3f}", f"{r['floor'][1]:.3f}",
                          f"{100 * r['front']:.1f} %", r["spray"],
                          per_step(key) if finest else "", pairs(key) if finest else "",
                          per_simulated_second(key) if finest else ""])
        still = rows[(key, "still")]["floor"]
        table.append([label, "still tank, 8", "", "", "", "", f"{still[0]:.3f}", f"{still[1]:.3f}",
                      "", "", "", "", ""])
    for key, label, _ in COST_ONLY:
        table.append([label, f"{SPACINGS[-1] * 1e3:g}", "", "", "", "", "", "", "", "",
                      per_step(key), pairs(key), ""])
    figure = os.path.join(cr.FIGURES, "pressure_noise.png")
    draw(rows, cost, figure)
    path = cr.write_table(
        "pressure_noise",
        ["option", "spacing (mm)", "far-wall sensor: mean", "noise (range)",
         "far-wall force: mean", "noise", "floor sensor: mean", "noise",
         "front: RMS rel. error", "water left as spray",
         f"ms per step at {SPACINGS[-1] * 1e3:g} mm (/ delta-SPH: median; range)",
         "pairs a step visits (/ delta-SPH)",
         "CPU s per simulated s (/ delta-SPH)"],
        table,
        preamble="The dam break's pressure sensors after the impact (t = "
                 f"{dam.AFTER_IMPACT[0]:g}-{dam.AFTER_IMPACT[1]:g} s) for each option of "
                 "`fluid.dissipation`, `fluid.kernel` and `fluid.shifting`: mean, and noise as the RMS about the running mean over "
                 f"0.1 sqrt(H/g) = {1e3 * dam.NOISE_WINDOW:.0f} ms, both over rho0 g H "
                 "(H = 0.288 m), and the far wall's horizontal force likewise over "
                 "rho0 g H^2, at 4 mm for the options quieter at 8 mm than delta-SPH, the "
                 f"earlier default; each row the medians of {REALISATIONS} runs whose sound "
                 "speed differs by parts per million (a run is one sample of a chaotic flow), "
                 "with the range of the far-wall sensor's noise over them; "
                 "the front's RMS relative error against Martin & Moyce "
                 "(T <= 3.1); the fluid's cost per step alone (`cosph-bench --cpu`, one thread, "
                 f"{BENCH_STEPS} steps; each option in {args.repeats} pairs with delta-SPH, "
                 "the two alternating on the shared machine: median ms, and the median, lowest "
                 "and highest of the pairs' ratios; the neighbour pairs a step visits, which the "
                 "cost follows), and per simulated second (the cost per step "
                 "times the steps the 4 mm run took: a larger h takes longer steps). "
                 "Every water here meets the walls with their friction (`fluid.wall_friction` "
                 "\"dissipation\"), the earlier default; the default water, Riemann with the "
                 "Wendland C2 kernel at h = 1.5 dx and walls damping along their normal only, "
                 "is that row's water with the walls of docs/results/wall_friction_front.md "
                 "(docs/physics.md, \"Choice of water\"). "
                 "Produced by `scripts/pressure_noise.py`.")
    print(open(path).read())
    print("wrote", figure)


if __name__ == "__main__":
    main()
