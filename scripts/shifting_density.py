#!/usr/bin/python3
"""What delta-plus shifting does to the dam break's far corner (issue 38).

With delta-plus-SPH's shifting (fluid.shifting "delta_plus") the dam break's
far-wall sensor reads several rho0 g H for a while after the impact
(docs/results/pressure_noise.md). The shifting moves particles and, as the
paper has it, corrects nothing else for the move: a particle keeps the density
continuity gave it. If the shifting spreads the corner's particles apart
while their densities stay, the two no longer tell of the same water: the
water's arrangement says it is less compressed than its densities say, and
the pressure, from the densities, stays high. This script measures that:
the dam break (cases/dam_break.pbtxt) at 8 mm to t = 0.36 s with and
without the shifting, for delta-SPH (the earlier default) and for the
default water, snapshots every 10 ms, and for the water in the far corner
(within 40 mm of the far wall and 30 mm of the floor) over t = 0.28-0.35 s:
  - its particles' density from continuity (the solver's), and the density
    its arrangement gives, the kernel sum of the masses of the water and
    wall particles within 2h, each with the run's kernel and h, as their
    ratio: 1 where the two agree (the walls fill the kernel's support, and
    the corner's water stands higher than 2h above its particles);
  - how many water particles the corner holds, and their mean pressure over
    rho0 g H.
Writes docs/results/shifting_density.md.

usage: /usr/bin/python3 scripts/shifting_density.py [--out DIR] [--reuse]
"""
import glob
import os

import h5py
import numpy as np

import cosph_results as cr
import sensor_support as ss
import sound_speed_noise as ssn
import validate_dam_break as dam

SPACING = 0.008  # m
END_TIME = 0.36  # s
SNAPSHOT_INTERVAL = 0.01  # s
WINDOW = (0.28, 0.35)  # s: after the impact, while the corner is full
FAR_WALL = 0.576  # m: x of the far wall's face (cases/dam_break.pbtxt)
CORNER = (0.04, 0.03)  # m: from the far wall, above the floor
RHO0 = 1000.0  # kg/m^3
# The kernels' 2-D normalisations, times sensor_support.kernel_weight's shapes.
NORMALISATION = {"cubic_spline": 10 / (7 * np.pi), "wendland_c2": 7 / (4 * np.pi)}
WATERS = [  # (label, settings, kernel, h / dx)
    ("delta-SPH (Marrone et al. 2011), the earlier default", cr.water(), "cubic_spline", 1.3),
    ("delta-plus-SPH: the same and shifting (Sun et al. 2017)", cr.water(shifting="delta_plus"),
     "cubic_spline", 1.3),
    ("Riemann, Wendland C2, walls damping along their normal" + cr.DEFAULT_WATER_MARK,
     ssn.DEFAULT_WATER, "wendland_c2", 1.5),
    ("the same and delta-plus shifting", ssn.DEFAULT_WATER + ["fluid.shifting=delta_plus"],
     "wendland_c2", 1.5),
]


def corner_state(snapshot, kernel, h):
    """(water particles in the corner, their mean continuity density, mean and
    lowest ratio of the arrangement's density to it, mean pressure in Pa) in
    one snapshot, an open h5py file."""
    x = snapshot["position"][:, :2]
    rho, p = snapshot["density"][:], snapshot["pressure"][:]
    water = snapshot["kind"][:] == ss.WATER
    corner = np.nonzero(water & (x[:, 0] > FAR_WALL - CORNER[0]) & (x[:, 1] < CORNER[1]))[0]
    mass = RHO0 * SPACING ** 2  # every particle, water or wall, fills dx^2 at rho0
    ratios = []
    for i in corner:
        q = np.sqrt(((x - x[i]) ** 2).sum(axis=1)) / h
        arranged = mass * NORMALISATION[kernel] / h ** 2 * ss.kernel_weight(q, kernel).sum()
        ratios.append(arranged / rho[i])
    return len(corner), float(rho[corner].mean()), float(np.mean(ratios)), \
        float(np.min(ratios)), float(p[corner].mean())


def main():
    args = cr.script_arguments(__doc__, "shifting_density").parse_args()
    table = []
    for k, (label, settings, kernel, h_factor) in enumerate(WATERS):
        out = os.path.join(args.out, f"water_{k}")
        if not (args.reuse and glob.glob(os.path.join(out, "fluid_*.h5"))):
            cr.run_case("dam_break", out, settings + [
                f"fluid.spacing={SPACING}", f"run.end_time={END_TIME}",
                f"run.snapshot_interval={SNAPSHOT_INTERVAL}"])
        states = []
        for path in sorted(glob.glob(os.path.join(out, "fluid_[0-9]*.h5"))):
            with h5py.File(path, "r") as snapshot:
                if WINDOW[0] - 1e-9 <= snapshot.attrs["time"] <= WINDOW[1] + 1e-9:
                    states.append(corner_state(snapshot, kernel, h_factor * SPACING))
        count, rho, ratio, pressure = (np.mean([s[n] for s in states]) for n in (0, 1, 2, 4))
        lowest = min(s[3] for s in states)
        table.append([label, f"{count:.1f}", f"{rho:.1f}", f"{ratio:.3f} ({lowest:.3f})",
                      f"{pressure / dam.RHO0_G_H:.2f}"])
        print(table[-1], flush=True)
    path = cr.write_table(
        "shifting_density",
        ["water", "particles in the corner", "their density from continuity (kg/m^3)",
         "density of their arrangement / from continuity: mean (lowest)",
         "their pressure / (rho0 g H)"],
        table,
        preamble="The dam break (`cases/dam_break.pbtxt`) at 8 mm with and without "
                 "delta-plus shifting: the water in the far corner (within "
                 f"{CORNER[0] * 1e3:g} mm of the far wall and {CORNER[1] * 1e3:g} mm of the "
                 f"floor), means over the snapshots of t = {WINDOW[0]:g}-{WINDOW[1]:g} s "
                 f"(every {SNAPSHOT_INTERVAL * 1e3:g} ms): how many water particles it holds, "
                 "their density as continuity gives it, the density their arrangement gives "
                 "(the kernel sum of the water's and the walls' masses within 2h, the run's "
                 "kernel and h) over it, and their pressure. Produced by "
                 "`scripts/shifting_density.py`.")
    print(open(path).read())


if __name__ == "__main__":
    main()
