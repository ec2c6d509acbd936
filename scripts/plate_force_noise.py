#!/usr/bin/python3
"""The water's net force on the elastic plate and its noise, for the quieter
fluid options of pressure_noise.py (issue 38, item 4), and for three of them
also without the walls' friction.

Runs cases/elastic_plate.pbtxt with each water below (the case's own, the
default water, is Riemann + Wendland C2 at h = 1.5 dx with walls damping along
their normal), and measures as scripts/interface_acceleration.py does: the force on
the plate (coupling.csv force_on_solid_x, the same number as timeseries.csv's
plate_force_x), its mean and its noise (RMS about its running mean over
0.1 sqrt(H/g), H = 0.14 m, over 0.02-0.4 s), both over rho g H^2 / 2, and the
tip's RMS error against Antoci et al. 2007. The case's walls are 8 mm deep,
2h at h = 2 dx for its 2 mm water. Writes docs/results/plate_force_noise.md.

usage: /usr/bin/python3 scripts/plate_force_noise.py [--out DIR] [--reuse]
"""
import os

import cosph_results as cr
import interface_acceleration as ia
import pressure_noise as pn

OPTIONS = [("delta_sph", "delta-SPH, cubic spline, h = 1.3 dx (the earlier default)",
            cr.water()),
           ("riemann", "Riemann, cubic spline, h = 1.3 dx", cr.water(**pn.RIEMANN)),
           ("wendland_2dx", "delta-SPH, Wendland C2, h = 2 dx", cr.water(**pn.WENDLAND_2DX)),
           ("riemann_wendland_2dx", "Riemann, Wendland C2, h = 2 dx",
            cr.water(**pn.RIEMANN, **pn.WENDLAND_2DX)),
           ("riemann_wendland", "Riemann, Wendland C2, h = 1.5 dx",
            cr.water(**pn.RIEMANN, **pn.WENDLAND))]
# The same waters without the walls' friction along the tank's walls and the
# plate (fluid.wall_friction "normal", docs/physics.md, "Artificial viscosity").
NORMAL_WALLS = ["fluid.wall_friction=normal"]
OPTIONS += [(key + "_normal", label + ", walls and plate damping along their normal only"
             + (" (the default water: the case)" if key == "riemann_wendland" else ""),
             settings + NORMAL_WALLS) for key, label, settings in OPTIONS
            if key in ("delta_sph", "riemann_wendland", "riemann_wendland_2dx")]


def main():
    parser = cr.script_arguments(__doc__, "plate_force_noise")
    args = parser.parse_args()
    rows = []
    for key, label, settings in OPTIONS:
        out = os.path.join(args.out, key)
        os.makedirs(out, exist_ok=True)
        reuse = args.reuse and os.path.exists(os.path.join(out, "coupling.csv"))
        wall, failure = cr.run_or_reuse("elastic_plate", out, settings, reuse)
        if failure:
            print(f"{label}: {failure}", flush=True)
        (ex, ey), reached = ia.tip_errors(out)
        mean, noise = ia.force_noise(out)
        rows.append([label, f"{1e3 * ex:.1f}", f"{1e3 * ey:.1f}", f"{reached:.3f}",
                     f"{mean:.2f}", f"{noise:.3f}", f"{wall:.0f} s" if wall else "-"])
        print(rows[-1], flush=True)
    path = cr.write_table(
        "plate_force_noise",
        ["water", "tip x RMS (mm)", "tip y RMS (mm)", "reached t (s)",
         "force on plate, mean (rho g H^2/2)", "its noise (rho g H^2/2)",
         "wall time (shared 2 cores)"],
        rows,
        preamble="The elastic plate with the quieter water options of the dam break's table, "
                 "and three of them also without the friction along the tank's walls and the "
                 "plate (`fluid.wall_friction` \"normal\"): "
                 "the force of the water on the plate and its noise (RMS about the running "
                 "mean over 0.1 sqrt(H/g), 0.02-0.4 s), over the water column's hydrostatic "
                 f"force rho g H^2 / 2 = {0.5 * ia.RHO * ia.G * ia.H ** 2:.0f} N/m, and the "
                 "tip's RMS against Antoci et al. 2007 (Khayyer et al. 2018: 8.3 / 4.4 mm). "
                 "Produced by `scripts/plate_force_noise.py`.")
    print(open(path).read())


if __name__ == "__main__":
    main()
