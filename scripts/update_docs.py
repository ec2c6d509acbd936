#!/usr/bin/python3
"""Copies the result tables the scripts wrote (docs/results/NAME.md) into the
pages that show them, between the markers <!-- results:NAME --> and
<!-- /results:NAME -->, so that every number in the docs comes from a script.
The README's table of cases (marker results:cases) is made here, from those
same tables. Run after the validation and benchmark scripts.

  /usr/bin/python3 scripts/update_docs.py           rewrite the pages
  /usr/bin/python3 scripts/update_docs.py --check   exit 1 if a page is stale
"""
import argparse
import glob
import os
import re
import sys

import cosph_results as cr

PAGES = ["README.md"] + sorted(os.path.relpath(p, cr.REPO)
                               for p in glob.glob(os.path.join(cr.REPO, "docs", "*.md")))
MARKER = re.compile(r"<!-- results:([\w-]+) -->.*?<!-- /results:\1 -->", re.S)


def table_rows(name):
    """The rows of the table in docs/results/NAME.md as {column: text}, or []."""
    path = os.path.join(cr.RESULTS, name + ".md")
    if not os.path.exists(path):
        return []
    lines = [line.strip() for line in open(path) if line.strip().startswith("|")]
    if len(lines) < 3:
        return []
    cells = [[cell.strip() for cell in line.strip("|").split("|")] for line in lines]
    return [dict(zip(cells[0], row)) for row in cells[2:]]


def first(rows, match=None, marked=None):
    """The first row whose columns start with the texts of MATCH ({column: text})
    and, with MARKED ({column: text}), end with those texts, or None."""
    for row in rows:
        if all(row.get(column, "").startswith(text) for column, text in (match or {}).items()) \
                and all(row.get(column, "").endswith(text)
                        for column, text in (marked or {}).items()):
            return row
    return None


def case_results():
    """One line of result per case, taken from the validation tables."""
    missing = "no result yet: run its validation script"
    dam = first(table_rows("dam_break"))
    mps = first(table_rows("dam_break"), {"spacing (mm)": "Koshizuka"})
    plate = first(table_rows("oscillating_plate"),
                  {"velocity gradient": "quadratic", "particles across H": "16"})
    # The case leaves the stepping to the coupler, which chooses multi-rate
    # with 32 sub-steps for this plate (docs/auto_substeps.md): the row of the
    # case as it is, or, in a table from before that row, the same stepping.
    elastic = (first(table_rows("elastic_plate"), {"run": "cosph, the case"})
               or first(table_rows("elastic_plate"), {"run": "cosph, multi-rate, max_substeps 32"}))
    khayyer = first(table_rows("elastic_plate"), {"run": "Khayyer"})
    # The same plate bending with its modulus (docs/shell.md): the shell at the
    # case's spacing, and the case's own solid where it bends right.
    coupled_shell = table_rows("shell_coupled")
    stiff_shell = first(coupled_shell, {"run": "shell, plate 1 mm (the case's"})
    stiff_continuum = first(coupled_shell, {"run": "Jaumann, quadratic gradient"})
    bending_right = (f"; a plate that bends with its modulus gives {stiff_shell['tip x RMS (mm)']} / "
                     f"{stiff_shell['tip y RMS (mm)']} (the shell; the Jaumann solid at 10 across: "
                     f"{stiff_continuum['tip x RMS (mm)']} / {stiff_continuum['tip y RMS (mm)']}): "
                     "the case's plate, 5 particles across, bends more softly than its modulus"
                     if stiff_shell and stiff_continuum else "")
    fracture = first(table_rows("plate_fracture"), {"run": "synchronised"})
    # The case as it runs: its own settings at its default spacing, 10 mm.
    flume = [row for row in table_rows("wave_flume")
             if row.get("run") == "the case" and row.get("spacing (mm)") == "10"]

    # The wall-pressure case's own water (docs/physics.md, "Choice of water"),
    # the row validate_wall_pressure.py marks, and the earlier default's.
    default_water = {"option": cr.DEFAULT_WATER_MARK}
    earlier_water = "delta-SPH (Marrone et al. 2011), the earlier default"
    wall = (first(table_rows("wall_pressure"), {"spacing (mm)": "6"}, default_water)
            or first(table_rows("wall_pressure"), marked=default_water))
    buchner = first(table_rows("wall_pressure"), {"option": "Buchner"})
    # The same runs against the converged 2-D solution: the default's load by
    # the floor, and the earlier default's, with the walls' friction.
    two_d = table_rows("wall_pressure_2d_reference")
    corner = "load at 6 mm (t* 3.3-5.2)"
    default_load = first(two_d, {"spacing (mm)": "6"}, default_water)
    friction = first(two_d, {"option": earlier_water, "spacing (mm)": "6"})
    de_courcy = first(two_d, {"option": "De Courcy"})
    against_2d = (f"; by the floor {default_load[corner]} rho g H against the converged 2-D "
                  f"solution's {de_courcy[corner]} (De Courcy 2024; delta-SPH with the walls' "
                  f"friction: {friction[corner]})"
                  if default_load and friction and de_courcy else "")

    def text(row, make):
        return make(row) if row else missing

    rows = [
        ("[dam break](cases/dam_break.pbtxt)", "water column collapsing in a tank",
         text(dam, lambda r: f"front RMS error {r['RMS rel. error (T <= 3.1)']} against Martin & "
              f"Moyce 1952 at {r['spacing (mm)']} mm"
              + (f" (Koshizuka & Oka's MPS: {mps['RMS rel. error (T <= 3.1)']})" if mps else "")),
         "validation.md#dam-break-scene-1"),
        ("[wall pressure](cases/dam_break_wall_pressure.pbtxt)",
         "a dam break striking a wall: the pressure on it",
         text(wall, lambda r: f"sensor RMS {r['P1 RMS vs experiment, as read']} rho g H against "
              f"Buchner 2002 at {r['spacing (mm)']} mm; load between the impacts "
              f"{r['plateau mean (t* 3.3-5.2)']} rho g H"
              + (f" (experiment: {buchner['plateau mean (t* 3.3-5.2)']})" if buchner else "")
              + against_2d),
         "validation.md#the-load-on-a-wall-against-an-experiment-buchner-2002"),
        ("[oscillating plate](cases/oscillating_plate.pbtxt)", "a clamped plate vibrating in vacuum",
         text(plate, lambda r: f"period {r['error vs theory']} against thin-plate theory at "
              f"{r['particles across H']} particles across"),
         "validation.md#the-solid-alone-oscillating-plate"),
        ("[elastic plate](cases/elastic_plate.pbtxt)", "water bending a rubber plate (the main case)",
         text(elastic, lambda r: f"tip RMS {r['tip x RMS (mm)']} / {r['tip y RMS (mm)']} mm (x / y) "
              f"against Antoci et al. 2007, in {r['wall time (2 cores)']} on 2 cores"
              + (f" (Khayyer 2018: {khayyer['tip x RMS (mm)']} / {khayyer['tip y RMS (mm)']})"
                 if khayyer else "") + bending_right),
         "validation.md#coupled-the-elastic-plate-of-antoci-et-al-scene-2"),
        ("[plate fracture](cases/plate_fracture.pbtxt)", "the same plate, weakened, broken by the water",
         text(fracture, lambda r: f"first failure at t = {r['first failure t (s)']} s, the piece "
              f"free by {r['piece free by t (s)']} s, its centre at x = {r['broken_x at end (m)']} m at the end"),
         "validation.md#fracture-the-plate-broken-by-the-flow-scene-3"),
        ("[wave flume](cases/wave_flume.pbtxt)", "a piston wave maker, waves down a flume to a beach",
         text(flume, lambda rows: "wave height against Biesel's linear theory: " + ", ".join(
             f"{r['error']} at T = {r['period T (s)']} s" for r in rows) + " at 10 mm"
             + ("; the beach reflects " + ", ".join(
                 r["measured Kr (window)"].split()[0] for r in rows) + " of the height"
                if all(r.get("measured Kr (window)", "-") != "-" for r in rows) else "")),
         "validation.md#wave-flume-a-piston-wave-maker"),
    ]
    lines = ["| case | what | result | details |", "|---|---|---|---|"]
    lines += [f"| {case} | {what} | {result} | [validation](docs/{link}) |"
              for case, what, result, link in rows]
    return "\n".join(lines)


def body(name):
    if name == "cases":
        return case_results()
    path = os.path.join(cr.RESULTS, name + ".md")
    if not os.path.exists(path):
        return f"_(no results yet: run the script that writes docs/results/{name}.md)_"
    return open(path).read().strip()


def updated(text):
    return MARKER.sub(lambda m: f"<!-- results:{m.group(1)} -->\n{body(m.group(1))}\n"
                                f"<!-- /results:{m.group(1)} -->", text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="change nothing; exit 1 naming each page that is not current")
    args = parser.parse_args()
    stale = []
    for page in PAGES:
        path = os.path.join(cr.REPO, page)
        old = open(path).read()
        new = updated(old)
        if new == old:
            continue
        stale.append(page)
        if not args.check:
            with open(path, "w") as f:
                f.write(new)
    if args.check:
        for page in stale:
            print(f"update_docs: {page} is not current: run /usr/bin/python3 scripts/update_docs.py",
                  file=sys.stderr)
        return 1 if stale else 0
    print("updated: " + ", ".join(stale) if stale else "all pages already current")
    return 0


if __name__ == "__main__":
    sys.exit(main())
