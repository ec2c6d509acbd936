#!/usr/bin/python3
"""Speed against accuracy: error against wall time for every validated run.

Reads the runs the validation scripts recorded (docs/results/*_points.json,
written by validate_dam_break.py and validate_elastic_plate.py) and draws, per
scene, error against wall time on log-log axes, one line per option:
docs/figures/speed_accuracy.png, with the table docs/results/speed_accuracy.md.
Pick the cheapest run that meets the accuracy you need.

usage: /usr/bin/python3 scripts/speed_accuracy.py
"""
import glob
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter  # noqa: E402

import cosph_results as cr  # noqa: E402


def main():
    points = []
    for path in sorted(glob.glob(os.path.join(cr.RESULTS, "*_points.json"))):
        with open(path) as f:
            points += json.load(f)
    if not points:
        raise SystemExit("no docs/results/*_points.json: run the validation scripts first")
    scenes = {}  # error name (one panel per scene) -> series -> points
    for point in points:
        scenes.setdefault(point["error_name"], {}).setdefault(point["series"], []).append(point)

    fig, axes = plt.subplots(1, len(scenes), figsize=(5.5 * len(scenes), 4.2), squeeze=False)
    for ax, (error_name, series) in zip(axes[0], scenes.items()):
        for k, (name, runs) in enumerate(series.items()):
            runs = sorted(runs, key=lambda run: run["wall_s"])
            ax.plot([run["wall_s"] for run in runs], [run["error"] for run in runs], "o-",
                    color=f"C{k}", label=name)
            for run in runs:
                ax.annotate(run["label"].split(", ")[-1], (run["wall_s"], run["error"]),
                            fontsize=7, xytext=(4, 4), textcoords="offset points")
        ax.set(xscale="log", yscale="log", xlabel="wall time on 2 cores (s)", ylabel=error_name)
        for axis in (ax.yaxis,):
            axis.set_major_formatter(FormatStrFormatter("%g"))
            axis.set_minor_formatter(FormatStrFormatter("%g"))
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(cr.FIGURES, "speed_accuracy.png"), dpi=110)

    rows = [[point["series"], point["label"], f"{point['wall_s']:.0f}",
             f"{point['error']:.2f} {point['error_name'].split('(')[-1].rstrip(')')}"]
            for point in sorted(points, key=lambda p: (p["series"], p["wall_s"]))]
    cr.write_table("speed_accuracy", ["scene, option", "run", "wall time (s)", "error"], rows,
                   preamble="Error against wall time of the validation runs, by "
                            "`scripts/speed_accuracy.py` from what `validate_dam_break.py`, "
                            "`validate_elastic_plate.py` and `validate_shell_coupled.py` "
                            "recorded. Dam break: RMS relative error "
                            "of the front (T <= 3.1); elastic plate: RMS error of the tip's x "
                            "displacement over the experimental points. Wall times come from "
                            "a shared machine: runs made at the same time slow each other.")
    print(open(os.path.join(cr.RESULTS, "speed_accuracy.md")).read())


if __name__ == "__main__":
    main()
