#!/usr/bin/python3
"""The dam break's wall-pressure noise against the artificial sound speed c0 (issue 38).

Weakly compressible water carries sound at c0, a number chosen far below real
water's 1480 m/s so that the step, about h / c0, stays affordable. The
surge's impact on the far wall sets the water ringing, and the dissipation
options damp long sound waves only weakly (as (k h)^2); the sound's share of
the pressure falls with the Mach number |u| / c0. Whether the sound is what
the issue's noise measure reads after the impact (the RMS about the running
mean over 0.1 sqrt(H/g) = 17 ms, t = 0.35-0.55 s) is what this script
measures: the dam break (cases/dam_break.pbtxt, to its end time) with the
default water at three sound speeds:
  - 10 sqrt(2 g H), the code's rule (Monaghan 1994): ten times the speed of
    a fall from the column's height;
  - 20 sqrt(g H), ten times Ritter's front speed 2 sqrt(g H), as DualSPHysics'
    example cases set it (coefsound 20 times its speedsystem, sqrt(g H) by
    default);
  - 2 x 10 sqrt(2 g H), about ten times the largest speed the runs reach,
    which is Monaghan's own condition (Ma = |u|max / c0 <= 0.1);
and the same water at h = 2 dx (the quiet option of pressure_noise.py) at
the code's c0, at 8 and 4 mm, each pn.REALISATIONS times over, and reports the far-wall
sensor's mean and noise, the far wall's force noise, the front's error
against Martin & Moyce, the largest speed and Mach number, and the cost: a
step does the same work at any c0 (the same pairs and terms), so the cost
per simulated second is the steps per simulated second, measured from the
runs' dt column, and the runs' CPU time is given too.
Writes docs/results/sound_speed_noise.md and docs/figures/sound_speed_noise.png.

usage: /usr/bin/python3 scripts/sound_speed_noise.py [--out DIR] [--reuse]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cosph_results as cr  # noqa: E402
import pressure_noise as pn  # noqa: E402
import validate_dam_break as dam  # noqa: E402

# The default water spelled out, so that the table names it whatever the
# code's default becomes (docs/physics.md, "Choice of water").
DEFAULT_WATER = cr.water(**pn.RIEMANN, **pn.WENDLAND, wall_friction="normal")
RULE_C0 = pn.RULE_C0
# The same water at h = 2 dx, the other way to a quiet wall (pressure_noise.py),
# at the rule's c0: its point on the same chart.
QUIET_WATER = cr.water(**pn.RIEMANN, **pn.WENDLAND_2DX, wall_friction="normal")
SOUND_SPEEDS = [  # (key, rule, c0 in m/s, water)
    ("rule", "10 sqrt(2 g H), the code's rule", RULE_C0, DEFAULT_WATER),
    ("ritter", "20 sqrt(g H): 10 x Ritter's front speed", 20 * np.sqrt(dam.G * dam.H),
     DEFAULT_WATER),
    ("double", "2 x 10 sqrt(2 g H): about 10 x the largest speed reached", 2 * RULE_C0,
     DEFAULT_WATER),
    ("quiet", "10 sqrt(2 g H), the code's rule; the water at h = 2 dx", RULE_C0, QUIET_WATER),
]
SPACINGS = pn.SPACINGS
# Each row is pn.REALISATIONS runs whose c0 differs by parts per million
# (pn.realisation): their median and range.
TARGET = 0.05  # the far-wall noise, rho0 g H


def run(out, settings, reuse):
    """(timeseries, CPU seconds of the run's processes as the launcher logged them)."""
    series = pn.run(out, settings, reuse)
    return series, sum(cr.logged_cpu_times(out).values()) or None


def measure(series, cpu, experiment):
    simulated = series["t"][-1] - series["t"][0]
    return {"far_wall": dam.sensor_noise(series, "probe1"),
            "force": pn.far_wall_force_noise(series),
            "front": dam.front_error(series, experiment)[0],
            "fastest": float(np.max(series["max_speed"])),
            "steps_per_s": pn.steps_per_second(series),
            "cpu_per_s": cpu / simulated if cpu else None}


def median(samples, pick):
    return float(np.median([pick(sample) for sample in samples]))


def draw(rows, signals, path):
    fig, (cost_ax, signal_ax) = plt.subplots(1, 2, figsize=(12, 4.8))
    for k, dx in enumerate(SPACINGS):
        reference = median(rows[("rule", dx)], lambda r: r["cpu_per_s"])
        for keys, style, label in (([key for key, *_ in SOUND_SPEEDS if key != "quiet"], "o-",
                                    f"{dx * 1e3:g} mm, c0 raised"),
                                   (["quiet"], "s", f"{dx * 1e3:g} mm, h = 2 dx")):
            cost = [median(rows[(key, dx)], lambda r: r["cpu_per_s"]) / reference
                    for key in keys]
            noise = [[r["far_wall"][1] for r in rows[(key, dx)]] for key in keys]
            middle = [float(np.median(n)) for n in noise]
            cost_ax.errorbar(cost, middle,
                             yerr=[[m - min(n) for m, n in zip(middle, noise)],
                                   [max(n) - m for m, n in zip(middle, noise)]],
                             fmt=style, color=f"C{k}", capsize=3, label=label)
            for key, x, y in zip(keys, cost, middle):
                cost_ax.annotate(f"c0 {rows[(key, dx)][0]['c0']:.1f}", (x, y), fontsize=7,
                                 xytext=(4, 4), textcoords="offset points")
    cost_ax.axhline(TARGET, color="k", ls="--", lw=0.8, label="issue's target")
    cost_ax.set(xlabel="CPU time per simulated second / the default water's",
                ylabel="far-wall sensor noise / (rho0 g H)",
                title=f"Dam break: median and range of {pn.REALISATIONS} runs")
    cost_ax.legend(fontsize=8)
    for k, (label, t, p) in enumerate(signals):
        signal_ax.plot(t, p, lw=0.7, color=f"C{k}", label=label)
    signal_ax.axvspan(*dam.AFTER_IMPACT, color="0.9")
    signal_ax.set(xlim=(0.3, 0.6), ylim=(0, 1.2), xlabel="t (s)",
                  ylabel="far-wall sensor / (rho0 g H)", title="The sensor at 4 mm, one run each")
    signal_ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    args = cr.script_arguments(__doc__, "sound_speed_noise").parse_args()
    experiment = cr.reference("martin_moyce_n2_front.csv")
    rows, signals = {}, []
    for key, _, c0, water in SOUND_SPEEDS:
        for dx in SPACINGS:
            rows[(key, dx)] = []
            # The rule's rows leave c0 to the code: the first is the case's own run.
            given = [] if key in ("rule", "quiet") else [f"fluid.sound_speed={float(c0)!r}"]
            for k in range(pn.REALISATIONS):
                series, cpu = run(os.path.join(args.out, f"{key}_dx_{dx:g}_{k}"),
                                  pn.realisation(water + given + [f"fluid.spacing={dx}"], k),
                                  args.reuse)
                rows[(key, dx)].append({**measure(series, cpu, experiment), "c0": c0})
                print(key, dx, k, rows[(key, dx)][-1], flush=True)
                if dx == 0.004 and k == 0 and key != "quiet":
                    window = (series["t"] >= 0.3) & (series["t"] <= 0.6)
                    signals.append((f"c0 = {c0:.1f} m/s", series["t"][window],
                                    series["probe1_pressure"][window] / dam.RHO0_G_H))
    table = []
    for key, rule, c0, _ in SOUND_SPEEDS:
        for dx in SPACINGS:
            samples, base = rows[(key, dx)], rows[("rule", dx)]
            noise = [r["far_wall"][1] for r in samples]
            steps = median(samples, lambda r: r["steps_per_s"])
            cpu = ""
            if all(r["cpu_per_s"] for r in samples + base):
                cpu_per_s = median(samples, lambda r: r["cpu_per_s"])
                cpu = f"{cpu_per_s:.1f} ({cpu_per_s / median(base, lambda r: r['cpu_per_s']):.2f})"
            fastest = median(samples, lambda r: r["fastest"])
            table.append([rule + (cr.DEFAULT_WATER_MARK if key == "rule" else ""),
                          f"{c0:.1f}", f"{dx * 1e3:g}", f"{fastest:.2f} ({fastest / c0:.2f})",
                          f"{median(samples, lambda r: r['far_wall'][0]):.3f}",
                          f"{np.median(noise):.3f} ({min(noise):.3f}-{max(noise):.3f})",
                          f"{median(samples, lambda r: r['force'][1]):.3f}",
                          f"{100 * median(samples, lambda r: r['front']):.1f} %",
                          f"{steps:.0f} ({steps / median(base, lambda r: r['steps_per_s']):.2f})",
                          cpu])
    figure = os.path.join(cr.FIGURES, "sound_speed_noise.png")
    draw(rows, signals, figure)
    path = cr.write_table(
        "sound_speed_noise",
        ["c0 rule", "c0 (m/s)", "spacing (mm)", "largest speed (m/s) (Mach number)",
         "far-wall sensor: mean", "noise: median (range)", "far-wall force: noise",
         "front: RMS rel. error", "steps per simulated s (/ the rule's)",
         "CPU s per simulated s (/ the rule's)"],
        table,
        preamble="The dam break (`cases/dam_break.pbtxt`) with the default water (Riemann, "
                 "Wendland C2 at h = 1.5 dx, walls damping along their normal) at three "
                 "artificial sound speeds c0 (H = 0.288 m), and the same water at h = 2 dx, "
                 "the quiet option of the pressure noise table, at the code's c0; each row "
                 f"the median of {pn.REALISATIONS} runs whose c0 differs by parts per million "
                 "(a run is one sample of a chaotic flow): the largest particle speed and its "
                 "Mach number |u|max / c0; the far-wall sensor after the impact "
                 f"(t = {dam.AFTER_IMPACT[0]:g}-{dam.AFTER_IMPACT[1]:g} s), its mean and noise "
                 "(RMS about the running mean over 0.1 sqrt(H/g); median and range of the "
                 "runs) over rho0 g H, and the far wall's force noise over rho0 g H^2; the "
                 "front's RMS relative error against Martin & Moyce (T <= 3.1); and the cost "
                 "(a step's work does not change with c0, but does with h): steps per "
                 "simulated second (from the runs' dt) and the runs' CPU time per simulated "
                 "second, on the shared machine. Produced by `scripts/sound_speed_noise.py`.")
    print(open(path).read())
    print("wrote", figure)


if __name__ == "__main__":
    main()
