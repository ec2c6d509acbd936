#!/usr/bin/python3
"""The moving wall's acceleration term (docs/physics.md, "Moving wall"),
without and with it: the elastic plate's tip against Antoci et al. 2007 and
the noise of the water's net force on the plate, and the fracture scene.

Runs the cases as they are, once with coupling.wall_acceleration false (the
default: the coupler takes a_w = 0) and once true, into
out/validation/interface_acceleration_{without,with}_{elastic_plate,plate_fracture}.
Writes docs/results/interface_acceleration.md.

The force noise is measured as the dam break's probes are
(cosph_results.pressure_noise): the RMS of the force on the plate about its
own running mean over 0.1 sqrt(H/g), H = 0.14 m the column's height, over
0.02 s <= t <= 0.4 s, both over the column's hydrostatic force
rho g H^2 / 2 = 96 N/m (timeseries.csv's plate_force_x).

usage: /usr/bin/python3 scripts/interface_acceleration.py [--reuse]
  --reuse   analyse the runs already in out/validation/interface_acceleration_* instead of running
"""
import math
import os

import numpy as np

import cosph_results as cr

RHO, G, H = 1000.0, 9.81, 0.14  # the elastic plate's water column


VARIANTS = [("without", "without the term (the default)", "false"),
            ("with", "with the term", "true")]
CASES = ["elastic_plate", "plate_fracture"]


def force_noise(out):
    """(mean, noise) of the force on the plate in x, over rho g H^2 / 2."""
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    return cr.pressure_noise(series["t"], series["plate_force_x"],
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
    args = cr.script_arguments(__doc__).parse_args()
    runs = {}
    for case in CASES:  # alternately, so that the machine's load falls on both alike
        for key, _, value in VARIANTS:
            out = os.path.join(cr.REPO, "out", "validation", f"interface_acceleration_{key}_{case}")
            wall, failure = cr.run_or_reuse(case, out, [f"coupling.wall_acceleration={value}"],
                                            args.reuse)
            runs[(key, case)] = (out, wall, failure)
    rows = []
    for key, words, _ in VARIANTS:
        out, wall, failure = runs[(key, "elastic_plate")]
        (ex, ey), reached = tip_errors(out)
        mean, noise = force_noise(out)
        rows.append([f"elastic plate, {words}", f"{1e3 * ex:.1f}", f"{1e3 * ey:.1f}",
                     f"{reached:.3f}", f"{mean:.2f}", f"{noise:.3f}", "", "", "",
                     f"{wall:.0f} s" if wall else "-", failure])
    for key, words, _ in VARIANTS:
        out, wall, failure = runs[(key, "plate_fracture")]
        reached, first, failed, bx, by = fracture_summary(out)
        rows.append([f"plate fracture, {words}", "", "", f"{reached:.3f}", "", "",
                     f"{first:.4f}", f"{failed}", f"{bx:.3f}, {by:.3f}",
                     f"{wall:.0f} s" if wall else "-", failure])
    cr.write_table(
        "interface_acceleration",
        ["run", "tip x RMS (mm)", "tip y RMS (mm)", "reached t (s)",
         "force on plate, mean (rho g H^2/2)", "its noise (rho g H^2/2)",
         "first failure t (s)", "failed at end", "broken part at end (m)", "wall time",
         "failure"],
        rows,
        preamble="The moving wall's pressure with the solid's acceleration "
                 "(coupling.wall_acceleration true) and without it (false, the default: "
                 "a_w = 0), by `scripts/interface_acceleration.py`: the cases as they are, run "
                 "alternately on the shared two-core machine. Tip RMS "
                 "against Antoci et al. 2007 as in the elastic plate's table; the force on "
                 "the plate and its noise (RMS about the running mean over 0.1 sqrt(H/g), "
                 "0.02-0.4 s) over the water column's hydrostatic force rho g H^2 / 2 = "
                 f"{0.5 * RHO * G * H * H:.0f} N/m. Khayyer et al. 2018 reach 8.3 / 4.4 mm.")
    print(open(os.path.join(cr.RESULTS, "interface_acceleration.md")).read())


if __name__ == "__main__":
    main()
