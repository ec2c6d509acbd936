"""Shared helpers of the validation scripts: reading cosph and reference CSVs,
running a case through the launcher, error norms, writing result tables.

Run the scripts with /usr/bin/python3 (Debian's numpy, matplotlib, h5py).
"""
import argparse
import glob
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REFERENCE = os.path.join(REPO, "validation", "reference")
FIGURES = os.path.join(REPO, "docs", "figures")
RESULTS = os.path.join(REPO, "docs", "results")


# The water the comparisons were first made against, the default before the
# Riemann solver's (docs/physics.md, "Choice of water"): every choice of the
# fluid block that water() spells out.
EARLIER_WATER = {"dissipation": "delta_sph", "kernel": "cubic_spline", "h_factor": 1.3,
                 "wall_friction": "dissipation", "shifting": "none"}


# What a table's label adds to the row of the default water, so that a reader
# of the table (update_docs.py) finds that row by it.
DEFAULT_WATER_MARK = " (the default water)"


def water(**choices):
    """The --set settings of a water with every choice of its fluid block
    spelled out (proto/case.proto, Fluid), so that a table's row names the
    same water whatever the case or the code take by default: EARLIER_WATER
    with CHOICES in place of its own."""
    unknown = set(choices) - set(EARLIER_WATER)
    if unknown:
        raise ValueError(f"water(): no choice {sorted(unknown)} (known: {sorted(EARLIER_WATER)})")
    return [f"fluid.{field}={value:g}" if isinstance(value, float) else f"fluid.{field}={value}"
            for field, value in {**EARLIER_WATER, **choices}.items()]


def setting(settings, field):
    """The value --set SETTINGS give FIELD (the last one given wins, as for
    the launcher), or None."""
    values = [s.split("=", 1)[1] for s in settings if s.split("=", 1)[0] == field]
    return values[-1] if values else None


def script_arguments(doc, out=None):
    """The scripts' common command line: the description (the first line of
    the script's docstring DOC), --reuse, and with OUT (a folder under out/)
    --out, where the runs go. Returns the parser, for the script's own
    arguments."""
    parser = argparse.ArgumentParser(description=doc.strip().splitlines()[0])
    if out is not None:
        parser.add_argument("--out", default=os.path.join(REPO, "out", out),
                            help=f"where the runs go (default out/{out})")
    parser.add_argument("--reuse", action="store_true",
                        help="read the runs made before instead of running them again")
    return parser


def build_bin():
    """The executables' folder: COSPH_BIN, or the release preset's build/bin."""
    return os.environ.get("COSPH_BIN", os.path.join(REPO, "build", "bin"))


def parallel_runtime(bin_dir):
    """The runtime of the solvers' loops in the build of `bin_dir` ("oneTBB" or
    "OpenMP"), from its CMakeCache.txt (COSPH_PARALLEL)."""
    with open(os.path.join(os.path.dirname(os.path.abspath(bin_dir)), "CMakeCache.txt")) as cache:
        value = re.search(r"^COSPH_PARALLEL:STRING=(\w+)", cache.read(), re.MULTILINE).group(1)
    return {"tbb": "oneTBB", "openmp": "OpenMP"}[value]


def read_csv(path):
    """Columns of a CSV with '#' comments and one header row, keyed by name.

    cosph headers carry units ('t [s]'); the key is the name before the unit.
    """
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#") and line.strip()]
    names = [name.split(" [")[0].strip() for name in lines[0].strip().split(",")]
    data = np.array([[float(v) for v in line.split(",")] for line in lines[1:]], ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def spray_removed(series):
    """Water particles that left a run as thinned spray (README "Spray"), as text."""
    return f"{int(series['spray_removed'][-1])}" if "spray_removed" in series else "-"


def reference(name):
    return read_csv(os.path.join(REFERENCE, name))


def run_case(case, out_dir, settings=(), timeout=3600):
    """Runs a case with the launcher; returns the wall time in seconds."""
    command = [os.path.join(REPO, "coupler", "cosph"), "run", case, "--out", out_dir, "--quiet",
               "--overwrite"]  # the script's own folder: its earlier run there goes
    # Gone before the launcher starts, too: a case it refuses leaves the folder
    # as it was, and the earlier run's results would be read as this one's.
    shutil.rmtree(out_dir, ignore_errors=True)
    os.makedirs(out_dir)
    for setting in settings:
        command += ["--set", setting]
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=timeout)
    elapsed = time.monotonic() - start
    with open(os.path.join(out_dir, "launcher.log"), "w") as log:
        log.write(result.stdout)
    if result.returncode != 0:
        sys.stderr.write(result.stdout)
        raise RuntimeError(f"{' '.join(command)} failed with exit code {result.returncode}")
    return elapsed


def run_solver(command):
    """Runs one solver alone (COMMAND: its program first, then its arguments),
    saying so; returns (its subprocess result, the wall time in seconds). Exit
    code 1 is a run that stopped (a blow-up, said on stderr); any other
    failure ends the script."""
    print("running:", " ".join(str(part) for part in command), flush=True)
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    if result.returncode not in (0, 1):
        sys.exit(f"{os.path.basename(str(command[0]))} failed unexpectedly "
                 f"(exit {result.returncode}):\n{result.stderr}")
    return result, wall


def shell_alone_means(binary, case, settings, out, end, average, columns):
    """Runs BINARY (cosph-solid-shell) alone on CASE with each FIELD=VALUE of
    SETTINGS to run.end_time END, into OUT; returns the mean of each of COLUMNS
    of its timeseries over the last AVERAGE seconds (a settled plate's swing
    averaged out)."""
    command = [str(binary), "--case", str(case), "--out", str(out), "--set",
               f"run.end_time={end!r}"]
    for s in settings:
        command += ["--set", s]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    series = read_csv(os.path.join(out, "timeseries.csv"))
    last = series["t"] >= end - average
    return [float(np.mean(series[column][last])) for column in columns]


def children_cpu_seconds():
    """CPU time (user + system, s) of this script's finished child processes
    so far: the difference across one run is that run's CPU time, which other
    jobs on a shared machine inflate less than its wall time."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_run(command, out_dir, reuse=False):
    """Runs COMMAND (a solver alone, its output into OUT_DIR) and returns its
    (wall s, CPU s), which it records in OUT_DIR; with REUSE and a record
    there, returns the recorded times without running (CPU None if an older
    run recorded none)."""
    wall_file = os.path.join(out_dir, "wall_time.txt")
    cpu_file = os.path.join(out_dir, "cpu_time.txt")
    if reuse and os.path.exists(wall_file):
        print("reusing:", out_dir, flush=True)
        with open(wall_file) as wall_text:
            wall = float(wall_text.read())
        if not os.path.exists(cpu_file):
            return wall, None
        with open(cpu_file) as cpu_text:
            return wall, float(cpu_text.read())
    print("running:", " ".join(str(part) for part in command), flush=True)
    start, cpu_start = time.monotonic(), children_cpu_seconds()
    subprocess.run([str(part) for part in command], check=True, stdout=subprocess.DEVNULL)
    wall, cpu = time.monotonic() - start, children_cpu_seconds() - cpu_start
    with open(wall_file, "w") as wall_text:
        wall_text.write(f"{wall}\n")
    with open(cpu_file, "w") as cpu_text:
        cpu_text.write(f"{cpu}\n")
    return wall, cpu


def run_or_reuse(case, out_dir, settings, reuse):
    """Runs a case into OUT_DIR, or with REUSE takes its earlier run there;
    returns (wall time in s or None, the first error a process reported or "").
    The wall time is the launcher's own clock, run now or reused: the same
    measure for every row of a table."""
    wall, failure = None, ""
    if not reuse:
        try:
            wall = run_case(case, out_dir, settings)
        except RuntimeError as error:
            failure = str(error)
    wall = logged_wall_time(out_dir) or wall
    log = os.path.join(out_dir, "launcher.log")
    if os.path.exists(log):
        with open(log) as lines:
            errors = [line for line in lines if line.startswith("[") and "error:" in line]
        # The process that failed first, before the others' reports that it
        # stopped ("fluid stopped: ..."), whichever the launcher printed first.
        errors.sort(key=lambda line: " stopped: " in line)
        failure = errors[0].strip() if errors else failure
    # The snapshot's path is of this machine, not of the README's reader.
    return wall, failure.split(". Last good snapshot:")[0]


DURATION = r"(?:(\d+) h )?(?:(\d+) min )?([\d.]+)(?: (s|min))?"


def seconds_of(groups):
    """Seconds of a DURATION the launcher wrote (its fmt_duration), from the
    regular expression's groups."""
    hours, minutes, last, unit = groups
    seconds = float(last) * (60 if unit == "min" else 1)
    return 3600 * int(hours or 0) + 60 * int(minutes or 0) + seconds


def launcher_summary(out_dir, pattern):
    """The match of `pattern` in the launcher's summary in OUT_DIR/launcher.log, or None."""
    path = os.path.join(out_dir, "launcher.log")
    if not os.path.exists(path):
        return None
    for line in open(path):
        match = re.match(pattern, line)
        if match:
            return match
    return None


def logged_wall_time(out_dir):
    """The wall time the launcher reported in OUT_DIR/launcher.log, in seconds,
    or None: what a rerun of a script that reuses the run should show."""
    match = launcher_summary(out_dir, rf"cosph: finished in {DURATION} wall")
    return seconds_of(match.groups()) if match else None


def logged_cpu_times(out_dir):
    """{process: CPU time in seconds} as the launcher reported them, or {}."""
    match = launcher_summary(out_dir, r"cosph: CPU time: (.*)$")
    if not match:
        return {}
    times = {}
    for part in match.group(1).split(", "):
        name, duration = part.split(" ", 1)
        times[name] = seconds_of(re.fullmatch(DURATION, duration).groups())
    return times


def rms_relative_error(t_model, y_model, t_ref, y_ref):
    """RMS and max of (model - ref) / ref at the reference times (model interpolated)."""
    relative = (np.interp(t_ref, t_model, y_model) - y_ref) / y_ref
    return float(np.sqrt(np.mean(relative ** 2))), float(np.max(np.abs(relative)))


def rms_error(t_model, y_model, t_ref, y_ref):
    """RMS of model - ref at the reference times, in the data's unit."""
    difference = np.interp(t_ref, t_model, y_model) - y_ref
    return float(np.sqrt(np.mean(difference ** 2)))


def antoci_rms(axis, t, displacement, until=None):
    """RMS (m) of the elastic plate's free-end displacement along AXIS ("x" or
    "y") against Antoci et al. 2007, over the experimental points up to UNTIL
    (by default the curve's last time: a run that stopped early is scored on
    what it reached). The one measure of every elastic plate table."""
    experiment = reference(f"antoci2007_plate_exp_{axis}.csv")
    within = experiment["t_s"] <= (t[-1] if until is None else until)
    return rms_error(t, displacement, experiment["t_s"][within], experiment[f"d{axis}_m"][within])


def antoci_tip_rms(series, until=None):
    """antoci_rms in x and y (m) of a cosph timeseries (its tip_dx, tip_dy)."""
    return [antoci_rms(axis, series["t"], series[f"tip_d{axis}"], until) for axis in "xy"]


def running_mean(series, width):
    """The centred running mean of SERIES over WIDTH samples, at the samples
    WIDTH // 2 from either end (the others have no full window); returns
    (the mean, the slice of SERIES it belongs to)."""
    mean = np.convolve(series, np.ones(width) / width, mode="valid")
    inner = slice(width // 2, width // 2 + len(mean))
    return mean, inner


def pressure_noise(t, p, window, scale, t_from=-np.inf, t_to=np.inf, interval=None):
    """A pressure signal's (mean, noise) over t_from <= t <= t_to, both over
    SCALE (rho0 g H): the noise is the RMS of P about its own running mean over
    WINDOW seconds, what a sensor reads on top of the load's own evolution
    (issue 38). The samples must be evenly spaced; (nan, nan) when fewer than
    one window of them lies in the interval. The window's width in samples is
    taken from INTERVAL, the run's output interval, when given, else from the
    samples' median spacing."""
    t, p = np.asarray(t), np.asarray(p)
    width = int(round(window / (interval or np.median(np.diff(t)))))
    if width < 1 or len(p) <= width:
        return float("nan"), float("nan")
    mean, inner = running_mean(p, width)
    taken = (t[inner] >= t_from) & (t[inner] <= t_to)
    if taken.sum() < width:
        return float("nan"), float("nan")
    level = np.mean(p[inner][taken]) / scale
    noise = np.sqrt(np.mean((p[inner][taken] - mean[taken]) ** 2)) / scale
    return float(level), float(noise)


def write_table(name, header, rows, preamble="", mode="w"):
    """docs/results/NAME.md: a markdown table the README includes (mode "a":
    a further table after those already there)."""
    os.makedirs(RESULTS, exist_ok=True)
    lines = [""] if mode == "a" else []
    lines += [preamble.strip(), ""] if preamble else []
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    path = os.path.join(RESULTS, name + ".md")
    with open(path, mode) as f:
        f.write("\n".join(lines) + "\n")
    return path


def write_points(name, points):
    """docs/results/NAME_points.json: runs as (series, label, wall_s, error,
    error_name), the input of scripts/speed_accuracy.py."""
    os.makedirs(RESULTS, exist_ok=True)
    path = os.path.join(RESULTS, name + "_points.json")
    with open(path, "w") as f:
        json.dump(points, f, indent=1)
    return path


def count_pieces(positions, link):
    """How many separate pieces particles at `positions` (N x 2) form, two
    particles closer than `link` belonging to the same piece."""
    x = np.asarray(positions)[:, :2]
    parent = list(range(len(x)))

    def root(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    for i in range(len(x)):
        near = np.nonzero(((x[i + 1:] - x[i]) ** 2).sum(axis=1) < link * link)[0] + i + 1
        for j in near:
            parent[root(j)] = root(i)
    return len({root(k) for k in range(len(x))})


def snapshot_at(out, name, time):
    """The snapshot of solver NAME in OUT nearest to TIME, an open h5py file."""
    files = sorted(glob.glob(os.path.join(out, f"{name}_[0-9]*.h5")))
    times = [h5py.File(f, "r").attrs["time"] for f in files]
    return h5py.File(files[int(np.argmin(np.abs(np.array(times) - time)))], "r")


def draw_water(ax, fluid, cmap, size, wall_size):
    """A fluid snapshot on AX: the water coloured by its pressure (0 to 1.4
    kPa), the walls grey; returns the water's scatter, for a colour bar."""
    x, water = fluid["position"][:], fluid["kind"][:] == 0
    drawn = ax.scatter(x[water, 0], x[water, 1], c=fluid["pressure"][:][water] / 1e3, s=size,
                       cmap=cmap, vmin=0, vmax=1.4)
    ax.scatter(x[~water, 0], x[~water, 1], c="0.6", s=wall_size)
    return drawn
