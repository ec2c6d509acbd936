#!/usr/bin/python3
"""The shell's fast modes under multi-rate coupling windows, with and without
its damping (docs/shell.md, "Multi-rate windows and the shell's fast modes").

Runs the coupled elastic plate (cases/elastic_plate.pbtxt, solid.model=shell,
plate 1 mm) to t = 0.1 s at coupling.max_substeps 1 (synchronised), 8, 32
(the windows the added-mass rule alone takes) and 0 (automatic: with the
damping, windows bound by the shell's fastest mode, docs/auto_substeps.md),
once with the shell's damping and once without
(solid.shell_damping=false). For each: the stepping the coupler took, the
mean window W (coupling steps over the run), omega_r W with omega_r the
section's shear-rotation cut-off (solid/shell/shell_section.hpp), and the
largest speed of a shell particle (timeseries column solid_max_speed) in each
0.02 s of the run: a vibration of the shell shows as speeds far above the
plate's own swing. Writes docs/results/shell_windows.md.

usage: /usr/bin/python3 scripts/shell_window_vibration.py [--reuse]
  --reuse   analyse the runs already in out/validation/shell_windows_* instead of running
"""
import math
import os
import re

import numpy as np

import cosph_results as cr

END = 0.1  # s
INTERVALS = [(k * 0.02, (k + 1) * 0.02) for k in range(5)]
SUBSTEPS = [1, 8, 32, 0]
# The case's plate (cases/elastic_plate.pbtxt): E, nu, rho, thickness.
E, NU, RHO, THICKNESS = 12.0e6, 0.4, 1100.0, 0.005
SHEAR_CORRECTION = 5.0 / 6.0


def rotation_frequency():
    """omega_r = sqrt(k G t / (rho t^3 / 12)), rad/s (shell_section.hpp)."""
    G = E / (2.0 * (1.0 + NU))
    return math.sqrt(SHEAR_CORRECTION * G * THICKNESS / (RHO * THICKNESS ** 3 / 12.0))


def coupler_share():
    """kRiemannCouplingStiffnessShare as the coupler has it: the share s of
    the damping bound for a Riemann water (docs/auto_substeps.md)."""
    with open(os.path.join(cr.REPO, "coupler", "src", "substep_choice.hpp")) as header:
        found = re.search(r"kRiemannCouplingStiffnessShare = ([0-9.eE+-]+);", header.read())
    return float(found.group(1))


def cut_off_damping_ratio(spacing):
    """zeta_r, the damping's ratio at the shear-rotation cut-off for a
    mid-line spacing (h = 1.3 dx; solid/shell/shell_damping.hpp): what the
    shell states in its Hello."""
    G = E / (2.0 * (1.0 + NU))
    c_G = math.sqrt(G / RHO)
    eta_s = 0.25 * RHO * c_G * min(THICKNESS, 1.3 * spacing)
    stiffness_inertia = SHEAR_CORRECTION * G * THICKNESS * RHO * THICKNESS ** 3 / 12.0
    return SHEAR_CORRECTION * THICKNESS * eta_s / (2.0 * math.sqrt(stiffness_inertia))


def damping_ratios():
    """The damping's ratios by its rule (solid/shell/shell_damping.hpp), h = 1.3 dx:
    the first bending mode of the free length L = 0.079 m (Euler-Bernoulli,
    plane strain) at the case's 1 mm, and the shear-rotation cut-off at the
    mid-line spacings of the convergence runs, in words."""
    E_plane = E / (1.0 - NU ** 2)
    c = math.sqrt(E_plane / RHO)
    omega_1 = (1.875 / 0.079) ** 2 * math.sqrt(E_plane * THICKNESS ** 2 / (12.0 * RHO))
    bending = 0.5 * RHO * c * 1.3e-3 * omega_1 / (2.0 * E_plane)
    omega_r = rotation_frequency()
    cut_off = [cut_off_damping_ratio(dx) for dx in (0.002, 0.001, 0.0005)]
    bound = [2.0 * zeta / omega_r for zeta in cut_off]
    share = coupler_share()
    return ("Damping ratios of the shell's damping by its rule: the first bending mode "
            f"{bending:.1e} (at h = 1.3 mm); the shear-rotation cut-off "
            + " / ".join(f"{z:.2f}" for z in cut_off)
            + " at the mid-line spacings 2 / 1 / 0.5 mm (h = 1.3 dx); the axial and rotation "
            f"zigzags h / (2 ds) = {1.3 / 2:.2f}. The automatic stepping's window bound "
            "2 zeta_r / (s omega_r) (docs/auto_substeps.md, \"Solids with weakly damped modes\") "
            "at these spacings: with a delta-SPH water (s = 1) "
            + " / ".join(f"{1e6 * w:.1f}" for w in bound) + " us, omega_r W <= "
            + " / ".join(f"{omega_r * w:.2f}" for w in bound)
            + f"; with a Riemann water, the default (s = {share:g}), "
            + " / ".join(f"{1e6 * w / share:.1f}" for w in bound) + " us, omega_r W <= "
            + " / ".join(f"{omega_r * w / share:.2f}" for w in bound) + ".")


def stepping(out):
    """The coupler's last sub-stepping line, up to its reason."""
    with open(os.path.join(out, "launcher.log")) as lines:
        chosen = [line.split("sub-stepping: ", 1)[1] for line in lines if "sub-stepping: " in line]
    return chosen[-1].split(" (")[0] if chosen else ""


def main():
    parser = cr.script_arguments(__doc__)
    args = parser.parse_args()
    omega_r = rotation_frequency()
    rows = []
    for damped in (False, True):
        for substeps in SUBSTEPS:
            name = f"shell_windows_{'damped' if damped else 'undamped'}_{substeps}"
            out = os.path.join(cr.REPO, "out", "validation", name)
            settings = ["solid.model=shell", f"solid.shell_damping={'true' if damped else 'false'}",
                        f"coupling.max_substeps={substeps}", f"run.end_time={END}",
                        f"run.snapshot_interval={END}"]
            _, failure = cr.run_or_reuse("elastic_plate", out, settings, args.reuse)
            series_path = os.path.join(out, "timeseries.csv")
            if not os.path.exists(series_path):
                print(f"skipping {name}: no run in {out}")
                continue
            series = cr.read_csv(series_path)
            coupling = cr.read_csv(os.path.join(out, "coupling.csv"))
            window = coupling["t"][-1] / coupling["step"][-1]
            t, speed = series["t"], series["solid_max_speed"]
            largest = [np.max(speed[(t >= a) & (t <= b)]) for a, b in INTERVALS
                       if np.any((t >= a) & (t <= b))]
            rows.append(["yes" if damped else "no",
                         f"{substeps}" + (" (automatic)" if substeps == 0 else ""),
                         stepping(out), f"{1e6 * window:.1f}", f"{omega_r * window:.2f}",
                         " / ".join(f"{v:.2f}" for v in largest), failure])
    header = ["damping", "coupling.max_substeps", "stepping", "mean window W (us)", "omega_r W",
              "largest shell speed per 0.02 s to 0.1 s (m/s)", "failure"]
    cr.write_table("shell_windows", header, rows,
                   "Written by `scripts/shell_window_vibration.py`. The coupled elastic plate with "
                   "the shell (plate 1 mm, water 2 mm) to t = 0.1 s; omega_r = "
                   f"{omega_r:.0f} rad/s, the section's shear-rotation cut-off. The synchronised "
                   "rows show the speeds of the plate's own swing. " + damping_ratios())


if __name__ == "__main__":
    main()
