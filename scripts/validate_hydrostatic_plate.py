#!/usr/bin/python3
"""Water column on a plate clamped at both ends (Fourey et al. 2017): the
mid-span deflection against the static beam theory, the plate a shell (the
case's model) and a continuum Jaumann solid (for comparison).

Runs cases/hydrostatic_plate.pbtxt through the launcher (three processes)
with the solid model and the water and plate spacings of RUNS, reads the
settled deflection (the mean over the last two periods of the water column's
acoustic mode, scripts/hydrostatic_plate.py, where the theory is), and writes
docs/figures/hydrostatic_plate.png (the deflection against time, the theory
marked; the error against the spacing), docs/results/hydrostatic_plate.md and,
for scripts/speed_accuracy.py, docs/results/hydrostatic_plate_points.json:
the shell runs of the error panel that have a run in out/validation/ (run now
or reused, not kept from the table), each with its wall time and the CPU time
of its three processes. Every run sets run.threads=1, so that its wall time
compares with the other exact references' (solids alone on one thread).

The Jaumann runs take 6 and 21 minutes and run only when asked for (--only):
without a run of its own in out/validation/, a Jaumann row is kept from the
table the script wrote before (matched by model and spacings), marked so.

usage: /usr/bin/python3 scripts/validate_hydrostatic_plate.py [--reuse] [--only SUFFIX ...]
  --reuse   analyse the runs already in out/validation/hydrostatic_plate_* instead of running
  --only    run only these configurations, reuse the others
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr
import hydrostatic_plate as hp

# (label, folder suffix, solid model, water spacing, plate spacing, extra
# settings). The shell: the water and the plate refined together, the plate
# L/32 and L/64 along (L/64 = 0.0156 m: the finest at which the thin-box
# rule, at most 6 spacings across, takes e = 0.05 m with a particle on each
# clamp's face); the water 40, 20 and 10 mm on the case's plate; the plate
# L/32 and L/64 under the case's water. The Jaumann solid (the case's model
# before): e/4 and e/8 across, with the coupler's automatic sub-steps.
SHELL, JAUMANN = "shell", "jaumann"
RUNS = [("shell, coarse", "shell_coarse", SHELL, 0.04, 0.03125, []),
        ("shell, the case", "shell_default", SHELL, 0.02, 0.015625, []),
        # What the case set before the shell had its damping: the same run in
        # windows of at most 8 shell steps.
        ("shell, the case, max_substeps 8", "shell_default_w8", SHELL, 0.02, 0.015625,
         ["coupling.max_substeps=8"]),
        ("shell, coarse water", "shell_coarse_water", SHELL, 0.04, 0.015625, []),
        ("shell, coarse plate", "shell_coarse_plate", SHELL, 0.02, 0.03125, []),
        ("shell, fine water", "shell_fine_water", SHELL, 0.01, 0.015625, []),
        ("Jaumann, coarse", "coarse", JAUMANN, 0.04, 0.0125,
         ["solid.model=jaumann", "coupling.max_substeps=0"]),
        ("Jaumann, the case before", "default", JAUMANN, 0.02, 0.00625,
         ["solid.model=jaumann", "coupling.max_substeps=0"])]
RUN_BY_DEFAULT = {SHELL}
# The figure's error panel: its series, and which spacing each run is
# plotted against. The shell's series are also the speed-accuracy chart's.
WATER_REFINED = "shell: the water refined (plate L/64)"
PLATE_REFINED = "shell: the plate refined (water 20 mm)"
BOTH_REFINED = "shell: both refined"
JAUMANN_REFINED = "Jaumann: both refined"
SERIES = {"shell_coarse": [(BOTH_REFINED, "water")],
          "shell_coarse_water": [(WATER_REFINED, "water")],
          "shell_default": [(WATER_REFINED, "water"), (PLATE_REFINED, "plate"),
                            (BOTH_REFINED, "water")],
          "shell_fine_water": [(WATER_REFINED, "water")],
          "shell_coarse_plate": [(PLATE_REFINED, "plate")],
          "coarse": [(JAUMANN_REFINED, "plate")], "default": [(JAUMANN_REFINED, "plate")]}
# The deflection panel: the runs at water 40 mm swing with the plate's first
# mode (262 Hz) over the whole run and would hide the others.
SHOWN_IN_TIME = {"shell_default", "shell_coarse_plate", "shell_fine_water"}
GOAL = 0.02  # relative, at the case's default resolution
HEADER = ["run", "solid", "water spacing (mm)", "plate spacing (mm)", "reached t (s)",
          "settled deflection (1e-5 m)", "error against Timoshenko", "against Euler-Bernoulli",
          "spread over windows", "water's force / rho g H L",
          "Timoshenko under that force (1e-5 m)",
          "wall time (2 cores)", "CPU time (3 processes)", "failure"]
NOT_RERUN = "not rerun: kept from the earlier table"


def earlier_rows():
    """{(solid, water spacing cell, plate spacing cell): {column: cell}} of the
    table the script wrote before; a table without a solid column was of the
    Jaumann solid."""
    path = os.path.join(cr.RESULTS, "hydrostatic_plate.md")
    if not os.path.exists(path):
        return {}
    lines = [line.strip() for line in open(path) if line.startswith("|")]
    if len(lines) < 2:
        return {}
    split = lambda line: [cell.strip() for cell in line.strip("|").split("|")]
    header = split(lines[0])
    rows = {}
    for line in lines[2:]:
        cells = dict(zip(header, split(line)))
        key = (cells.get("solid", JAUMANN), cells["water spacing (mm)"],
               cells["plate spacing (mm)"])
        rows[key] = cells
    return rows


def spacing_cells(p, model, dx_f, dx_s):
    plate = (f"{1e3 * dx_s:g} ({p['thickness_e'] / dx_s:.0f} across)" if model == JAUMANN
             else f"{1e3 * dx_s:g} ({p['span_L'] / dx_s:.0f} along)")
    return f"{1e3 * dx_f:g}", plate


def speed_point(series, p, dx_f, dx_s, wall, cpu, error):
    """A run for scripts/speed_accuracy.py: |error| against Timoshenko, the
    exact static deflection of the shell's beam model."""
    refined = series.split(": ")[1].split(" (")[0].replace("the ", "")  # "water refined"
    # The same label in every series: the case's point, shared, reads as one.
    label = f"{1e3 * dx_f:g} mm + L/{p['span_L'] / dx_s:.0f}"  # the water's + the plate's
    return {"series": f"hydrostatic plate, shell, {refined}", "label": label, "wall_s": wall,
            "cpu_s": cpu, "error": 100 * abs(error),
            "error_name": "hydrostatic plate: |deflection error| vs Timoshenko (%)",
            "exact": True}


def main():
    parser = cr.script_arguments(__doc__)
    parser.add_argument("--only", action="append", default=[],
                        help="run only these (" + ", ".join(r[1] for r in RUNS) + ")")
    args = parser.parse_args()

    p = hp.parameters()
    w_eb, w_t = hp.static_deflection(p)
    T = hp.column_period(p)
    fig, (ax, ax_conv) = plt.subplots(1, 2, figsize=(11, 4.2))
    earlier = earlier_rows()
    rows, speed_points = [], []
    convergence = {WATER_REFINED: [], PLATE_REFINED: [], BOTH_REFINED: [], JAUMANN_REFINED: []}
    for n, (label, suffix, model, dx_f, dx_s, extra) in enumerate(RUNS):
        out = os.path.join(cr.REPO, "out", "validation", f"hydrostatic_plate_{suffix}")
        water_cell, plate_cell = spacing_cells(p, model, dx_f, dx_s)
        asked = suffix in args.only if args.only else model in RUN_BY_DEFAULT
        path = os.path.join(out, "timeseries.csv")
        if not args.reuse and asked:
            wall, failure = cr.run_or_reuse(
                "hydrostatic_plate", out,
                [f"fluid.spacing={dx_f}", f"solid.spacing={dx_s}", "run.threads=1"] + extra,
                False)
        elif os.path.exists(path):
            wall, failure = cr.run_or_reuse("hydrostatic_plate", out, [], True)
        else:
            kept = earlier.get((model, water_cell, plate_cell))
            if kept is None:
                print(f"skipping {label}: no run in {out}")
                continue
            kept = dict(kept, run=label, solid=model)
            if NOT_RERUN not in kept.get("failure", ""):
                kept["failure"] = "; ".join(c for c in (NOT_RERUN, kept.get("failure", "")) if c)
            rows.append([kept.get(column, "") for column in HEADER])
            error = float(kept["error against Timoshenko"].rstrip(" %")) / 100
            for name, spacing in SERIES.get(suffix, []):
                convergence[name].append((dx_f if spacing == "water" else dx_s, abs(error)))
            continue
        cpu = sum(cr.logged_cpu_times(out).values()) or None
        series = cr.read_csv(path)
        t = series["t"]
        w = hp.settled_deflection(t, series["tip_dy"])
        error = (w - w_t) / w_t
        # The cross-check of the coupling alone: the load the water passed
        # (the settled force on the plate, whose held ends carry the walls,
        # not water) and the beam's deflection under it and the plate's weight.
        force = -hp.settled_mean(t, series["plate_force_y"])
        weight = p["solid_density_rho_s"] * p["gravity_g"] * p["thickness_e"]
        q = hp.water_load(p) / p["span_L"] + weight
        w_force = w_t * (force / p["span_L"] + weight) / q
        if suffix in SHOWN_IN_TIME:
            ax.plot(t, -1e5 * series["tip_dy"], f"C{n}", lw=0.8,
                    label=f"{label}: water {1e3 * dx_f:g} mm, plate {1e3 * dx_s:g} mm")
            if np.isfinite(w):
                ax.hlines(1e5 * w, t[-1] - 2 * T, t[-1], colors=f"C{n}", linestyles="--", lw=2)
        if np.isfinite(w):
            for name, spacing in SERIES.get(suffix, []):
                convergence[name].append((dx_f if spacing == "water" else dx_s, abs(error)))
                if wall is not None and not failure:
                    speed_points.append(speed_point(name, p, dx_f, dx_s, wall, cpu, error))
        # How well the reading is settled: the same mean over each two-period
        # window that starts a whole period or more after the load, the
        # largest less the smallest, against w_T.
        windows = [-np.mean(series["tip_dy"][(t >= start) & (t < start + 2 * T)])
                   for start in np.arange(T, t[-1] - 2 * T + 1e-9, T)]
        spread = (max(windows) - min(windows)) / w_t if windows else float("nan")
        # A run shorter than the averaging window has no settled value.
        settled = ([f"{1e5 * w:.3f}", f"{100 * error:+.2f} %", f"{100 * (w - w_eb) / w_eb:+.2f} %",
                    f"{100 * spread:.2f} %", f"{force / hp.water_load(p):.4f}",
                    f"{1e5 * w_force:.3f}"]
                   if np.isfinite(w) else ["-"] * 6)
        rows.append([label, model, water_cell, plate_cell, f"{t[-1]:.3f}"] + settled +
                    [f"{wall:.0f} s" if wall is not None else "-",
                     f"{cpu:.0f} s" if cpu is not None else "-",
                     "" if not failure else failure.splitlines()[0]])
    ax.axhline(1e5 * w_t, color="k", lw=1, label=f"Timoshenko {1e5 * w_t:.2f}e-5 m")
    ax.axhline(1e5 * w_eb, color="k", ls=":", lw=1,
               label=f"Euler-Bernoulli {1e5 * w_eb:.2f}e-5 m")
    ax.set(xlabel="t (s)", ylabel="mid-span deflection (1e-5 m)",
           title="Water column on a clamped plate")
    ax.legend(fontsize=7, loc="lower right")
    for name, marker in ((WATER_REFINED, "o-"), (PLATE_REFINED, "^-"), (BOTH_REFINED, "v-"),
                         (JAUMANN_REFINED, "s-")):
        points = sorted(convergence[name])
        if points:
            ax_conv.loglog([x for x, _ in points], [e for _, e in points], marker, label=name)
    ax_conv.axhline(GOAL, color="0.5", ls="--", label="goal at the default: 2 %")
    ax_conv.set(xlabel="the refined spacing (m; both refined: the water's)",
                ylabel="|error| against Timoshenko",
                title="Convergence")
    ax_conv.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    fig.savefig(os.path.join(cr.FIGURES, "hydrostatic_plate.png"), dpi=110)

    cr.write_table(
        "hydrostatic_plate", HEADER, rows,
        preamble="Mid-span deflection of the plate under the water column, by "
                 "`scripts/validate_hydrostatic_plate.py`: the mean over the last two periods "
                 f"of the water column's acoustic mode (4 H / c0 = {T:.3f} s), against the "
                 "clamped-clamped beam of plane strain under q = rho g H + rho_s g e: "
                 f"Timoshenko (shear included, kappa = 5/6) {1e5 * w_t:.3f}e-5 m, the target; "
                 f"Euler-Bernoulli {1e5 * w_eb:.3f}e-5 m, the value Fourey et al. 2017 compare "
                 f"with. Goal: within {100 * GOAL:.0f} % at the case's default resolution. "
                 "The spread: the largest less the smallest of the same mean over each two-period "
                 "window from one period on (the settled value's uncertainty). "
                 "The water's force on the plate, over the same window, against the water's "
                 "weight rho g H L, and Timoshenko's deflection under that force and the "
                 "plate's weight: what the coupling passed, apart from the solid's own error. "
                 "Both solids with the coupler's automatic choice unless the row says otherwise: "
                 "multi-rate, the shell's windows bound by its damping (docs/auto_substeps.md), "
                 "the Jaumann solid's at 32 steps. Rows marked not rerun were run before that "
                 "bound (the shell's) or are kept from an earlier table (the Jaumann solid's); "
                 "wall times on the shared machine, each solver on one thread "
                 "(run.threads=1; the rows kept from earlier tables: as many as the solver "
                 "chose), the CPU time the coupler's, the fluid's and the solid's together.")
    cr.write_points("hydrostatic_plate", speed_points)
    print(open(os.path.join(cr.RESULTS, "hydrostatic_plate.md")).read())


if __name__ == "__main__":
    main()
