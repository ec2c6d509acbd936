#!/usr/bin/python3
"""Reruns every script that writes a table of docs/results/ (and the figures
it draws with it), in an order where a script that reads another's runs
comes after it, then scripts/update_docs.py: what a change of a default
asks, since every table says what the defaults give.

Each step is run from scratch (its runs are made again, not reused), and its
wall time is printed as it ends and kept in
docs/results/regenerate_results_times.json, committed with the tables, so
that the next regeneration, on any clone, can say how long it will take
(--list).

  /usr/bin/python3 scripts/regenerate_results.py             every step
  /usr/bin/python3 scripts/regenerate_results.py --list      the steps and their last times
  /usr/bin/python3 scripts/regenerate_results.py --from NAME from that step on
  /usr/bin/python3 scripts/regenerate_results.py --only NAME [NAME ...]
  /usr/bin/python3 scripts/regenerate_results.py --accuracy  without the timing steps
  ... --other-build DIR   the busy-machine step also on DIR, a build with the
                          other runtime of the solvers' loops, which rewrites
                          docs/results/parallel_runtimes.md (without it, that
                          table stays as it is)

The timing steps (the benchmarks) measure speed and want the machine to
themselves; the others report wall times too, so run nothing else beside
them. scripts/peer/compare_elastic_gate.py is not a step: it needs the
user's own build of the peer (its --peer-command).
"""
import argparse
import json
import os
import subprocess
import sys
import time

import cosph_results as cr

# (name, script and its arguments, kind): "accuracy" steps validate,
# "timing" steps benchmark. Order: pressure_noise before the scripts that
# import its runs (sensor_support, far_wall_profile); the validation tables
# before solid_comparison and speed_accuracy, which read them.
STEPS = [
    ("dam_break", ["validate_dam_break.py"], "accuracy"),
    ("pressure_noise", ["pressure_noise.py", "--repeats", "9"], "accuracy"),
    ("sound_speed_noise", ["sound_speed_noise.py"], "accuracy"),
    ("smoothing_length_noise", ["smoothing_length_noise.py"], "accuracy"),
    ("shifting_density", ["shifting_density.py"], "accuracy"),
    ("sensor_convergence", ["pressure_noise.py", "--convergence"], "accuracy"),
    ("sensor_support", ["sensor_support.py"], "accuracy"),
    ("far_wall_profile", ["far_wall_profile.py"], "accuracy"),
    ("wall_pressure", ["validate_wall_pressure.py"], "accuracy"),
    ("oscillating_plate", ["validate_oscillating_plate.py"], "accuracy"),
    ("oscillating_plate_tl", ["validate_oscillating_plate.py", "--model", "total_lagrangian"],
     "accuracy"),
    ("tensile_instability", ["tensile_instability.py"], "accuracy"),
    ("shell", ["validate_shell.py"], "accuracy"),
    ("shell_elastica", ["validate_shell_elastica.py"], "accuracy"),
    ("shell_curved", ["validate_shell_curved.py"], "accuracy"),
    ("continuum_plate_in_vacuum", ["continuum_plate_in_vacuum.py"], "accuracy"),
    ("elastic_plate", ["validate_elastic_plate.py"], "accuracy"),
    ("plate_force_noise", ["plate_force_noise.py"], "accuracy"),
    ("modulus_sweep", ["modulus_sweep.py"], "accuracy"),
    ("interface_acceleration", ["interface_acceleration.py"], "accuracy"),
    ("shell_coupled", ["validate_shell_coupled.py"], "accuracy"),
    ("shell_windows", ["shell_window_vibration.py"], "accuracy"),
    ("shell_window_waters", ["shell_window_waters.py"], "accuracy"),
    ("shell_clamp_contact_line", ["shell_clamp_contact_line.py"], "accuracy"),
    ("hydrostatic_plate", ["validate_hydrostatic_plate.py"], "accuracy"),
    ("plate_fracture", ["validate_plate_fracture.py"], "accuracy"),
    ("wave_flume", ["validate_wave_flume.py", "--previous"], "accuracy"),
    ("wave_flume_points", ["validate_wave_flume.py", "--points"], "accuracy"),
    ("stability_map", ["stability_map.py"], "accuracy"),
    ("solid_comparison", ["solid_comparison.py"], "accuracy"),
    ("benchmark", ["benchmark.py"], "timing"),
    ("busy_machine", ["benchmark.py", "--busy", "--candidates"], "timing"),
    ("busy_machine_long", ["benchmark.py", "--busy-long"], "timing"),
    ("speed_accuracy", ["speed_accuracy.py"], "accuracy"),
]
TIMES = os.path.join(cr.RESULTS, "regenerate_results_times.json")


def step_names():
    return [name for name, _, _ in STEPS]


def chosen_steps(args):
    """The steps ARGS asks for, in STEPS' order; SystemExit naming an unknown one."""
    for name in args.only + ([args.start] if args.start else []):
        if name not in step_names():
            raise SystemExit(f"regenerate_results: no step '{name}' (steps: "
                             + ", ".join(step_names()) + ")")
    steps = STEPS
    if args.start:
        steps = steps[step_names().index(args.start):]
    if args.only:
        steps = [step for step in steps if step[0] in args.only]
    if args.accuracy:
        steps = [step for step in steps if step[2] == "accuracy"]
    return steps


def duration(seconds):
    return f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.1f} min"


def last_times():
    if not os.path.exists(TIMES):
        return {}
    with open(TIMES) as file:
        return json.load(file)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", action="store_true", help="print the steps and stop")
    parser.add_argument("--from", dest="start", help="start at this step")
    parser.add_argument("--only", nargs="+", default=[], help="run only these steps")
    parser.add_argument("--accuracy", action="store_true", help="leave out the timing steps")
    parser.add_argument("--other-build", metavar="DIR",
                        help="the busy-machine step's build with the other parallel runtime")
    args = parser.parse_args()
    steps = chosen_steps(args)
    if args.other_build:
        steps = [(name, command + (["--other-build", args.other_build]
                                   if name == "busy_machine" else []), kind)
                 for name, command, kind in steps]
    times = last_times()
    if args.list:
        for name, command, kind in steps:
            last = f"{duration(times[name])} last time" if name in times else "not timed yet"
            print(f"{name:28s} {kind:9s} {' '.join(command):55s} {last}")
        known = [times[name] for name, _, _ in steps if name in times]
        print(f"{len(steps)} steps; {duration(sum(known))} for the {len(known)} timed")
        return
    for name, command, _ in steps:
        start = time.monotonic()
        print(f"regenerate_results: {name}: {' '.join(command)}", flush=True)
        result = subprocess.run([sys.executable, os.path.join(cr.REPO, "scripts", command[0])]
                                + command[1:], cwd=cr.REPO)
        if result.returncode != 0:
            raise SystemExit(f"regenerate_results: step {name} failed (exit "
                             f"{result.returncode}); rerun with --from {name}")
        times[name] = round(time.monotonic() - start, 1)
        with open(TIMES, "w") as file:
            json.dump(times, file, indent=1)
        print(f"regenerate_results: {name}: {duration(times[name])}", flush=True)
    subprocess.run([sys.executable, os.path.join(cr.REPO, "scripts", "update_docs.py")],
                   cwd=cr.REPO, check=True)


if __name__ == "__main__":
    main()
