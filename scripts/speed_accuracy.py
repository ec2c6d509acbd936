#!/usr/bin/python3
"""Speed against accuracy: error against wall time for every validated run.

Reads the runs the validation scripts recorded (docs/results/*_points.json)
and draws, per scene, error against wall time on log-log axes, one line per
option. Two figures: docs/figures/speed_accuracy.png, the scenes measured
against an experiment (dam break, elastic plate: validate_dam_break.py,
validate_elastic_plate.py, validate_shell_coupled.py), and
docs/figures/speed_accuracy_exact.png, the scenes with an exact reference
(points marked "exact": the plate in vacuum, validate_shell.py and
continuum_plate_in_vacuum.py; the oscillating plate,
validate_oscillating_plate.py; the hydrostatic plate,
validate_hydrostatic_plate.py; the wave flume, validate_wave_flume.py
--points), where a costlier run must be more accurate.
The table of all runs is docs/results/speed_accuracy.md.
Pick the cheapest run that meets the accuracy you need.

usage: /usr/bin/python3 scripts/speed_accuracy.py
"""
import glob
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter, FuncFormatter, NullFormatter  # noqa: E402

import cosph_results as cr  # noqa: E402


def by_scene(points):
    """{error name (one panel per scene): {series: [runs by wall time]}}."""
    scenes = {}
    for point in points:
        scenes.setdefault(point["error_name"], {}).setdefault(point["series"], []).append(point)
    for series in scenes.values():
        for runs in series.values():
            runs.sort(key=lambda run: run["wall_s"])
    return scenes


def some_minor_labels(value, _position):
    """A minor tick's label at 2, 3 and 5 times a power of ten only: all eight
    crowd at the top of a decade."""
    mantissa = value / 10 ** math.floor(math.log10(value) + 1e-9)
    return f"{value:g}" if round(mantissa) in (2, 3, 5) else ""


def label_points(ax, runs):
    """Each run's label (its own last part) beside its point, leaving out a
    label whose text would land on one already placed: runs of one scene
    often sit on nearly the same point, and their colour and the legend
    still tell them apart."""
    placed = []
    ax.figure.canvas.draw()  # the axes' scales and limits, for display coordinates
    for run in sorted(runs, key=lambda run: (run["wall_s"], run["error"])):
        x, y = ax.transData.transform((run["wall_s"], run["error"]))
        if any(abs(x - u) < 70 and abs(y - v) < 10 for u, v in placed):
            continue
        placed.append((x, y))
        ax.annotate(run["label"].split(", ")[-1], (run["wall_s"], run["error"]),
                    fontsize=7, xytext=(4, 4), textcoords="offset points")


def draw(scenes, path, xlabel, legend_of=None):
    """One log-log panel per scene, two panels a row. With legend_of (series
    -> legend), series with the same legend share a colour across panels."""
    colours = {}
    columns = min(len(scenes), 2)
    rows = -(-len(scenes) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(5.5 * columns, 4.2 * rows), squeeze=False)
    for ax in axes.flat[len(scenes):]:
        ax.set_visible(False)
    for ax, (error_name, series) in zip(axes.flat, scenes.items()):
        if legend_of is None:
            colours = {}
        for name, runs in series.items():
            legend = legend_of(name) if legend_of else name
            colour = colours.setdefault(legend, f"C{len(colours)}")
            ax.plot([run["wall_s"] for run in runs], [run["error"] for run in runs], "o-",
                    color=colour, label=legend)
        # "scene: error (unit)" reads as the panel's title and its axis.
        title, _, ylabel = error_name.rpartition(": ")
        ax.set(xscale="log", yscale="log", xlabel=xlabel, ylabel=ylabel, title=title)
        label_points(ax, [run for runs in series.values() for run in runs])
        for axis, (low, high) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            axis.set_major_formatter(FormatStrFormatter("%g"))
            # Minor labels only where the axis spans too little for major
            # ones, fewer the more it spans; over decades they overlap.
            axis.set_minor_formatter(FormatStrFormatter("%g") if high / low < 3 else
                                     FuncFormatter(some_minor_labels) if high / low < 30 else
                                     NullFormatter())
        ax.legend(fontsize=8, framealpha=0.6)
    fig.tight_layout()
    fig.savefig(os.path.join(cr.FIGURES, path), dpi=110)


def error_text(point):
    unit = point["error_name"].split("(")[-1].rstrip(")")
    error = point["error"]
    return f"{error:.2f} {unit}" if error >= 0.1 else f"{error:.2g} {unit}"


def main():
    points = []
    for path in sorted(glob.glob(os.path.join(cr.RESULTS, "*_points.json"))):
        with open(path) as f:
            points += json.load(f)
    if not points:
        raise SystemExit("no docs/results/*_points.json: run the validation scripts first")
    measured = [p for p in points if not p.get("exact")]
    exact = [p for p in points if p.get("exact")]
    if measured:
        draw(by_scene(measured), "speed_accuracy.png", "wall time on 2 cores (s)")
    if exact:
        # The series are "scene, solid and option": the legend names the solid, the panel the scene.
        draw(by_scene(exact), "speed_accuracy_exact.png", "wall time, one thread (s)",
             legend_of=lambda name: name.split(", ", 1)[-1])

    def seconds(value):
        if value is None:
            return "-"
        return f"{value:.0f}" if value >= 10 else f"{value:.2g}"

    rows = [[point["series"], "exact" if point.get("exact") else "experiment", point["label"],
             seconds(point["wall_s"]), seconds(point.get("cpu_s")), error_text(point)]
            for point in sorted(points, key=lambda p: (bool(p.get("exact")), p["series"],
                                                       p["wall_s"]))]
    cr.write_table("speed_accuracy",
                   ["scene, option", "reference", "run", "wall time (s)", "CPU time (s)", "error"],
                   rows,
                   preamble="Error against wall time of the validation runs, by "
                            "`scripts/speed_accuracy.py` from what the validation scripts "
                            "recorded. Two scenes against experiments, where the error need not "
                            "fall with cost (the reference is not what a converged model should "
                            "reach): dam break (`validate_dam_break.py`), RMS relative error "
                            "of the front (T <= 3.1); elastic plate (`validate_elastic_plate.py`, "
                            "`validate_shell_coupled.py`), RMS error of the tip's x displacement "
                            "over the experimental points; coupled runs on 2 cores. Four scenes "
                            "with exact references, where a finer or costlier run must be more "
                            "accurate: the Antoci plate in vacuum (`validate_shell.py`, "
                            "`continuum_plate_in_vacuum.py`), |period error| against the "
                            "Timoshenko beam; the oscillating plate "
                            "(`validate_oscillating_plate.py`), |period error| against "
                            "thin-plate theory, solids alone on one thread; and two with water, "
                            "each solver on one thread (the hydrostatic plate's three processes "
                            "share the 2 cores): the hydrostatic plate "
                            "(`validate_hydrostatic_plate.py`), |error| of the settled mid-span "
                            "deflection against the Timoshenko beam, the shell with the water "
                            "refined, the plate refined, or both (the run: the water's spacing "
                            "+ the plate's, span L over the particles along); the wave flume "
                            "(`validate_wave_flume.py --points`), |error| of the first-order "
                            "wave height 1 m from the piston against Biesel's linear wave-maker "
                            "theory, the fluid alone. On the hydrostatic plate every refinement "
                            "of the coarse runs cuts the error, but a costlier run is not always "
                            "more accurate: below a few tenths of a per cent the error is within "
                            "the uncertainty of its own settled reading (the spread over windows "
                            "in docs/results/hydrostatic_plate.md; the deflection swings about "
                            "its static value with the water column's acoustic mode). On the wave "
                            "flume the error falls with cost, "
                            "but slowly: it is about the height the waves lose over a metre "
                            "of flume (`validate_wave_flume.py`'s H at 2 m / H at 1 m), which "
                            "SPH's damping sets and refinement reduces only slowly. "
                            "The figures plot "
                            "the wall time; the CPU time (the solver's, where the script "
                            "recorded it; the coupled runs': all their processes') is given too, "
                            "since wall times come from a shared "
                            "machine: runs made at the same time slow each other.")
    print(open(os.path.join(cr.RESULTS, "speed_accuracy.md")).read())


if __name__ == "__main__":
    main()
