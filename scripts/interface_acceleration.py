#!/usr/bin/python3
"""The moving wall's acceleration term (docs/physics.md, "Moving wall"),
without and with it: the elastic plate's tip against Antoci et al. 2007 and
the noise of the water's net force on the plate, and the fracture scene.

Runs the cases as they are, once with coupling.wall_acceleration false (the
coupler takes a_w = 0) and once true (what both cases take when it is unset:
their feedback ratio rho_f h_f / (rho_s e) is 0.55), into
out/validation/interface_acceleration_{without,with}_{elastic_plate,plate_fracture}.
Then the bound of the automatic choice: the elastic plate made lighter
(solid.density), to t = 0.1 s, with the term forced on and as chosen, into
out/validation/interface_acceleration_light_*. Writes
docs/results/interface_acceleration.md.

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


VARIANTS = [("without", "without the term", "false"),
            ("with", "with the term (the default: chosen for both cases)", "true")]
CASES = ["elastic_plate", "plate_fracture"]
# The lighter plates: mu_a = 1000 x 0.003 / (rho_s x 0.005) of 1.09, 2.2 and
# 12 (the stability map's lightest automatic row), on both sides of the bound 1.
LIGHT_DENSITIES = [550.0, 275.0, 50.0]
LIGHT_END_TIME = 0.1


def force_noise(out):
    """(mean, noise) of the force on the plate in x, over rho g H^2 / 2."""
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    return cr.pressure_noise(series["t"], series["plate_force_x"],
                             0.1 * math.sqrt(H / G), 0.5 * RHO * G * H * H, t_from=0.02,
                             t_to=0.4)


def tip_errors(out):
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    return cr.antoci_tip_rms(series), series["t"][-1]


def chosen_words(out):
    """What the coupler's log says it did with the term ("taken" or "left
    out"), from the launcher's log."""
    with open(os.path.join(out, "launcher.log")) as log:
        for line in log:
            if "acceleration in its pressure:" in line:
                return line.split("pressure:")[1].split("(")[0].strip()
    return "?"


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
    light_rows = []
    for rho_s in LIGHT_DENSITIES:
        mu_a = 1000.0 * 0.003 / (rho_s * 0.005)
        for key, words, settings in (
                ("forced", "forced on (true)", ["coupling.wall_acceleration=true"]),
                ("auto", "as chosen (unset)", [])):
            out = os.path.join(cr.REPO, "out", "validation",
                               f"interface_acceleration_light_{key}_{rho_s:.0f}")
            wall, failure = cr.run_or_reuse(
                "elastic_plate", out,
                [f"solid.density={rho_s}", f"run.end_time={LIGHT_END_TIME}"] + settings,
                args.reuse)
            series = cr.read_csv(os.path.join(out, "timeseries.csv"))
            light_rows.append([f"{rho_s / 1000.0:g}", f"{mu_a:.2f}", f"the term {words}: "
                               + chosen_words(out), f"{series['t'][-1]:.3f}",
                               f"{wall:.0f} s" if wall else "-", failure])
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
                 "(coupling.wall_acceleration true, which both cases take when it is unset, "
                 "their feedback ratio being 0.55) and without it (false: a_w = 0), by "
                 "`scripts/interface_acceleration.py`: the cases as they are, run "
                 "alternately on the shared two-core machine. Tip RMS "
                 "against Antoci et al. 2007 as in the elastic plate's table; the force on "
                 "the plate and its noise (RMS about the running mean over 0.1 sqrt(H/g), "
                 "0.02-0.4 s) over the water column's hydrostatic force rho g H^2 / 2 = "
                 f"{0.5 * RHO * G * H * H:.0f} N/m. Khayyer et al. 2018 reach 8.3 / 4.4 mm.")
    cr.write_table(
        "interface_acceleration",
        ["rho_s / rho_f", "feedback ratio mu_a = rho_f h_f / (rho_s e)", "run",
         "reached t (s)", "wall time", "failure"],
        light_rows,
        preamble="**The bound of the automatic choice.** The elastic plate made lighter "
                 f"(`solid.density`), to t = {LIGHT_END_TIME} s, with the term forced on and "
                 "as the coupler chooses it when `coupling.wall_acceleration` is unset: taken "
                 "where mu_a <= 1 with h_f the water's smoothing length (3 mm; the plate "
                 "e = 5 mm), left out above (docs/physics.md, \"Moving wall\").",
        mode="a")
    print(open(os.path.join(cr.RESULTS, "interface_acceleration.md")).read())


if __name__ == "__main__":
    main()
