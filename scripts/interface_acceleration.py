#!/usr/bin/python3
"""The moving wall's acceleration term (docs/physics.md, "Moving wall"),
before and after: the elastic plate's tip against Antoci et al. 2007 and the
noise of the water's net force on the plate, and the fracture scene.

Analyses runs of the cases as they are (no --set), made alternately, in
out/ab/{before,after}_{elastic_plate,plate_fracture}: "before" by a build of
the code without the term (protocol version 2: the coupler took a_w = 0),
"after" by this one (the commands: out/ab.sh in the merge's log). Writes
docs/results/interface_acceleration.md.

The force noise is measured as the dam break's probes are
(cosph_results.pressure_noise): the RMS of the force on the plate about its
own running mean over 0.1 sqrt(H/g), H = 0.14 m the column's height, over
0.02 s <= t <= 0.4 s, both over the column's hydrostatic force
rho g H^2 / 2 = 96 N/m. The force is read from coupling.csv
(force_on_solid_x), which both builds write (timeseries.csv's plate_force_x
is the same number from this build on).

usage: /usr/bin/python3 scripts/interface_acceleration.py [--runs DIR]
"""
import argparse
import math
import os

import numpy as np

import cosph_results as cr

RHO, G, H = 1000.0, 9.81, 0.14  # the elastic plate's water column


def force_noise(out):
    """(mean, noise) of the force on the plate in x, over rho g H^2 / 2."""
    coupling = cr.read_csv(os.path.join(out, "coupling.csv"))
    return cr.pressure_noise(coupling["t"], coupling["force_on_solid_x"],
                             0.1 * math.sqrt(H / G), 0.5 * RHO * G * H * H, t_from=0.02,
                             t_to=0.4)


def tip_errors(out):
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    return cr.antoci_tip_rms(series), series["t"][-1]


def fracture_summary(out):
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    failed = series["failed"]
    first = series["t"][np.argmax(failed > 0)] if failed[-1] > 0 else float("nan")
    return (series["t"][-1], first, int(failed[-1]), series["broken_x"][-1],
            series["broken_y"][-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", default=os.path.join(cr.REPO, "out", "ab"))
    args = parser.parse_args()
    runs = [os.path.join(args.runs, f"{variant}_{case}") for variant in ("before", "after")
            for case in ("elastic_plate", "plate_fracture")]
    missing = [out for out in runs if not os.path.exists(os.path.join(out, "timeseries.csv"))]
    if missing:
        # The runs come from two builds (the "before" one without the term): a
        # clone that has not made them keeps the table as it was made.
        print(f"interface_acceleration: no runs in {', '.join(missing)}: "
              "docs/results/interface_acceleration.md stays as it is")
        return
    rows = []
    for variant in ("before", "after"):
        out = os.path.join(args.runs, f"{variant}_elastic_plate")
        (ex, ey), reached = tip_errors(out)
        mean, noise = force_noise(out)
        wall = cr.logged_wall_time(out)
        rows.append([f"elastic plate, {variant}", f"{1e3 * ex:.1f}", f"{1e3 * ey:.1f}",
                     f"{reached:.3f}", f"{mean:.2f}", f"{noise:.3f}", "", "", "",
                     f"{wall:.0f} s" if wall else "-"])
    for variant in ("before", "after"):
        out = os.path.join(args.runs, f"{variant}_plate_fracture")
        reached, first, failed, bx, by = fracture_summary(out)
        wall = cr.logged_wall_time(out)
        rows.append([f"plate fracture, {variant}", "", "", f"{reached:.3f}", "", "",
                     f"{first:.4f}", f"{failed}", f"{bx:.3f}, {by:.3f}",
                     f"{wall:.0f} s" if wall else "-"])
    cr.write_table(
        "interface_acceleration",
        ["run", "tip x RMS (mm)", "tip y RMS (mm)", "reached t (s)",
         "force on plate, mean (rho g H^2/2)", "its noise (rho g H^2/2)",
         "first failure t (s)", "failed at end", "broken part at end (m)", "wall time"],
        rows,
        preamble="The moving wall's pressure with the solid's acceleration (after) and "
                 "without it (before, a_w = 0), by `scripts/interface_acceleration.py`: the "
                 "cases as they are, run alternately on the shared two-core machine. Tip RMS "
                 "against Antoci et al. 2007 as in the elastic plate's table; the force on "
                 "the plate and its noise (RMS about the running mean over 0.1 sqrt(H/g), "
                 "0.02-0.4 s) over the water column's hydrostatic force rho g H^2 / 2 = "
                 f"{0.5 * RHO * G * H * H:.0f} N/m. Khayyer et al. 2018 reach 8.3 / 4.4 mm.")
    print(open(os.path.join(cr.RESULTS, "interface_acceleration.md")).read())


if __name__ == "__main__":
    main()
