"""The busy-machine mode of scripts/benchmark.py (--busy): whole runs through
the launcher on a quiet machine and with one competing CPU-bound process
(`sh -c 'while :; do :; done'`, started and stopped here), side by side and
alternating, and their ratio against the quiet one-thread run. Writes
docs/results/busy_machine.md. With a build of the other runtime of the solvers'
loops (--other-build: -DCOSPH_PARALLEL=openmp or tbb), the dam break's rows on it
too, and cosph-bench on both builds (docs/results/parallel_runtimes.md)."""
import contextlib
import os
import resource
import statistics
import subprocess
import tempfile
import time

import cosph_results as cr
import parallel_runtimes

# The scenes: the fluid alone at about 20 000 particles, and the
# coupled elastic plate multi-rate (its main case), both short.
SCENES = [
    ("dam break, fluid alone, 1.5 mm (22 318 particles)", "dam_break",
     ["fluid.spacing=0.0015"]),
    ("elastic plate, coupled, multi-rate", "elastic_plate", ["coupling.max_substeps=32"]),
]

# (label, busy, settings, extra launcher options, environment): the reference
# and the default first; the candidates (--candidates) are what the default
# was chosen against.
REFERENCE = ("quiet, one thread", False, ["run.threads=1"], [], {})
VARIANTS = [
    ("quiet, default", False, [], [], {}),
    ("busy, default", True, [], [], {}),
]
CANDIDATES = [
    ("busy, two threads always", True, ["run.threads=2"], [], {}),
    ("busy, one thread", True, ["run.threads=1"], [], {}),
    ("busy, default, not pinned (--no-pin)", True, [], ["--no-pin"], {}),
    ("quiet, default, not pinned (--no-pin)", False, [], ["--no-pin"], {}),
]

# With --other-build: the rows that compare the two runtimes on the dam break,
# two threads asked for rather than left to the default, which a machine
# loaded by others turns into one. The other build's rows run its
# executables (COSPH_BIN), set in other_rows, and are labelled with its runtime.
DEFAULT_TWO_THREADS = [
    ("quiet, two threads", False, ["run.threads=2"], [], {}),
    CANDIDATES[0],  # busy, two threads always
]
OTHER_ROWS = [
    ("quiet, one thread", False, ["run.threads=1"], [], {}),
    ("quiet, two threads", False, ["run.threads=2"], [], {}),
    ("busy, default", True, [], [], {}),
    ("busy, two threads always", True, ["run.threads=2"], [], {}),
]


def other_prefix(other_build):
    """The label before the other build's rows: its runtime's name."""
    return cr.parallel_runtime(os.path.join(os.path.abspath(other_build), "bin")) + " build: "


def other_rows(other_build):
    """The rows that compare the runtimes, the other's on other_build's executables."""
    env = {"COSPH_BIN": os.path.join(os.path.abspath(other_build), "bin")}
    prefix = other_prefix(other_build)
    return DEFAULT_TWO_THREADS + [(prefix + label, busy, extra, options, {**environment, **env})
                                  for label, busy, extra, options, environment in OTHER_ROWS]


@contextlib.contextmanager
def busy_loop(wanted):
    """One competing CPU-bound process while the block runs (if wanted); it is
    stopped however the block ends, Ctrl-C and errors included."""
    if not wanted:
        yield
        return
    loop = subprocess.Popen(["sh", "-c", "while :; do :; done"])
    try:
        yield
    finally:
        loop.kill()
        loop.wait()


def children_cpu_s():
    """CPU seconds, user and system, of every finished child and its children."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_run(case, settings, options, env):
    """Wall time and CPU time (all processes of the run) of one run through the
    launcher, in seconds."""
    with tempfile.TemporaryDirectory(prefix="cosph-busy-") as out:
        command = [os.path.join(cr.REPO, "coupler", "cosph"), "run", case, "--out", out,
                   "--quiet", *options]
        for setting in settings:
            command += ["--set", setting]
        cpu_before, started = children_cpu_s(), time.monotonic()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       env={**os.environ, **env})
        return time.monotonic() - started, children_cpu_s() - cpu_before


def load():
    """The machine's load average over the last minute."""
    with open("/proc/loadavg") as loadavg:
        return float(loadavg.read().split()[0])


def measure(repeat, end_time, candidates, other_build=None, scenes=SCENES, variants=None):
    """{(scene, label): [wall seconds per run]}, {(scene, label): [CPU seconds
    per run]}, and the load averages seen."""
    variants = variants or [REFERENCE] + VARIANTS + (CANDIDATES if candidates else [])
    times, cpu, loads = {}, {}, []
    for scene, case, settings in scenes:
        # The plate's candidates that only pin or unpin matter for; the dam
        # break runs one process, which the launcher never pins.
        chosen = [v for v in variants if case == "elastic_plate" or not v[3]]
        if other_build and case == "dam_break":
            chosen += [v for v in other_rows(other_build) if v[0] not in [c[0] for c in chosen]]
        for _ in range(repeat):
            for label, busy, extra, options, env in chosen:
                run_settings = settings + [f"run.end_time={end_time}"] + extra
                loads.append(load())
                with busy_loop(busy):
                    seconds, cpu_s = timed_run(case, run_settings, options, env)
                times.setdefault((scene, label), []).append(seconds)
                cpu.setdefault((scene, label), []).append(cpu_s)
                print(f"{scene}: {label}: {seconds:.2f} s (load {loads[-1]:.2f})", flush=True)
    return times, cpu, loads


def fair_share_bound(cores_used):
    """The most a run that keeps `cores_used` of two cores busy on a quiet
    machine can reach beside one CPU-bound process, as a fraction of its quiet
    speed, when the scheduler shares the cores fairly among runnable threads.
    While the run has one runnable thread, it and the competing process each
    hold a core: full speed. While it has two, three threads share two cores
    and the run gets 4/3 of the 2 it used: its work there takes 3/2 as long.
    With a fraction u - 1 of the quiet run's time spent with two threads
    runnable (u = CPU time over wall time), the busy run takes
    (2 - u) + 3/2 (u - 1) = (1 + u) / 2 of the quiet time."""
    u = min(max(cores_used, 1.0), 2.0)
    return 2.0 / (1.0 + u)


def ratios(times, scene, label):
    """Quiet one-thread time over this variant's, run by run (the runs of one
    repeat are seconds apart): above 1, faster than one thread on a quiet
    machine."""
    return [t1 / t for t1, t in zip(times[(scene, REFERENCE[0])], times[(scene, label)])]


def runtimes_compared(times, other_build):
    """What the other runtime's rows say against the default's, or nothing without them."""
    scene = SCENES[0][0]
    if not other_build:
        return ""
    prefix = other_prefix(other_build)
    other, default = prefix.split(" build: ")[0], cr.parallel_runtime(cr.build_bin())

    def ratio(label, reference=REFERENCE[0]):
        return statistics.median(t1 / t for t1, t in zip(times[(scene, reference)],
                                                         times[(scene, label)]))

    return (
        f" {other} (the rows \"{prefix}...\", a build with the other runtime of the "
        f"solvers' loops), on the dam break: busy with two threads always "
        f"{ratio(prefix + 'busy, two threads always'):.2f} of {default}'s quiet one-thread "
        f"speed ({default}'s two threads always {ratio(CANDIDATES[0][0]):.2f}, its default on a "
        f"busy machine {ratio('busy, default'):.2f}); quiet, two threads "
        f"{ratio(prefix + 'quiet, two threads', prefix + 'quiet, one thread'):.2f} times its own "
        f"one thread ({default} {ratio('quiet, two threads'):.2f}); its one thread "
        f"{ratio(prefix + 'quiet, one thread'):.2f} of {default}'s.")


def write(times, cpu, loads, repeat, end_time, other_build=None):
    rows = []
    for scene, _, _ in SCENES:
        for (row_scene, label), seconds in times.items():
            if row_scene != scene:
                continue
            r = ratios(times, scene, label)
            rows.append([scene, label, f"{statistics.median(seconds):.2f}",
                         f"{min(seconds):.2f} to {max(seconds):.2f}",
                         f"{statistics.median(r):.2f}", f"{min(r):.2f} to {max(r):.2f}"])
    busy = {scene: statistics.median(ratios(times, scene, "busy, default"))
            for scene, _, _ in SCENES}
    quiet = {scene: statistics.median(ratios(times, scene, "quiet, default"))
             for scene, _, _ in SCENES}
    used = {scene: statistics.median(c / t for c, t in zip(cpu[(scene, REFERENCE[0])],
                                                          times[(scene, REFERENCE[0])]))
            for scene, _, _ in SCENES}
    preamble = (
        f"`scripts/benchmark.py --busy` ({repeat} rounds, each running every row once in turn, "
        f"simulated time {end_time} s, {os.cpu_count()} cores; the load average before each run "
        f"was {min(loads):.1f} to {max(loads):.1f}, the competing loop included while it ran, "
        "so other work on the machine shows there). \"Busy\": one competing CPU-bound process, "
        "`sh -c 'while :; do :; done'`, started before the run and stopped after it. The ratio "
        "is the quiet one-thread run's wall time over the row's, taken within each round; "
        "above 1 is faster. Targets (issue 35): busy at its default thread count at least 0.8 "
        "of quiet one-thread speed; quiet, two threads at least 1.8 times one (the fluid's "
        "particle-steps on the benchmark's scenes are in the table above). Measured: "
        + "; ".join(f"{scene}, busy {busy[scene]:.2f}, quiet default {quiet[scene]:.2f}"
                    for scene in busy) + "." + runtimes_compared(times, other_build) + "\n\n"
        "What a busy machine leaves. Beside one CPU-bound process on two cores, a scheduler "
        "that shares the cores fairly among runnable threads gives a run that keeps u cores "
        "busy on a quiet machine at most 2 / (1 + u) of its quiet speed: while it has one "
        "runnable thread, it and the other process each hold a core; while it has two, three "
        "threads share two cores (`fair_share_bound` in scripts/busy_machine.py gives the "
        "steps). The quiet one-thread runs used, in CPU time over wall time, "
        + "; ".join(f"{scene} u = {used[scene]:.2f}, so at most {fair_share_bound(used[scene]):.2f}"
                    for scene in busy)
        + ". A coupled run keeps both its solvers busy at once, so the 0.8 target lies above "
        "what fair sharing leaves it once u passes 1.5; only a run that holds the scheduler's "
        "placement (pinning, below) can go beyond it.\n\n"
        "Why the default is what it is. The solvers' loops run on "
        f"{cr.parallel_runtime(cr.build_bin())} here. Under OpenMP every loop ends at a barrier "
        "that waits for each thread's share: with another process on one of two cores, the "
        "thread there runs only in the scheduler's time slices, every loop waits for one, and "
        "two threads always ran many times slower than one (OpenMP's rows \"busy, two threads "
        "always\"). Under oneTBB a loop is cut into chunks that idle threads take from the "
        "others, so a thread that lost its core holds a loop up by at most the chunk it is "
        "working on. With either, a solver takes no more threads than the cores other "
        "processes leave free (from the machine's busy time in /proc/stat less its own, a core "
        "counting as free while others use less than a quarter of it; as it starts, from the "
        "least of a few readings of the threads runnable then), and looks again every second; "
        "results are the same bits on any thread count and on either runtime. On a busy "
        "machine a solver then runs one thread (the row \"busy, one thread\" is what it "
        "reaches); docs/performance.md (\"OpenMP or oneTBB\") has why oneTBB is the default. In a "
        "multi-rate coupled run the launcher pins each solver to cores of its own, on a busy "
        "machine too: left to the scheduler (the row \"not pinned\"), both solvers can share "
        "one core while the outside job holds the other; pinned, the job shares a core with "
        "one solver only.")
    return cr.write_table("busy_machine", ["scene", "run", "wall time (s, median)",
                                           "range (s)", "quiet one thread / this",
                                           "range"], rows, preamble=preamble)


# The coupled plate over a longer run: a 0.02 s run lasts about 1.5 s, of
# which starting three processes and their first look at the free cores is
# a part; 0.1 s is some 2 000 coupling windows, what a user's run is made of.
LONG_END_TIME = 0.1  # s
LONG_SCENES = [("elastic plate, coupled, multi-rate, 0.1 s", "elastic_plate",
                ["coupling.max_substeps=32"])]
LONG_VARIANTS = [REFERENCE, VARIANTS[0], VARIANTS[1], CANDIDATES[2]]


def run_long(repeat):
    """The coupled plate quiet and busy over LONG_END_TIME, alternating;
    writes docs/results/busy_machine_long.md."""
    times, cpu, loads = measure(repeat, LONG_END_TIME, False, scenes=LONG_SCENES,
                                variants=LONG_VARIANTS)
    scene = LONG_SCENES[0][0]
    rows = []
    for label, *_ in LONG_VARIANTS:
        seconds, r = times[(scene, label)], ratios(times, scene, label)
        rows.append([label, f"{statistics.median(seconds):.2f}",
                     f"{min(seconds):.2f} to {max(seconds):.2f}", f"{statistics.median(r):.2f}",
                     f"{min(r):.2f} to {max(r):.2f}"])
    used = statistics.median(c / t for c, t in zip(cpu[(scene, REFERENCE[0])],
                                                  times[(scene, REFERENCE[0])]))
    busy = statistics.median(ratios(times, scene, "busy, default"))
    preamble = (
        f"`scripts/benchmark.py --busy-long` ({repeat} rounds, each running every row once in "
        f"turn; the load average before each run was {min(loads):.1f} to {max(loads):.1f}). The "
        f"elastic plate, coupled, multi-rate, over {LONG_END_TIME} s of simulated time rather "
        "than the table above's 0.02 s, whose runs last about a second and a half, of which "
        "starting three processes is a part. Rows and ratios as above. Measured: busy at the "
        f"default thread count {busy:.2f} of quiet one-thread speed (target 0.8); the quiet "
        f"one-thread run used u = {used:.2f} cores, for which fair sharing would leave at most "
        f"{fair_share_bound(used):.2f} (the table above's preamble); not pinned "
        f"{statistics.median(ratios(times, scene, LONG_VARIANTS[3][0])):.2f}.")
    return cr.write_table("busy_machine_long", ["run", "wall time (s, median)", "range (s)",
                                                "quiet one thread / this", "range"], rows,
                          preamble=preamble)


def run(repeat, end_time, candidates, other_build=None):
    times, cpu, loads = measure(repeat, end_time, candidates, other_build)
    print(write(times, cpu, loads, repeat, end_time, other_build))
    if other_build:
        print(parallel_runtimes.run(repeat, other_build))
