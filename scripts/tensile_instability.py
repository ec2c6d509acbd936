#!/usr/bin/python3
"""Where the method fails: the tensile instability of SPH solids.

Runs the oscillating plate (cases/oscillating_plate.pbtxt) at a large
amplitude three times: with the solver's default (linear) velocity gradient
without and with the Gray-Monaghan artificial stress
(solid.artificial_stress.enabled), and with the quadratic velocity gradient
(the small-amplitude case's choice) with artificial stress. It draws the
particles of the runs side by side at a few times from their HDF5 snapshots,
coloured by the von Mises stress: docs/figures/tensile_instability.png, with the outcome of each run in
docs/results/tensile_instability.md (README marker results:tensile_instability).

A run that blows up is part of the result, not a failure of this script: its
last good snapshot (solid_last_good.h5) is drawn and the error is reported.

Usage: scripts/tensile_instability.py [--out DIR] [--tip-speed V] [--end-time T] [--spacing DX]
                                     [--plot-only]
COSPH_BIN names the folder of cosph-solid-jaumann (default build/bin).
"""
import argparse
import glob
import os
import pathlib
import sys

import h5py
import numpy as np
import matplotlib

import cosph_results as cr

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "oscillating_plate.pbtxt"
SOLVER = pathlib.Path(os.environ.get("COSPH_BIN", ROOT / "build" / "bin")) / "cosph-solid-jaumann"


RUNS = [  # (velocity gradient, artificial stress)
    ("linear", False),
    ("linear", True),
    ("quadratic", True),
]


def label_of(gradient, artificial_stress):
    return f"{gradient} gradient, artificial stress {'on' if artificial_stress else 'off'}"


def run(out, gradient, artificial_stress, args):
    command = [str(SOLVER), "--case", str(CASE), "--out", str(out),
               "--set", f"solid.velocity_gradient={gradient}",
               "--set", f"solid.initial_velocity.tip_speed={args.tip_speed}",
               "--set", f"solid.artificial_stress.enabled={'true' if artificial_stress else 'false'}",
               "--set", f"run.end_time={args.end_time}",
               "--set", f"solid.spacing={args.spacing!r}",
               "--set", f"run.snapshot_interval={args.end_time / args.frames}"]
    result, wall = cr.run_solver(command)
    error = result.stderr.strip() if result.returncode == 1 else ""
    if error:
        print("  stopped:", error)
    return error, wall


def snapshots(out):
    """(time, file) of the time series, plus the last good state if the run blew up."""
    files = sorted(glob.glob(str(out / "solid_0*.h5")))
    last_good = out / "solid_last_good.h5"
    if last_good.exists():
        files.append(str(last_good))
    frames = []
    for f in files:
        with h5py.File(f) as h5:
            frames.append((float(h5.attrs["time"]) if "time" in h5.attrs else float("nan"), f))
    return frames


def draw(ax, path, title, vmax):
    with h5py.File(path) as h5:
        x = h5["position"][:]
        von_mises = h5["von_mises"][:]
        clamped = h5["clamped"][:].astype(bool)
    ax.scatter(x[clamped, 0], x[clamped, 1], s=2, c="0.6")
    sc = ax.scatter(x[~clamped, 0], x[~clamped, 1], s=2, c=von_mises[~clamped], cmap="viridis",
                    vmin=0.0, vmax=vmax)
    ax.set_title(title, fontsize=8)
    ax.tick_params(labelsize=6)
    return sc, x[:, :2].min(axis=0), x[:, :2].max(axis=0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default="/tmp/cosph_tensile_instability")
    parser.add_argument("--tip-speed", type=float, default=4.0,
                        help="initial tip speed [m/s] (the validation case uses 0.65)")
    parser.add_argument("--end-time", type=float, default=0.3)
    parser.add_argument("--spacing", type=float, default=0.002,
                        help="solid.spacing [m] (default 0.002: 10 particles across)")
    parser.add_argument("--frames", type=int, default=6)
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the figure from the runs already in --out")
    args = parser.parse_args()
    if not SOLVER.exists():
        sys.exit(f"{SOLVER} not found: build it first")
    out = pathlib.Path(args.out)
    runs = []
    for gradient, artificial_stress in RUNS:
        run_out = out / f"{gradient}_{'with' if artificial_stress else 'without'}_artificial_stress"
        label = label_of(gradient, artificial_stress)
        if args.plot_only:
            runs.append((label, run_out, "", float("nan")))
            continue
        for old in glob.glob(str(run_out / "solid_*.h5")):
            pathlib.Path(old).unlink()
        error, wall = run(run_out, gradient, artificial_stress, args)
        runs.append((label, run_out, error, wall))

    # The same times for both columns: every snapshot, and the last good one.
    columns = [snapshots(run_out) for _, run_out, _, _ in runs]
    rows = max(len(c) for c in columns)
    picks = np.unique(np.linspace(1, rows - 1, min(4, rows - 1)).round().astype(int))
    fig, axes = plt.subplots(len(picks), len(runs), figsize=(5 * len(runs), 2.0 * len(picks) + 0.6),
                             squeeze=False)
    vmax = 2.0e5
    shown_last = [False] * len(runs)
    for row, k in enumerate(picks):
        lower, upper = np.full(2, np.inf), np.full(2, -np.inf)
        for col, ((label, _, _, _), frames) in enumerate(zip(runs, columns)):
            ax = axes[row, col]
            if k >= len(frames) and shown_last[col]:
                ax.axis("off")
                continue
            # A run that ended early shows its last frame (its last good state) once.
            t, path = frames[min(k, len(frames) - 1)]
            shown_last[col] = k >= len(frames) - 1
            tag = " (last good: blew up)" if path.endswith("last_good.h5") else ""
            sc, low, high = draw(ax, path, f"{label}, t = {t:.3f} s{tag}", vmax)
            lower, upper = np.minimum(lower, low), np.maximum(upper, high)
        # The same window for both runs of a row, so that they compare at a glance.
        margin = 0.01
        for ax in axes[row]:
            ax.set_xlim(lower[0] - margin, upper[0] + margin)
            ax.set_ylim(lower[1] - margin, upper[1] + margin)
            ax.set_aspect("equal")
    fig.colorbar(sc, ax=axes, shrink=0.6, label="von Mises stress [Pa]")
    fig.suptitle(f"Oscillating plate at tip speed {args.tip_speed} m/s: tensile instability "
                 "without artificial stress; the quadratic gradient breaks even with it",
                 fontsize=10)
    path = ROOT / "docs" / "figures" / "tensile_instability.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=130)
    for label, _, error, wall in runs:
        print(f"{label}: {wall:.0f} s, " + (f"blew up: {error}" if error else "reached the end time"))
    print("wrote", path)
    write_outcomes(runs, args)


def write_outcomes(runs, args):
    """Each run's end: how far it got, and whether it blew up (its last good state kept)."""
    rows = []
    for label, run_out, _, wall in runs:
        reached = cr.read_csv(str(run_out / "timeseries.csv"))["t"][-1]
        last = snapshots(run_out)[-1][1]
        with h5py.File(last) as h5:
            # Torn: the particles no longer hang together at 1.5 spacings.
            pieces = cr.count_pieces(h5["position"][:], 1.5 * args.spacing)
        state = "whole" if pieces == 1 else f"in {pieces} pieces"
        outcome = (f"blew up; last good state {state}"
                   if last.endswith("last_good.h5") else f"ran to the end, {state}")
        rows.append([label, f"{reached:.3f}", outcome, "" if np.isnan(wall) else f"{wall:.0f}"])
    cr.write_table("tensile_instability", ["run", "reached t (s)", "outcome", "wall time (s)"],
                   rows, preamble=f"`scripts/tensile_instability.py`: the oscillating plate at tip "
                                  f"speed {args.tip_speed} m/s, solid.spacing {args.spacing} m, "
                                  f"to t = {args.end_time} s, the case's CFL number.")


if __name__ == "__main__":
    main()
