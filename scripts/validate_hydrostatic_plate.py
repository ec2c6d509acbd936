#!/usr/bin/python3
"""Water column on a plate clamped at both ends (Fourey et al. 2017): the
mid-span deflection against the static beam theory at three resolutions.

Runs cases/hydrostatic_plate.pbtxt through the launcher (three processes)
with the water and plate spacings of RUNS (the case's default is the middle
one), reads the settled deflection (the mean over the last two periods of the
water column's acoustic mode, scripts/hydrostatic_plate.py, where the theory
is), and writes docs/figures/hydrostatic_plate.png (the deflection against
time, the theory marked; the error against the spacing) and
docs/results/hydrostatic_plate.md.

usage: /usr/bin/python3 scripts/validate_hydrostatic_plate.py [--reuse] [--only SUFFIX ...]
  --reuse   analyse the runs already in out/validation/hydrostatic_plate_* instead of running
  --only    run only these configurations, reuse the others
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import cosph_results as cr
import hydrostatic_plate as hp

# (label, folder suffix, water spacing, plate spacing), coarse to fine: the
# water and the plate refined together, the plate e/4, e/8 and e/16 across.
RUNS = [("coarse", "coarse", 0.04, 0.0125),
        ("the case", "default", 0.02, 0.00625),
        ("fine", "fine", 0.01, 0.003125)]
GOAL = 0.02  # relative, at the case's default resolution


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reuse", action="store_true",
                        help="analyse the runs in out/validation/hydrostatic_plate_* instead")
    parser.add_argument("--only", action="append", default=[],
                        help="run only these (" + ", ".join(r[1] for r in RUNS) + ")")
    args = parser.parse_args()

    p = hp.parameters()
    w_eb, w_t = hp.static_deflection(p)
    T = hp.column_period(p)
    fig, (ax, ax_conv) = plt.subplots(1, 2, figsize=(11, 4.2))
    rows, spacings, errors = [], [], []
    for n, (label, suffix, dx_f, dx_s) in enumerate(RUNS):
        out = os.path.join(cr.REPO, "out", "validation", f"hydrostatic_plate_{suffix}")
        reuse = args.reuse or bool(args.only and suffix not in args.only)
        wall, failure = cr.run_or_reuse(
            "hydrostatic_plate", out, [f"fluid.spacing={dx_f}", f"solid.spacing={dx_s}"], reuse)
        path = os.path.join(out, "timeseries.csv")
        if not os.path.exists(path):
            print(f"skipping {label}: no run in {out}")
            continue
        series = cr.read_csv(path)
        t = series["t"]
        w = hp.settled_deflection(t, series["tip_dy"])
        error = (w - w_t) / w_t
        ax.plot(t, -1e5 * series["tip_dy"], f"C{n}", lw=1.0,
                label=f"{label}: water {1e3 * dx_f:g} mm, plate {1e3 * dx_s:g} mm")
        ax.hlines(1e5 * w, t[-1] - 2 * T, t[-1], colors=f"C{n}", linestyles="--", lw=2)
        if np.isfinite(w):
            spacings.append(dx_s)
            errors.append(abs(error))
        rows.append([label, f"{1e3 * dx_f:g}", f"{1e3 * dx_s:g} ({p['thickness_e'] / dx_s:.0f} across)",
                     f"{t[-1]:.3f}", f"{1e5 * w:.3f}", f"{100 * error:+.1f} %",
                     f"{100 * (w - w_eb) / w_eb:+.1f} %",
                     f"{wall:.0f} s" if wall is not None else "-",
                     "" if not failure else failure.splitlines()[0]])
    ax.axhline(1e5 * w_t, color="k", lw=1, label=f"Timoshenko {1e5 * w_t:.2f}e-5 m")
    ax.axhline(1e5 * w_eb, color="k", ls=":", lw=1,
               label=f"Euler-Bernoulli {1e5 * w_eb:.2f}e-5 m")
    ax.set(xlabel="t (s)", ylabel="mid-span deflection (1e-5 m)",
           title="Water column on a clamped plate")
    ax.legend(fontsize=7, loc="lower right")
    if spacings:
        ax_conv.loglog(spacings, errors, "o-")
        ax_conv.axhline(GOAL, color="0.5", ls="--", label="goal at the default: 2 %")
        ax_conv.set(xlabel="plate spacing (m)", ylabel="|error| against Timoshenko",
                    title="Convergence")
        ax_conv.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(cr.FIGURES, exist_ok=True)
    fig.savefig(os.path.join(cr.FIGURES, "hydrostatic_plate.png"), dpi=110)

    cr.write_table(
        "hydrostatic_plate",
        ["run", "water spacing (mm)", "plate spacing (mm)", "reached t (s)",
         "settled deflection (1e-5 m)", "error against Timoshenko", "against Euler-Bernoulli",
         "wall time (2 cores)", "failure"],
        rows,
        preamble="Mid-span deflection of the plate under the water column, by "
                 "`scripts/validate_hydrostatic_plate.py`: the mean over the last two periods "
                 f"of the water column's acoustic mode (4 H / c0 = {T:.3f} s), against the "
                 "clamped-clamped beam of plane strain under q = rho g H + rho_s g e: "
                 f"Timoshenko (shear included, kappa = 5/6) {1e5 * w_t:.3f}e-5 m, the target; "
                 f"Euler-Bernoulli {1e5 * w_eb:.3f}e-5 m, the value Fourey et al. 2017 compare "
                 f"with. Goal: within {100 * GOAL:.0f} % at the case's default resolution.")
    print(open(os.path.join(cr.RESULTS, "hydrostatic_plate.md")).read())


if __name__ == "__main__":
    main()
