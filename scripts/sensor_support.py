#!/usr/bin/python3
"""Why the far-wall sensor reads a lower mean at h = 2 dx while the wall's force does not (issue 38).

The sensor (fluid/src/gauges.cpp) is the Adami et al. 2012 wall pressure at the
probe: the kernel-weighted mean of the water within 2h, corrected
hydrostatically to the probe's height. A larger h widens that support, and a
one-sided mean next to a pressure maximum (the floor corner, where the flow
along the floor stagnates) reads low by an amount that grows with the support:
a measurement artifact. Or the water itself is different there. This script
tells the two apart on the dam break at 4 mm, the default run and the runs with
the Wendland C2 kernel at h = 2 dx (delta-SPH, Riemann), with snapshots every
2.5 ms over t = 0.35-0.55 s:
  - the sensor re-evaluated on each run's snapshots with either kernel and
    support: if the support made the difference, the default's sensor on
    the h = 2 dx runs' water would read the default's mean;
  - the water's pressure beside the far wall (8-40 mm up, corrected
    hydrostatically to the sensor's 16 mm) against distance from the wall;
  - the mean horizontal velocity of the water flowing along the floor towards
    the far wall (x = 0.45-0.55 m, y < 30 mm), whose stagnation in the corner
    the sensor reads, and its 0.5 u^2 / (g H);
  - the far wall's force (wall2_force_x), as pressure_noise.py measures it;
and, to see whether the wall friction of the artificial viscosity (alpha h c0,
larger with h) slows that flow, the h = 2 dx run with alpha h held at the
default's. (Whether the means converge with the spacing:
pressure_noise.py --convergence.) Writes docs/results/sensor_support.md.

usage: /usr/bin/python3 scripts/sensor_support.py [--out DIR] [--reuse]
"""
import glob
import os
import re

import h5py
import numpy as np

import cosph_results as cr
import pressure_noise as pn
import validate_dam_break as dam

SPACING = 0.004


def case_text():
    """cases/dam_break.pbtxt as text."""
    with open(os.path.join(cr.REPO, "cases", "dam_break.pbtxt")) as case:
        return case.read()


def case_probe(index):
    """The case's pressure sensor `index` (cases/dam_break.pbtxt, pressure_probes), in m."""
    probes = re.findall(r"pressure_probes\s*\{\s*x:\s*(\S+)\s+y:\s*(\S+)\s*\}", case_text())
    return np.array([float(value) for value in probes[index]])


PROBE = case_probe(1)  # probe1, on the far wall
ALPHA = 0.02  # Monaghan's alpha of the delta-SPH water (its default, proto/case.proto)
H_FACTOR = cr.EARLIER_WATER["h_factor"]  # delta-SPH's, the comparison's reference
RUNS = [  # (key, label, settings)
    ("default", "delta-SPH, cubic spline, h = 1.3 dx (the earlier default)", cr.water()),
    ("wendland_2dx", "delta-SPH, Wendland C2, h = 2 dx", cr.water(**pn.WENDLAND_2DX)),
    ("riemann_wendland_2dx", "Riemann, Wendland C2, h = 2 dx",
     cr.water(**pn.RIEMANN, **pn.WENDLAND_2DX)),
    # A diagnosis, not an option: the artificial viscosity's alpha h c0, which
    # also acts between water and the walls (their no-slip, docs/physics.md),
    # held at delta-SPH's at 1.3 dx by alpha = 0.02 x 1.3 / 2.
    ("wendland_2dx_same_alpha_h", "delta-SPH, Wendland C2, h = 2 dx, alpha = "
     f"{ALPHA * H_FACTOR / 2:g} (alpha h as at h = 1.3 dx; a diagnosis)",
     cr.water(**pn.WENDLAND_2DX) + [f"fluid.artificial_viscosity={ALPHA * H_FACTOR / 2:g}"]),
]
SUPPORTS = [  # (label, kernel, h): the sensor's, as in the runs
    ("cubic spline, h = 1.3 dx (the earlier default)", "cubic_spline", H_FACTOR * SPACING),
    ("Wendland C2, h = 2 dx", "wendland_c2", 2.0 * SPACING),
]
SNAPSHOT_INTERVAL = 0.0025  # s: 80 snapshots over the window
WATER = 0  # the snapshots' kind of a water particle
BESIDE_WALL = (0.008, 0.04)  # m: the band of heights whose water pressure is profiled
DISTANCE_BINS = np.arange(0.0, 0.0401, 0.008)  # m from the far wall's face
APPROACH = ((0.45, 0.55), 0.03)  # m: x range and top of the water flowing to the corner


def kernel_weight(q, kernel):
    """The kernel's shape in 2-D up to its normalisation (a weighted mean needs none)."""
    if kernel == "cubic_spline":
        return np.where(q < 1, 1 - 1.5 * q ** 2 + 0.75 * q ** 3,
                        np.where(q < 2, 0.25 * (2 - q) ** 3, 0.0))
    return np.where(q < 2, (1 - q / 2) ** 4 * (2 * q + 1), 0.0)


def water_state(snapshot):
    """The water's positions, pressures and densities in a snapshot, read once."""
    water = snapshot["kind"][:] == WATER
    return (snapshot["position"][:, :2][water], snapshot["pressure"][:][water],
            snapshot["density"][:][water])


def sensor_reading(water, point, kernel, h):
    """A sensor at `point` on the water (water_state) as gauges.cpp computes it,
    in Pa: the kernel mean of the water's pressure, corrected hydrostatically
    to the point; 0 with no water in reach."""
    x, p, rho = water
    offset = np.asarray(point) - x
    w = kernel_weight(np.linalg.norm(offset, axis=1) / h, kernel)
    total = np.sum(w)
    return (np.sum(p * w) + np.sum(rho * w * -dam.G * offset[:, 1])) / total if total > 0 else 0.0


def run_after_impact(folder, settings, spacing, snapshot_interval, reuse):
    """The dam break at `spacing` into `folder`, run to just past the window
    after the impact with a snapshot every `snapshot_interval` (kept as it is
    with `reuse`, if there); returns its timeseries."""
    os.makedirs(folder, exist_ok=True)
    if not (reuse and os.path.exists(os.path.join(folder, "timeseries.csv"))):
        cr.run_case("dam_break", folder, settings + [
            f"fluid.spacing={spacing}", f"run.output_interval={dam.OUTPUT_INTERVAL}",
            f"run.snapshot_interval={snapshot_interval}",
            f"run.end_time={dam.AFTER_IMPACT[1] + 0.01}"])
    return cr.read_csv(os.path.join(folder, "timeseries.csv"))


def snapshots(folder):
    """The run's snapshots within the window after the impact."""
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"',
                                          open(os.path.join(folder, "fluid.xdmf")).read())]
    for t, path in zip(times, sorted(glob.glob(os.path.join(folder, "fluid_*.h5")))):
        if dam.AFTER_IMPACT[0] <= t <= dam.AFTER_IMPACT[1]:
            with h5py.File(path, "r") as snapshot:
                yield snapshot


def measure(folder):
    readings = [[] for _ in SUPPORTS]
    pressure_sum = np.zeros(len(DISTANCE_BINS) - 1)
    counts = np.zeros(len(DISTANCE_BINS) - 1)
    u, dynamic = [], []
    for snapshot in snapshots(folder):
        water_now = water_state(snapshot)
        for reading, (_, kernel, h) in zip(readings, SUPPORTS):
            reading.append(sensor_reading(water_now, PROBE, kernel, h))
        x, p, rho = water_now
        water = snapshot["kind"][:] == WATER
        band = (x[:, 1] > BESIDE_WALL[0]) & (x[:, 1] < BESIDE_WALL[1])
        corrected = p[band] + rho[band] * dam.G * (x[band, 1] - PROBE[1])
        k = np.digitize(PROBE[0] - x[band, 0], DISTANCE_BINS) - 1
        inside = (k >= 0) & (k < len(counts))
        np.add.at(pressure_sum, k[inside], corrected[inside])
        np.add.at(counts, k[inside], 1)
        (x0, x1), top = APPROACH
        flowing = (x[:, 0] > x0) & (x[:, 0] < x1) & (x[:, 1] < top)
        v = snapshot["velocity"][:, :2][water][flowing]
        u.append(np.mean(v[:, 0]))
        dynamic.append(0.5 * np.mean(v[:, 0]) ** 2 / (dam.G * dam.H))
    return ([np.mean(values) / dam.RHO0_G_H for values in readings],
            pressure_sum / np.maximum(counts, 1) / dam.RHO0_G_H, float(np.mean(u)),
            float(np.mean(dynamic)), len(u))


def main():
    parser = cr.script_arguments(__doc__, "sensor_support")
    args = parser.parse_args()

    rows = []
    for key, label, settings in RUNS:
        folder = os.path.join(args.out, key)
        series = run_after_impact(folder, settings, SPACING, SNAPSHOT_INTERVAL, args.reuse)
        readings, profile, u, dynamic, count = measure(folder)
        rows.append([label, f"{dam.sensor_noise(series, 'probe1')[0]:.3f}",
                     *(f"{value:.3f}" for value in readings),
                     ", ".join(f"{v:.3f}" for v in profile), f"{u:.2f}", f"{dynamic:.3f}",
                     f"{pn.far_wall_force_noise(series)[0]:.3f}"])
        print(rows[-1], count, "snapshots", flush=True)
    centres = ", ".join(f"{1e3 * (a + b) / 2:g}" for a, b in zip(DISTANCE_BINS, DISTANCE_BINS[1:]))
    path = cr.write_table(
        "sensor_support",
        ["run (4 mm)", "far-wall sensor: mean (timeseries)",
         *(f"sensor re-read with: {label}" for label, _, _ in SUPPORTS),
         f"water pressure beside the far wall at {centres} mm from it",
         "u of the water flowing to the corner (m/s)", "0.5 u^2 / (g H)",
         "far-wall force: mean"],
        rows,
        preamble="The far-wall sensor's mean after the impact (t = "
                 f"{dam.AFTER_IMPACT[0]:g}-{dam.AFTER_IMPACT[1]:g} s), over rho0 g H, with "
                 "its own kernel and support (timeseries) and re-read on the same snapshots "
                 f"(every {1e3 * SNAPSHOT_INTERVAL:g} ms) with either kernel and support; the "
                 "water's pressure "
                 f"{1e3 * BESIDE_WALL[0]:g}-{1e3 * BESIDE_WALL[1]:g} mm up, corrected "
                 "hydrostatically to the sensor's height, against distance from the far wall, "
                 "over rho0 g H; the mean horizontal velocity u of the water flowing along the "
                 f"floor to the far wall (x = {APPROACH[0][0]:g}-{APPROACH[0][1]:g} m, "
                 f"y < {1e3 * APPROACH[1]:g} mm); the far wall's force over rho0 g H^2. "
                 "Produced by `scripts/sensor_support.py`.")
    print(open(path).read())


if __name__ == "__main__":
    main()
