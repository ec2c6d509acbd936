#!/usr/bin/python3
"""Where the methods break: a stability map, produced by runs, for the README.

Sweeps, each run short and each blow-up caught and reported (a run that stops
with an error is a result, not a failure of this script):
  1. run.cfl for the fluid alone (dam break, 8 mm), the solid alone
     (oscillating plate, 6 particles across) and the coupled elastic plate
     (multi-rate, so the sweep stays affordable);
  2. the coupled plate with the solid stepped whole at the fluid's step
     (coupling.solid_step = fluid), which must stop with an error;
  3. delta-SPH density diffusion off and on, and the default water (Riemann):
     pressure noise in a still tank and in the dam break, over the particles
     and at the case's floor sensor;
  4. the solid-to-fluid density ratio of the coupled plate, down from 1.1,
     multi-rate, then with the case's default, the coupler's automatic choice
     (docs/auto_substeps.md), and the first ratio that breaks multi-rate again
     with synchronised steps.
(Artificial stress off against on: scripts/tensile_instability.py.)

Writes docs/results/stability_map.md and docs/figures/stability_cfl.png.
usage: /usr/bin/python3 scripts/stability_map.py [--out DIR] [--reuse]
"""
import argparse
import glob
import os
import re
import subprocess
import time

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import cosph_results as cr  # noqa: E402

CFLS = [0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0]
COUPLED_CFLS = [0.25, 0.5, 1.0, 1.5, 2.0]
DENSITY_RATIOS = [1.1, 0.5, 0.25, 0.1, 0.05, 0.02, 0.01]
MULTIRATE = ["coupling.max_substeps=64"]
SYNCHRONISED = ["coupling.max_substeps=1"]

SCENES = {  # name: (case, settings, end time)
    "fluid alone (dam break, 8 mm)": ("dam_break", [], 0.3),
    # The solver's default (linear) velocity gradient, not the plate case's
    # quadratic one: the map is of the methods the scenes at large run with.
    "solid alone (oscillating plate, 6 across)": (
        "oscillating_plate", ["solid.spacing=0.0033333333333333", "solid.velocity_gradient=linear"],
        0.1),
    "solid alone, total-Lagrangian (same plate)": (
        "oscillating_plate", ["solid.spacing=0.0033333333333333", "solid.model=total_lagrangian"],
        0.1),
    "coupled elastic plate (multi-rate)": ("elastic_plate", MULTIRATE, 0.03),
}


REUSE = False  # --reuse: read runs already in --out instead of running them again


def launch(case, out, settings, end_time):
    """Runs a case (or, with --reuse, reads its earlier run); returns (reached
    time, median dt, error line or '', wall seconds)."""
    log_path = os.path.join(out, "launcher.log")
    if REUSE and os.path.exists(log_path):
        with open(log_path) as log:
            wall, output, code = float(log.readline()), log.read(), None
        return summarise(out, output, wall, code, " ".join([case] + settings))
    command = [os.path.join(cr.REPO, "coupler", "cosph"), "run", case, "--out", out, "--quiet",
               "--overwrite",
               "--set", f"run.end_time={end_time}", "--set", f"run.snapshot_interval={end_time}"]
    for setting in settings:
        command += ["--set", setting]
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=3600)
    wall = time.monotonic() - start
    os.makedirs(out, exist_ok=True)
    with open(log_path, "w") as log:
        log.write(f"{wall}\n{result.stdout}")
    return summarise(out, result.stdout, wall, result.returncode, " ".join(command))


def summarise(out, output, wall, returncode, command):
    lines = [line for line in output.splitlines() if "error:" in line]
    if returncode not in (0, None) and not lines:
        raise RuntimeError(f"{command} failed without a message:\n{output}")
    error = lines[0] if lines else ""
    # A coupled run's timeseries.csv ends at its last output row; the solver's
    # error tells when it really stopped.
    stopped = re.search(r"t = ([0-9.eE+-]+) s, step", error)
    series_path = os.path.join(out, "timeseries.csv")
    series = cr.read_csv(series_path) if os.path.exists(series_path) else None
    if series is None or len(series["t"]) == 0:
        return float(stopped.group(1)) if stopped else 0.0, float("nan"), error, wall
    dt = series["dt"][series["dt"] > 0]
    reached = max(float(series["t"][-1]), float(stopped.group(1)) if stopped else 0.0)
    return reached, float(np.median(dt)) if len(dt) else float("nan"), error, wall


def spray_note(out):
    """How much water left the run as thinned spray (README "Spray"), if any."""
    series_path = os.path.join(out, "timeseries.csv")
    if not os.path.exists(series_path):
        return ""
    removed = cr.spray_removed(cr.read_csv(series_path))
    if removed in ("-", "0"):
        return ""
    return f" ({removed} water particle{'' if removed == '1' else 's'} left as spray)"


def reason(error):
    """The solver's own words, without the paths."""
    if not error:
        return ""
    text = error.split("error:")[-1].strip()
    # Whichever process printed first: the same words, relayed by the coupler.
    text = re.sub(r"^(?:coupler: )?(?:fluid|solid) stopped: (?:fluid|solid): ", "", text)
    return text.split("; the run has blown up")[0].split(". Last good")[0][:160]


def cfl_sweeps(out_root):
    rows, curves = [], {}
    for scene, (case, settings, end) in SCENES.items():
        cfls = COUPLED_CFLS if case == "elastic_plate" else CFLS
        curve = []
        for cfl in cfls:
            model = "_tl" if "solid.model=total_lagrangian" in settings else ""
            out = os.path.join(out_root, f"cfl_{case}{model}_{cfl}")
            reached, dt, error, wall = launch(case, out, settings + [f"run.cfl={cfl}"], end)
            stable = not error and reached >= end * (1 - 1e-9)
            curve.append((cfl, stable, dt))
            rows.append([scene, f"{cfl:g}", f"{dt:.3g}", ("runs" if stable else
                         f"stops at t = {reached:.3g} s: {reason(error)}") + spray_note(out),
                         f"{wall:.0f}"])
            print(rows[-1], flush=True)
            if not stable:
                break  # larger steps only fail sooner
        curves[scene] = curve
    return rows, curves


def fluid_step_row(out_root):
    """The coupled plate with the solid made to take the water's step whole
    (coupling.solid_step = fluid): it must stop with an error, not run on."""
    out = os.path.join(out_root, "coupled_solid_at_fluid_step")
    reached, dt, error, wall = launch("elastic_plate", out, ["coupling.solid_step=fluid"], 0.01)
    overstep = re.search(r"up to ([0-9.]+) times its stable step", error)
    outcome = "runs (not caught)" if not error else (
        f"stops at t = {reached:.3g} s, steps up to {float(overstep.group(1)):.1f} times the "
        f"solid's stable one: {reason(error)}" if overstep else
        f"stops at t = {reached:.3g} s: {reason(error)}")
    with open(os.path.join(cr.REPO, "cases", "elastic_plate.pbtxt")) as case:
        cfl = re.search(r"^\s*cfl:\s*([0-9.eE+-]+)", case.read(), re.M).group(1)  # the case's own
    return ["coupled, solid stepped whole at the fluid's step", cfl, f"{dt:.3g}", outcome,
            f"{wall:.0f}"]


def pressure_noise(snapshot, rho0=1000.0, g=9.81, scale_height=0.288):
    """RMS over water particles of P_i minus the mean P of its neighbours within
    2.6 dx, over rho0 g H: the particle-to-particle part of the pressure field."""
    with h5py.File(snapshot) as h5:
        water = h5["kind"][:] == 0
        x, p = h5["position"][:][water, :2], h5["pressure"][:][water]
    spacing = np.sqrt(np.median(np.sort(np.sum((x[:, None] - x[None]) ** 2, axis=2), axis=1)[:, 1]))
    d2 = np.sum((x[:, None] - x[None]) ** 2, axis=2)
    near = (d2 < (2.6 * spacing) ** 2) & (d2 > 0)
    mean = (near @ p) / np.maximum(near.sum(axis=1), 1)
    return float(np.sqrt(np.mean((p - mean) ** 2)) / (rho0 * g * scale_height))


PROBE_OUTPUT_INTERVAL = 0.0005  # s: timeseries rows, 20 to the probe's averaging window
PROBE_WINDOW = 0.01             # s: a fifth of the column's acoustic period 4H/c0


def probe_noise(out, rho0=1000.0, g=9.81, scale_height=0.288):
    """The dam break's floor sensor (probe0, under the column) over the whole
    run: RMS of its pressure about its running mean over PROBE_WINDOW, over
    rho0 g H (cosph_results.pressure_noise): what the sensor reads on top of
    the flow and the column's sound waves."""
    series = cr.read_csv(os.path.join(out, "timeseries.csv"))
    return cr.pressure_noise(series["t"], series["probe0_pressure"], PROBE_WINDOW,
                             rho0 * g * scale_height, interval=PROBE_OUTPUT_INTERVAL)[1]


def diffusion_rows(out_root):
    rows = []
    scenes = [("still tank (dam break tank filled, 8 mm), t = 1 s",
               ["fluid.water[0].max.x=0.576"], 1.0),
              ("dam break (8 mm), t = 0.3 s", [], 0.3)]
    for scene, settings, end in scenes:
        # delta-SPH (the earlier default water) with its diffusion off and on,
        # and the default water, whose Riemann solver damps in its stead.
        for label, name, water in (
                ("delta-SPH, diffusion off", "delta_-1", cr.water() + ["fluid.density_diffusion=-1"]),
                ("delta-SPH, diffusion on (0.1)", "delta_0.1",
                 cr.water() + ["fluid.density_diffusion=0.1"]),
                ("the default water (Riemann, Wendland C2)", "default_water", [])):
            out = os.path.join(out_root, f"{name}_{len(settings)}")
            reached, _, error, wall = launch(
                "dam_break", out, settings + water + [
                    f"run.output_interval={PROBE_OUTPUT_INTERVAL}"], end)
            last = sorted(glob.glob(os.path.join(out, "fluid_[0-9]*.h5")))[-1]
            noise = pressure_noise(last)
            rows.append([scene, label, f"{100 * noise:.2f} %", f"{100 * probe_noise(out):.2f} %",
                         ("runs" if not error else
                          f"stops at t = {reached:.3f} s: {reason(error)}") + spray_note(out)])
            print(rows[-1], flush=True)
    return rows


def automatic_choice(out):
    """The coupler's automatic choice in a run's log: ("multi-rate" or
    "synchronised", the added-mass ratio of a window), or None."""
    log_path = os.path.join(out, "launcher.log")
    text = open(log_path).read() if os.path.exists(log_path) else ""
    found = re.search(r"sub-stepping: (multi-rate|synchronised)\b.*"
                      r"added-mass ratio of a window ([0-9.eE+-]+)", text)
    return (found.group(1), float(found.group(2))) if found else None


def acceleration_choice(out):
    """What the coupler did with the wall's acceleration term in a run's log
    ("taken" or "left out"), or "?"."""
    log_path = os.path.join(out, "launcher.log")
    text = open(log_path).read() if os.path.exists(log_path) else ""
    found = re.search(r"acceleration in its pressure: (taken|left out)", text)
    return found.group(1) if found else "?"


def density_run(out_root, ratio, label, settings):
    """One run of the plate with rho_s = ratio rho_f to t = 0.1 s: its row,
    whether it ran, and the automatic choice its coupler made, if any."""
    # The multi-rate runs keep the folder names of earlier maps, for --reuse.
    suffix = "" if label == "multi-rate" else f"_{label}"
    out = os.path.join(out_root, f"density_{ratio}{suffix}")
    reached, dt, error, wall = launch("elastic_plate", out,
                                      settings + [f"solid.density={1000.0 * ratio}"], 0.1)
    choice = automatic_choice(out) if label == "automatic" else None
    if label == "automatic" and choice is None:
        raise RuntimeError(f"{out}: the coupler did not say what it chose")
    shown = (f"automatic: {choice[0]} (mu_W = {choice[1]:.3g}), the wall's acceleration "
             f"{acceleration_choice(out)}" if choice else label)
    row = [f"{ratio:g}", shown, ("runs to 0.1 s" if not error else
           f"stops at t = {reached:.3g} s: {reason(error)}") + spray_note(out), f"{wall:.0f}"]
    print(row, flush=True)
    return row, not error, choice


def automatic_verdict(runs, choices):
    """Sentences on the automatic rows: where the coupler chose what, and
    whether every choice held."""
    multi = [ratio for ratio in runs if choices[ratio][0] == "multi-rate"]
    synchronised = [ratio for ratio in runs if choices[ratio][0] == "synchronised"]
    failed = [ratio for ratio, ran in runs.items() if not ran]
    mu = lambda ratio: f"{choices[ratio][1]:.3g}"
    text = "With the case's default, the coupler's automatic choice, "
    parts = []
    if multi:
        parts.append(f"multi-rate down to {min(multi):g} (mu_W up to {mu(min(multi))})")
    if synchronised:
        parts.append(f"synchronised steps from {max(synchronised):g} down "
                     f"(mu_W from {mu(max(synchronised))})")
    text += " and ".join(parts) + " were chosen against the bound mu_W <= 1: "
    text += ("every ratio runs to 0.1 s." if not failed else
             "the choice fails at " + ", ".join(f"{r:g}" for r in failed) + ".")
    return text


def density_rows(out_root):
    """The table's rows, and sentences on where the sweep breaks: multi-rate
    down the ratios, the automatic choice at each, then the first ratio that
    stops again with synchronised steps, to tell the window's held forces
    from the coupling itself."""
    rows, runs, auto_runs, choices = [], {}, {}, {}
    for ratio in DENSITY_RATIOS:
        row, runs[ratio], _ = density_run(out_root, ratio, "multi-rate", MULTIRATE)
        rows.append(row)
    for ratio in DENSITY_RATIOS:
        row, auto_runs[ratio], choices[ratio] = density_run(out_root, ratio, "automatic", [])
        rows.append(row)
    auto_text = automatic_verdict(auto_runs, choices)
    failing = [ratio for ratio, ran in runs.items() if not ran]
    if not failing:
        return rows, (f"Every ratio down to {min(runs):g} runs to 0.1 s: no break was found. "
                      + auto_text)
    heaviest_failing = max(failing)
    running = [ratio for ratio, ran in runs.items() if ran and ratio > heaviest_failing]
    lighter = [ratio for ratio in runs if ratio < heaviest_failing]
    verdict = (f"Multi-rate, it breaks between {min(running):g}, the lightest plate that runs, "
               f"and {heaviest_failing:g}" if running else
               f"Multi-rate, even the heaviest plate, {heaviest_failing:g}, stops")
    if lighter:
        stop_too = all(not runs[ratio] for ratio in lighter)
        verdict += (": every lighter plate stops too" if stop_too else
                    ", though a lighter plate runs again")
    verdict += ". The solvers' own checks stop each run, and the error says where."
    if choices[heaviest_failing][0] == "synchronised":
        # The automatic row at that ratio is this run already.
        synchronised_ran, where = auto_runs[heaviest_failing], "(its automatic row)"
    else:
        row, synchronised_ran, _ = density_run(out_root, heaviest_failing, "synchronised",
                                               SYNCHRONISED)
        rows.append(row)
        where = "(its synchronised row)"
    verdict += (f" With synchronised steps the {heaviest_failing:g} plate {where} "
                + ("runs to 0.1 s: what breaks is holding the interface forces over the "
                   "multi-rate window, not the pair-by-pair coupling, so a light structure "
                   "wants synchronised steps." if synchronised_ran else
                   "stops too: the pair-by-pair coupling itself breaks there."))
    return rows, verdict + "\n\n" + auto_text


def draw(curves, path):
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    for k, (scene, curve) in enumerate(curves.items()):
        cfl = [c for c, _, _ in curve]
        ax.plot(cfl, [k] * len(cfl), "-", color=f"C{k}", lw=1)
        for c, stable, _ in curve:
            ax.plot(c, k, "o" if stable else "x", color=f"C{k}", ms=9, mew=2)
    ax.set_yticks(range(len(curves)), [scene.split(" (")[0] for scene in curves])
    ax.set(xlabel="run.cfl (o runs, x stops with an error)", xscale="log",
           title="Largest stable CFL number", ylim=(-0.5, len(curves) - 0.5))
    ax.set_xticks(CFLS, [f"{c:g}" for c in CFLS])
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def parse_run_folder(description, folder):
    """The --out and --reuse options of a script that launches runs through
    launch(): sets REUSE, makes the folder (default out/FOLDER), returns the
    parsed arguments."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", default=os.path.join(cr.REPO, "out", folder))
    parser.add_argument("--reuse", action="store_true",
                        help="read the runs already in --out; run only the missing ones")
    args = parser.parse_args()
    global REUSE
    REUSE = args.reuse
    os.makedirs(args.out, exist_ok=True)
    return args


def main():
    args = parse_run_folder(__doc__.splitlines()[0], "stability")

    cfl_rows, curves = cfl_sweeps(args.out)
    cfl_rows.append(fluid_step_row(args.out))
    draw(curves, os.path.join(cr.FIGURES, "stability_cfl.png"))
    density_table, density_verdict = density_rows(args.out)
    table = lambda header, rows: "\n".join(
        ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] +
        ["| " + " | ".join(str(c) for c in row) + " |" for row in rows])
    text = [
        "Produced by `scripts/stability_map.py`: short runs, every blow-up caught by the solvers' "
        "own checks and reported in their words.",
        "",
        "**Step size.** A sweep stops at its first failure. The force limit "
        "0.25 sqrt(h/|a|) of docs/physics.md (\"Time step\") still applies, so the step taken "
        "(median dt) can stop growing with the CFL number; in multi-rate runs the solid's sub-steps obey the same "
        "limits. The last row is the coupled plate with the solid made to take the step the "
        "water takes at CFL 0.25 whole (`coupling.solid_step: \"fluid\"`, a stability test, "
        "not a way to run): the solid's own step check stops the run within a few steps, and "
        "its error says that the steps were longer than its stable one.",
        "",
        table(["scene", "run.cfl", "median dt (s)", "outcome", "wall (s)"], cfl_rows),
        "",
        "**Density diffusion, and the default water.** Pressure noise: RMS over water particles of P minus the mean "
        "P of the neighbours within 2.6 dx, over rho0 g H (H = 0.288 m), at the run's end. At the "
        "floor sensor under the column (the case's probe0, sampled every "
        f"{1e3 * PROBE_OUTPUT_INTERVAL:g} ms over the whole run): RMS of its pressure minus its "
        f"running mean over {1e3 * PROBE_WINDOW:g} ms, over rho0 g H.",
        "",
        table(["scene", "water", "pressure noise (particles)", "pressure noise (floor sensor)",
               "outcome"], diffusion_rows(args.out)),
        "",
        "**Solid-to-fluid density ratio** of the coupled plate (to t = 0.1 s); the "
        "case has 1.1. Partitioned coupling of light structures is where added-mass "
        "trouble is known to start. Multi-rate rows hold at most 64 sub-steps a window; "
        "the automatic rows run the case's default (`coupling.max_substeps: 0`), and "
        "name what the coupler chose and the added-mass ratio of a window mu_W it "
        "chose by (docs/auto_substeps.md), and whether it took the wall's acceleration "
        "into the wall pressure (`coupling.wall_acceleration` unset: taken where "
        "rho_f h_f / (rho_s e) <= 1, docs/physics.md, \"Moving wall\").",
        "",
        table(["rho_s / rho_f", "coupling", "outcome", "wall (s)"], density_table),
        "",
        density_verdict,
    ]
    os.makedirs(cr.RESULTS, exist_ok=True)
    with open(os.path.join(cr.RESULTS, "stability_map.md"), "w") as f:
        f.write("\n".join(text) + "\n")
    print("\n".join(text))


if __name__ == "__main__":
    main()
