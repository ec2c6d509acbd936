#!/usr/bin/python3
"""Plate fracture (the study's scene 3): the elastic plate broken by the water.

Runs, through the launcher:
  1. the calibration: cases/plate_fracture.pbtxt with fracture off, to
     t = 0.1 s (multi-rate coupling, snapshots every 5 ms), and measures the
     largest von Mises stress in the weakened band against time: the stress
     the band's yield stress is chosen from (see the case's comment);
  2. the case with synchronised steps (coupling.max_substeps=1; the case
     itself is automatic, which chooses multi-rate, as in 3.);
  3. the case with multi-rate coupling (coupling.max_substeps=32), for its
     wall time against the synchronised run's.
Writes docs/figures/plate_fracture_snapshots.png (t = 0.10, 0.15, 0.20,
0.25 s as the study's Fig. 8: water coloured by pressure, plate by von Mises
stress, failed particles marked), docs/figures/plate_fracture_failed.png
(failed particles and the broken part's x against time) and
docs/results/plate_fracture.md.

usage: /usr/bin/python3 scripts/validate_plate_fracture.py [--reuse] [--only NAME ...]
  --reuse   analyse the runs already in out/validation/plate_fracture_* instead of running
  --only    run only these (no_fracture, sync, multirate), reuse the others
"""
import glob
import os
import re

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr

CASE = "plate_fracture"
BAND = (0.069, 0.079)  # m: the weakened band's initial y range (the case's weakened[0])
MULTIRATE = ["coupling.max_substeps=32"]
RUNS = [("calibration: fracture off, multi-rate", "no_fracture",
         MULTIRATE + ["solid.fracture.enabled=false", "run.end_time=0.1",
                      "run.snapshot_interval=0.005"]),
        ("synchronised steps, max_substeps 1", "sync", ["coupling.max_substeps=1"]),
        ("multi-rate, max_substeps 32", "multirate", MULTIRATE)]
SNAPSHOT_TIMES = (0.10, 0.15, 0.20, 0.25)  # s, the study's Fig. 8


def output_dir(suffix):
    return os.path.join(cr.REPO, "out", "validation", f"{CASE}_{suffix}")


def run_or_reuse(suffix, settings, reuse):
    """Runs one configuration unless reusing; returns (out, wall time in s or None, error)."""
    out = output_dir(suffix)
    return (out, *cr.run_or_reuse(CASE, out, settings, reuse))


def snapshots(out, name):
    files = sorted(glob.glob(os.path.join(out, f"{name}_[0-9]*.h5")))
    return [h5py.File(f, "r") for f in files]


def initial_y(out):
    first = snapshots(out, "solid")[0]
    return dict(zip(first["id"][:], first["position"][:, 1]))


def band_stress(out):
    """Times and the weakened band's largest von Mises stress, from the solid snapshots."""
    y0 = initial_y(out)
    times, stress = [], []
    for f in snapshots(out, "solid"):
        y = np.array([y0[i] for i in f["id"][:]])
        band = (y > BAND[0]) & (y < BAND[1])
        times.append(f.attrs["time"])
        stress.append(f["von_mises"][:][band].max())
    return np.array(times), np.array(stress)


def free_time(out, h):
    """First snapshot time at which the lower plate (initial y below the band)
    is no longer joined to the clamp through intact particles, two particles
    being joined when they are within 2h (failed particles carry no tension,
    so they join nothing). None if that never happens."""
    y0 = initial_y(out)
    for f in snapshots(out, "solid"):
        x, failed, clamped = f["position"][:, :2], f["failed"][:] == 1, f["clamped"][:] == 1
        lower = np.array([y0[i] < BAND[0] for i in f["id"][:]])
        intact = np.where(~failed)[0]
        near = np.sqrt(((x[intact, None] - x[None, intact]) ** 2).sum(-1)) < 2.0 * h
        reached = clamped[intact].copy()  # flood from the clamp
        frontier = reached.copy()
        while frontier.any():
            frontier = near[frontier].any(0) & ~reached
            reached |= frontier
        if not (reached & lower[intact]).any():
            return float(f.attrs["time"])
    return None


def draw_snapshots(out, path):
    fig, axes = plt.subplots(2, 2, figsize=(12, 5.2), layout="constrained")
    for ax, time in zip(axes.flat, SNAPSHOT_TIMES):
        fluid, solid = cr.snapshot_at(out, "fluid", time), cr.snapshot_at(out, "solid", time)
        p = cr.draw_water(ax, fluid, "Blues", 2, 1)
        xs, failed = solid["position"][:], solid["failed"][:] == 1
        s = ax.scatter(xs[~failed, 0], xs[~failed, 1], c=solid["von_mises"][:][~failed] / 1e3,
                       s=3, cmap="plasma", vmin=0, vmax=30)
        ax.scatter(xs[failed, 0], xs[failed, 1], marker="x", c="red", s=14, linewidths=0.8,
                   label="failed")
        ax.set(aspect="equal", xlim=(-0.01, 0.46), ylim=(-0.01, 0.17),
               title=f"t = {solid.attrs['time']:.3f} s, {int(failed.sum())} failed",
               xlabel="x (m)", ylabel="y (m)")
        ax.legend(loc="upper right", fontsize=8)
    fig.colorbar(p, ax=axes, shrink=0.8, location="right", label="water pressure (kPa, 1.4+ saturated)")
    fig.colorbar(s, ax=axes, shrink=0.8, location="right",
                 label="plate von Mises stress (kPa, 30+ saturated)")
    fig.savefig(path, dpi=110)


def main():
    parser = cr.script_arguments(__doc__)
    parser.add_argument("--only", action="append", default=[],
                        help="run only these (no_fracture, sync, multirate)")
    args = parser.parse_args()

    results = {}
    for label, suffix, settings in RUNS:
        reuse = args.reuse or bool(args.only and suffix not in args.only)
        out, wall, failure = run_or_reuse(suffix, settings, reuse)
        if not os.path.exists(os.path.join(out, "timeseries.csv")):
            print(f"skipping {label}: no run in {out}")
            continue
        results[suffix] = (label, out, wall, failure, cr.read_csv(os.path.join(out, "timeseries.csv")))

    sigma_y = 20.0e3  # Pa: the case's solid.fracture.weakened[0].yield_stress
    with open(os.path.join(cr.REPO, "cases", f"{CASE}.pbtxt")) as f:
        found = re.search(r"weakened\s*{.*?yield_stress:\s*([0-9.eE+-]+)", f.read(), re.S)
        sigma_y = float(found.group(1)) if found else sigma_y

    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    preamble = []
    if "no_fracture" in results:
        _, out, _, failure, _ = results["no_fracture"]
        t, stress = band_stress(out)
        axes[0].plot(t, stress / 1e3, "o-", ms=3, label="largest in the band, fracture off")
        axes[0].axhline(sigma_y / 1e3, color="r", ls="--", label=f"band sigma_y = {sigma_y / 1e3:g} kPa")
        axes[0].set(xlabel="t (s)", ylabel="von Mises stress (kPa)",
                    title="calibration: the weakened band, unbroken")
        axes[0].legend(fontsize=8)
        crossing = t[np.argmax(stress >= sigma_y)] if np.any(stress >= sigma_y) else None
        at = lambda time: stress[int(np.argmin(np.abs(t - time)))] / 1e3
        preamble.append(
            f"Calibration (fracture off, multi-rate, to t = {t[-1]:.3f} s"
            + (f"; it stopped early: {failure}" if failure else "") + "): the weakened band's "
            f"largest von Mises stress is {at(0.01):.1f} kPa at t = 0.01 s, {at(0.05):.1f} kPa at "
            f"0.05 s, {at(0.10):.1f} kPa at 0.10 s (peak {stress.max() / 1e3:.1f} kPa). "
            f"The band's sigma_y = {sigma_y / 1e3:g} kPa is first reached at t = "
            + (f"{crossing:.3f} s" if crossing is not None else "never") + " (snapshots every 5 ms).")
    rows = []
    h = 1.3 * 0.001
    for suffix in ("sync", "multirate"):
        if suffix not in results:
            continue
        label, out, wall, failure, series = results[suffix]
        failed = series["failed"]
        first = series["t"][np.argmax(failed > 0)] if np.any(failed > 0) else None
        free = free_time(out, h)
        rows.append([label, f"{series['t'][-1]:.3f}" + (" (stopped)" if failure else ""),
                     f"{first:.4f}" if first is not None else "none",
                     f"{free:.2f}" if free is not None else "not free",
                     int(failed[-1]), f"{series['broken_x'][-1]:.3f}",
                     f"{series['broken_y'][-1]:.3f}",
                     f"{wall:.0f}" if wall is not None else "?", cr.spray_removed(series)])
        if failure:
            preamble.append(f"**{label} stopped early:** {failure}")
        style = "-" if suffix == "sync" else "--"
        axes[1].plot(series["t"], failed, style, label=label)
        axes[2].plot(series["t"], series["broken_x"], style, label=label)
    axes[1].set(xlabel="t (s)", ylabel="failed particles", title="failed particles")
    axes[2].set(xlabel="t (s)", ylabel="broken_x (m)",
                title="x centre of mass of the plate below the band")
    for ax in axes[1:]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    fig.savefig(os.path.join(cr.FIGURES, "plate_fracture_failed.png"), dpi=110)
    if "sync" in results:
        draw_snapshots(results["sync"][1], os.path.join(cr.FIGURES, "plate_fracture_snapshots.png"))

    preamble.insert(0, "Plate fracture (the study's scene 3), by `scripts/validate_plate_fracture.py`: "
                    "`cases/plate_fracture.pbtxt`, water 2 mm, plate 1 mm, band 0.069 <= y <= "
                    "0.079 m at E = 0.12e6 Pa. 'free' is the first snapshot (every 10 ms) at which "
                    "no intact particle of the lower plate is within 2h of an intact clamped one. "
                    "broken_x, broken_y: centre of mass of the free particles that start below "
                    "y = 0.069 m. Wall times on two cores shared with other jobs.")
    preamble.append(
        "Why sigma_y = 20 kPa: the study gives no yield stress. Unbroken, the soft band "
        "becomes a hinge and the plate below swings out; the band's stress grows with the "
        "hinge's angle (calibration above). sigma_y is about two thirds of the band's stress at "
        "0.1 s, so the band yields before 0.1 s (the table's first failure) and the piece is "
        "free and carried away well before the snapshots of the study's Fig. 8 (0.10 to 0.25 s); it is a strain "
        "sigma_y / E = 1/6 in the band. The rest of the plate keeps a rubber's strength, "
        "10 MPa (solid.fracture.yield_stress; the band's own value is "
        "solid.fracture.weakened[0].yield_stress): with a single sigma_y the free end's corner "
        "particles, whose von Mises stress grows to about 0.5 MPa by 0.1 s as the plate swings "
        "(spurious, most likely the corners' kernel renormalisation falling back to the "
        "identity), would fail before the band at any sigma_y the band can reach. The broken "
        "piece rests on the floor through solid.walls (an inelastic, frictionless contact, "
        "solid/common/wall_contact.hpp); without it the piece fell through the floor.")
    path = cr.write_table(CASE, ["run", "reached t (s)", "first failure t (s)", "piece free by t (s)",
                                 "failed at end", "broken_x at end (m)", "broken_y at end (m)",
                                 "wall time (s)", "water left as spray"], rows,
                           "\n\n".join(preamble))
    print(open(path).read())


if __name__ == "__main__":
    main()
