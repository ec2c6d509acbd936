#!/usr/bin/python3
"""Which water pumps the shell's fast modes in long multi-rate windows: the
evidence for the coupling share s of the automatic window bound
(docs/auto_substeps.md, "Solids with weakly damped modes").

Runs the coupled elastic plate (cases/elastic_plate.pbtxt, solid.model=shell)
to its end, t = 0.4 s, at coupling.max_substeps 32 (the windows the
added-mass rule alone takes), with the shell's damping, for each water
spelled out in full (cosph_results.water) at the mid-line spacings 1 and
0.5 mm, and a synchronised run of the default water as the plate's own swing.
For each: the mean window W, omega_r W (omega_r the section's shear-rotation
cut-off), the damping ratio zeta_r the shell states there, the largest speed
of a shell particle (timeseries column solid_max_speed) in each 0.05 s after
0.1 s, and whether the run stayed quiet: its largest speed after 0.1 s no more
than twice the synchronised run's. A quiet run bounds the share the held
force took of the cut-off's stiffness, s < 4 zeta_r / (omega_r W) (its
negative damping s omega_r W / 4 stayed below zeta_r); a pumped one says the
share was larger. Writes docs/results/shell_window_waters.md.

usage: /usr/bin/python3 scripts/shell_window_waters.py [--reuse]
  --reuse   analyse the runs already in out/validation/shell_window_waters_* instead of running
"""
import os

import numpy as np

import cosph_results as cr
from pressure_noise import RIEMANN, WENDLAND
from shell_window_vibration import (coupler_share, cut_off_damping_ratio, rotation_frequency,
                                    stepping)

FROM, END = 0.1, 0.4  # s
INTERVALS = [(FROM + k * 0.05, FROM + (k + 1) * 0.05) for k in range(6)]
# A quiet run: its largest shell speed after FROM at most this many times the
# synchronised run's (the plate's own swing and the water's noise on it).
QUIET_FACTOR = 2.0
DEFAULT = cr.water(**RIEMANN, **WENDLAND, wall_friction="normal")
# (key, the water in words, its settings, mid-line spacings in m)
WATERS = [
    ("default", "the default: Riemann, Wendland C2, walls damping along their normal", DEFAULT,
     [0.001, 0.0005]),
    ("default_friction", "the default with the walls' friction", cr.water(**RIEMANN, **WENDLAND),
     [0.0005]),
    ("riemann_cubic", "Riemann, cubic spline, walls damping along their normal",
     cr.water(**RIEMANN, wall_friction="normal"), [0.0005]),
    ("delta_wendland", "delta-SPH, Wendland C2, walls damping along their normal",
     cr.water(**WENDLAND, wall_friction="normal"), [0.0005]),
    ("earlier_normal", "delta-SPH, cubic spline, walls damping along their normal",
     cr.water(wall_friction="normal"), [0.0005]),
    ("earlier", "the earlier default: delta-SPH, cubic spline, the walls' friction", cr.water(),
     [0.001, 0.0005]),
]
SYNCHRONISED_SPACING = 0.001


def run(key, settings, spacing, substeps, reuse):
    """The run's series, coupling log and failure, or None without a run."""
    name = f"shell_window_waters_{key}_{spacing * 1e3:g}mm_{substeps}"
    out = os.path.join(cr.REPO, "out", "validation", name)
    settings = settings + ["solid.model=shell", f"solid.spacing={spacing}",
                           f"coupling.max_substeps={substeps}", f"run.snapshot_interval={END}"]
    _, failure = cr.run_or_reuse("elastic_plate", out, settings, reuse)
    if not os.path.exists(os.path.join(out, "timeseries.csv")):
        print(f"skipping {name}: no run in {out}")
        return None
    return (cr.read_csv(os.path.join(out, "timeseries.csv")),
            cr.read_csv(os.path.join(out, "coupling.csv")), failure, stepping(out))


def largest_speeds(series):
    t, speed = series["t"], series["solid_max_speed"]
    return [float(np.max(speed[(t >= a) & (t <= b)])) for a, b in INTERVALS
            if np.any((t >= a) & (t <= b))]


def main():
    args = cr.script_arguments(__doc__).parse_args()
    omega_r = rotation_frequency()
    reference = run("default", DEFAULT, SYNCHRONISED_SPACING, 1, args.reuse)
    if reference is None:
        raise SystemExit("shell_window_waters: no synchronised run to measure the plate's own "
                         "swing against")
    swing = max(largest_speeds(reference[0]))
    rows = [["the default (synchronised: the plate's own swing)", f"{SYNCHRONISED_SPACING * 1e3:g}",
             reference[3], "", "", f"{cut_off_damping_ratio(SYNCHRONISED_SPACING):.3f}",
             " / ".join(f"{v:.2f}" for v in largest_speeds(reference[0])), "", "",
             reference[2]]]
    riemann_bounds = []
    for key, words, settings, spacings in WATERS:
        # Whether the water solves the Riemann problem against the plate.
        riemann = cr.setting(settings, "fluid.dissipation") == RIEMANN["dissipation"]
        for spacing in spacings:
            result = run(key, settings, spacing, 32, args.reuse)
            if result is None:
                continue
            series, coupling, failure, chosen = result
            window = coupling["t"][-1] / coupling["step"][-1]
            zeta_r = cut_off_damping_ratio(spacing)
            speeds = largest_speeds(series)
            quiet = not failure and max(speeds) <= QUIET_FACTOR * swing
            bound = 4.0 * zeta_r / (omega_r * window)
            if riemann and quiet:
                riemann_bounds.append(bound)
            rows.append([words, f"{spacing * 1e3:g}", chosen, f"{1e6 * window:.1f}",
                         f"{omega_r * window:.2f}", f"{zeta_r:.3f}",
                         " / ".join(f"{v:.2f}" for v in speeds),
                         "quiet" if quiet else "pumped",
                         f"< {bound:.2f}" if quiet else f"> {bound:.2f}", failure])
    header = ["water", "plate spacing (mm)", "stepping", "mean window W (us)", "omega_r W",
              "zeta_r", "largest shell speed per 0.05 s from 0.1 s (m/s)", "the shell",
              "coupling share s it shows", "failure"]
    share = coupler_share()
    least = ""
    if riemann_bounds:
        least = (f" The smallest bound the quiet Riemann rows set: s < {min(riemann_bounds):.3f}; "
                 f"the coupler takes s = {share:g} for a Riemann water "
                 "(kRiemannCouplingStiffnessShare, coupler/src/substep_choice.hpp), "
                 + ("within it." if share < min(riemann_bounds) else "NOT within it."))
    cr.write_table("shell_window_waters", header, rows,
                   "Written by `scripts/shell_window_waters.py`. The coupled elastic plate with the "
                   f"damped shell (water 2 mm) to t = {END} s in the windows the added-mass rule "
                   "alone takes (coupling.max_substeps 32), for each water; omega_r = "
                   f"{omega_r:.0f} rad/s, the section's shear-rotation cut-off, zeta_r the damping "
                   "ratio the shell states there. Quiet: the largest shell speed after 0.1 s at "
                   f"most {QUIET_FACTOR:g} times the synchronised run's ({swing:.2f} m/s). A quiet "
                   "run bounds the held force's share of the cut-off's stiffness, "
                   "s < 4 zeta_r / (omega_r W); a pumped run shows it larger." + least)


if __name__ == "__main__":
    main()
