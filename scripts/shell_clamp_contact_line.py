#!/usr/bin/python3
"""The water particle that stops the coupled shell plate at the clamp
(docs/shell.md, "Water drawn into the clamp's upstream face").

Runs the coupled elastic plate with the shell at the case's spacing and
coupling.max_substeps 7 (windows of about 10 us, as issue 39's run at 8 that
stopped at the clamp; held explicitly, so the rule of automatic windows does
not move them) into out/validation/shell_clamp_contact_line, and, if it
stopped on a
water particle, follows that particle through the fluid's snapshots: its
position, how deep it lies inside the plate's upstream face (x = 0.1 m; the
shell's outer interface layer is half a solid spacing inside it), its
pressure, density and speed, and how far it stands above the other water
near it (it is the free surface's highest at the wall). For comparison, the
deepest any water particle lies inside the water's own left wall (x < 0) in
the same snapshot. Writes docs/results/shell_clamp_contact_line.md.

usage: /usr/bin/python3 scripts/shell_clamp_contact_line.py [--reuse]
  --reuse   analyse the run already in out/validation/shell_clamp_contact_line
"""
import glob
import os
import re

import h5py
import numpy as np

import cosph_results as cr

RUN = os.path.join(cr.REPO, "out", "validation", "shell_clamp_contact_line")
SETTINGS = ["solid.model=shell", "coupling.max_substeps=7"]
FACE_X = 0.1  # m, the plate's upstream face (cases/elastic_plate.pbtxt)
EVERY = 2     # every other snapshot (0.04 s), and the last


def failing_particle():
    """(id, failure line) of the water particle the run stopped on, or (None, "")."""
    with open(os.path.join(RUN, "launcher.log")) as lines:
        for line in lines:
            found = re.search(r"cosph-fluid: error: water particle (\d+) at", line)
            if found:
                return int(found.group(1)), line.split(". Last good")[0].strip()
    return None, ""


def main():
    parser = cr.script_arguments(__doc__)
    args = parser.parse_args()
    cr.run_or_reuse("elastic_plate", RUN, SETTINGS, args.reuse)
    particle, failure = failing_particle()
    if particle is None:
        print(f"{RUN}: the run did not stop on a water particle; nothing to follow")
        return
    files = sorted(glob.glob(os.path.join(RUN, "fluid_*.h5")))
    chosen = files[::EVERY] + ([files[-1]] if (len(files) - 1) % EVERY else [])
    rows = []
    for path in chosen:
        with h5py.File(path, "r") as f:
            x, kind, ident = f["position"][:], f["kind"][:], f["id"][:]
            p, rho, v = f["pressure"][:], f["density"][:], f["velocity"][:]
            t = f.attrs["time"]
        water = kind == 0
        j = np.where(ident == particle)[0][0]
        others = water & (ident != particle) & (np.abs(x[:, 0] - x[j, 0]) < 0.005)
        above = x[j, 1] - np.max(x[others, 1]) if np.any(others) else float("nan")
        rows.append([f"{t:.2f}", f"{1e3 * x[j, 0]:.1f}, {1e3 * x[j, 1]:.1f}",
                     f"{1e3 * (x[j, 0] - FACE_X):+.1f}", f"{1e3 * above:.1f}", f"{p[j]:.0f}",
                     f"{rho[j]:.0f}", f"{np.linalg.norm(v[j]):.2f}",
                     f"{1e3 * max(0.0, -np.min(x[water, 0])):.1f}"])
    header = ["t (s)", "x, y (mm)", "x - face (mm)", "height above the highest other water within 5 mm in x (mm)",
              "pressure (Pa)", "density (kg/m^3)", "speed (m/s)",
              "deepest water inside the left wall (mm)"]
    cr.write_table("shell_clamp_contact_line", header, rows,
                   "Written by `scripts/shell_clamp_contact_line.py` from the coupled shell plate "
                   "at the case's spacing and `coupling.max_substeps=7`, which stopped with: "
                   f"{failure}. Water particle {particle}, from "
                   "the fluid's snapshots (every 0.04 s and the last).")


if __name__ == "__main__":
    main()
