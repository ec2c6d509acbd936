#!/usr/bin/python3
"""The two shipped solids side by side (issue 7): error, wall time and the
largest stable step on the oscillating plate and on the elastic plate.

The errors and wall times are the validation scripts' own results, read
from what they wrote:
  docs/results/oscillating_plate.md, oscillating_plate_tl.md
      (scripts/validate_oscillating_plate.py; the case's default resolution,
      16 particles across, the default velocity gradient of the Jaumann solid
      and the first, i.e. plotted, hourglass coefficient of the
      total-Lagrangian one)
  docs/results/elastic_plate_points.json
      (scripts/validate_elastic_plate.py; the multi-rate rows, the only
      configuration run with both solids)
This script adds only the step sizes, from short runs: for each solid, a
sweep of run.cfl on the oscillating plate (alone, 10 across) and on the
coupled elastic plate (multi-rate, as its validation), each stopping at its
first failure (a solver error or a run that falls short of its end). The
largest stable step is the largest swept run.cfl that ran to the end, and
the median dt (s) that run took; a sweep without a failure says so.

Writes docs/results/solid_comparison.md (README marker results:solid_comparison).
usage: /usr/bin/python3 scripts/solid_comparison.py [--out DIR] [--reuse]
"""
import json
import os
import re

import cosph_results as cr
import stability_map as sm

SOLIDS = {"jaumann": "Jaumann (`cosph-solid-jaumann`)",
          "total_lagrangian": "total-Lagrangian (`cosph-solid-tl`)"}
ALONE_CFLS = [0.3, 0.6, 1.0, 2.0, 4.0, 8.0]   # 0.3: the case's; 8: the largest run.cfl accepted
ALONE_END_S = 0.05                            # s: a fifth of a period, thousands of steps
COUPLED_CFLS = [0.25, 0.5, 1.0, 1.5, 2.0]
COUPLED_END_S = 0.03                          # s: the water's first impact on the plate
MULTIRATE = "coupling.max_substeps=32"        # as validate_elastic_plate.py's multi-rate rows
ERROR_ACROSS = 16                             # the oscillating plate's default resolution
SWEEP_ACROSS = 10                             # the sweeps' (cheaper; the step scales with dx)
ELASTIC_LABELS = {"jaumann": "multi-rate, max_substeps 32",
                  "total_lagrangian": "total-Lagrangian solid, multi-rate"}


def sweep(case, settings, cfls, end, out_root, tag):
    """[(cfl, stable, median dt, solver error or '')] up to and including the first failure."""
    results = []
    for cfl in cfls:
        out = os.path.join(out_root, f"{tag}_cfl_{cfl:g}")
        reached, dt, error, _ = sm.launch(case, out, settings + [f"run.cfl={cfl}"], end)
        # Stable: the physics ran to the end. An error after that (a process
        # that failed to shut down cleanly) is reported, but says nothing
        # about the step size.
        stable = reached >= end * (1 - 1e-9)
        results.append((cfl, stable, dt, sm.reason(error)))
        print(tag, results[-1], flush=True)
        if not stable:
            break
    return results


def largest_stable(results):
    """'CFL c, dt s' of the largest stable run, and what stopped the sweep."""
    stable = [r for r in results if r[1]]
    if not stable:
        return "none", f"fails at CFL {results[0][0]:g}: {results[0][3]}"
    cfl, _, dt, _ = stable[-1]
    failed = [r for r in results if not r[1]]
    limit = (f"fails at CFL {failed[0][0]:g}" if failed else
             f"no failure up to CFL {cfl:g}, the largest tried")
    after_end = [f"CFL {r[0]:g} ran to the end, then: " + re.sub(r"ipc://\S+", "its endpoint", r[3])
                 for r in stable if r[3]]
    return f"CFL {cfl:g}: dt {dt:.3g} s", "; ".join([limit] + after_end)


def markdown_rows(path):
    """The rows of the markdown table in a results file, as lists of cells."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("|") and not line.startswith("|--") and "---" not in line:
                rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
    return rows[1:]  # without the header


def oscillating_plate_result(model):
    """(period error, wall time, option label) at the default resolution: the
    first (default, plotted) velocity gradient or hourglass coefficient of the
    table."""
    name = "oscillating_plate.md" if model == "jaumann" else "oscillating_plate_tl.md"
    rows = markdown_rows(os.path.join(cr.RESULTS, name))
    option = rows[0][0]
    row = next(r for r in rows if r[0] == option and r[1] == str(ERROR_ACROSS))
    label = f"{option} velocity gradient" if model == "jaumann" else f"alpha {option}"
    return row[5], row[6], label


def elastic_plate_result(model):
    """(error, wall time) of the model's multi-rate run, which has a point only
    if it reached the end; the elastic plate table says where one stopped."""
    with open(os.path.join(cr.RESULTS, "elastic_plate_points.json")) as f:
        points = json.load(f)
    point = next((p for p in points if p["label"] == ELASTIC_LABELS[model]), None)
    if point is None:
        return "stopped early (see the elastic plate table)", ""
    return f"{point['error_name'].split(' (')[0]} {point['error']:.1f} mm", f"{point['wall_s']:.0f}"


def current_default_alpha():
    """solid.hourglass_control's default, from the code that applies it."""
    header = os.path.join(cr.REPO, "solid", "common", "solid_parameters.hpp")
    with open(header) as f:
        return re.search(r"kDefaultHourglassControl = ([0-9.]+);", f.read()).group(1)


def main():
    args = sm.parse_run_folder(__doc__.splitlines()[0], "solid_comparison")
    alone_settings = [f"solid.spacing={0.02 / SWEEP_ACROSS!r}"]

    rows = []
    for model, name in SOLIDS.items():
        error, wall, option = oscillating_plate_result(model)
        alone = sweep("oscillating_plate", alone_settings + [f"solid.model={model}"],
                      ALONE_CFLS, ALONE_END_S, args.out, f"alone_{model}")
        step, limit = largest_stable(alone)
        rows.append([f"{name}, {option}",
                     f"oscillating plate (alone; error {ERROR_ACROSS} across, step "
                     f"{SWEEP_ACROSS} across)",
                     f"period {error}", wall, step, limit])
    for model, name in SOLIDS.items():
        error, wall = elastic_plate_result(model)
        coupled = sweep("elastic_plate", [MULTIRATE, f"solid.model={model}"], COUPLED_CFLS,
                        COUPLED_END_S, args.out, f"coupled_{model}")
        step, limit = largest_stable(coupled)
        rows.append([name, "elastic plate (coupled, multi-rate)", error, wall,
                     step, limit])

    preamble = (
        "The two solids on both scenes, by `scripts/solid_comparison.py`. Error and wall time "
        "(one thread alone, two cores coupled, shared machine) are those of the validation "
        f"tables above: the oscillating plate's period against thin-plate theory at "
        f"{ERROR_ACROSS} particles across (the case's default), the elastic plate's free-end "
        "x displacement against Antoci et al. 2007, multi-rate (max_substeps 32). The largest stable step comes from a sweep of "
        f"run.cfl ({', '.join(f'{c:g}' for c in ALONE_CFLS)} alone, to t = {ALONE_END_S:g} s; "
        f"{', '.join(f'{c:g}' for c in COUPLED_CFLS)} coupled, to t = {COUPLED_END_S:g} s) "
        "that stops at the first run a solver stops with an error: the largest CFL number "
        "that ran, and the median step it took. The force limit 0.25 sqrt(h/|a|) caps the "
        "step too, so dt can stop growing with the CFL number. The hourglass coefficient of "
        f"the total-Lagrangian solid is its default, alpha = {current_default_alpha()}, in "
        "the sweeps and in the elastic plate; the oscillating plate's error row names the "
        "alpha it was run with.")
    path = cr.write_table("solid_comparison",
                          ["solid", "scene", "error", "wall time (s)",
                           "largest stable step", "sweep"], rows, preamble)
    with open(path) as f:
        print(f.read())


if __name__ == "__main__":
    main()
