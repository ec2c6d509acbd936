"""cosph-bench's fluid alone on an OpenMP build and on a oneTBB build (the
default's and --other-build's, -DCOSPH_PARALLEL), side by side and alternating:
one thread and two on a quiet machine, and two beside one competing CPU-bound
process (busy_machine.busy_loop). Part of scripts/benchmark.py --busy
--other-build DIR; writes docs/results/parallel_runtimes.md."""
import os
import statistics
import subprocess

import busy_machine
import cosph_results as cr

# The busy mode's dam break, 1.5 mm (22 318 particles), in process.
SPACING = 0.0015
STEPS = 200

# (machine, threads); the first is the reference of the ratios.
RUNS = [("quiet", 1), ("quiet", 2), ("busy", 2), ("busy", 1)]


def ms_per_step(bin_dir, threads):
    """The fluid's time per step (ms) on `threads` threads, by cosph-bench."""
    output = subprocess.run(
        [os.path.join(bin_dir, "cosph-bench"), "--fluid", "--spacing", str(SPACING), "--threads",
         str(threads), "--steps", str(STEPS)], check=True, text=True,
        stdout=subprocess.PIPE).stdout
    return float(output.splitlines()[-1].split()[3])


def measure(repeat, builds):
    """{(runtime, machine, threads): [ms per step per round]}, and the load
    averages seen; each round runs every build and row once, in turn."""
    times, loads = {}, []
    for _ in range(repeat):
        for machine, threads in RUNS:
            for runtime, bin_dir in builds:
                loads.append(busy_machine.load())
                with busy_machine.busy_loop(machine == "busy"):
                    ms = ms_per_step(bin_dir, threads)
                times.setdefault((runtime, machine, threads), []).append(ms)
                print(f"cosph-bench: {runtime}, {machine}, {threads} thread(s): {ms:.3f} ms a "
                      f"step (load {loads[-1]:.2f})", flush=True)
    return times, loads


# Stalls: quiet, two threads, this many more runs of each build in turn. This
# virtual machine has spells in which one of two threads loses its core to the
# host for a while; a run then takes up to twice its time.
STALL_RUNS = 20
STALL = 1.5  # a run this many times its build's median counts as stalled


def stalls(builds):
    """{runtime: [ms per step of each quiet two-thread run]}, the builds in turn."""
    times = {}
    for _ in range(STALL_RUNS):
        for runtime, bin_dir in builds:
            times.setdefault(runtime, []).append(ms_per_step(bin_dir, 2))
    for runtime, ms in times.items():
        print(f"cosph-bench: {runtime}, quiet, 2 threads, {STALL_RUNS} runs: "
              f"{stalled(ms)} stalled", flush=True)
    return times


def stalled(ms):
    """How many runs took more than STALL times the median."""
    return sum(t > STALL * statistics.median(ms) for t in ms)


def run(repeat, other_build):
    bins = [cr.build_bin(), os.path.join(os.path.abspath(other_build), "bin")]
    builds = sorted((cr.parallel_runtime(bin_dir), bin_dir) for bin_dir in bins)  # OpenMP first
    if [runtime for runtime, _ in builds] != ["OpenMP", "oneTBB"]:
        raise SystemExit(f"--other-build {other_build}: the two builds have the same runtime")
    times, loads = measure(repeat, builds)
    return write(times, loads, repeat, stalls(builds))


def write(times, loads, repeat, stall_times):
    reference = times[("OpenMP",) + RUNS[0]]

    def against(key, base=reference):
        return [r / t for r, t in zip(base, times[key])]

    rows = []
    for key, ms in times.items():
        r = against(key)
        rows.append([key[0], key[1], str(key[2]), f"{statistics.median(ms):.3f}",
                     f"{min(ms):.3f} to {max(ms):.3f}", f"{statistics.median(r):.2f}",
                     f"{min(r):.2f} to {max(r):.2f}"])

    def paired(key, base):
        """base's time over key's, round by round: the median, and its range."""
        r = against(key, times[base])
        return f"{statistics.median(r):.2f} (from {min(r):.2f} to {max(r):.2f})"

    def busy_two(runtime):
        return statistics.median(against((runtime, "busy", 2)))

    preamble = (
        f"`scripts/benchmark.py --busy --other-build DIR` runs `cosph-bench --fluid --spacing "
        f"{SPACING} --steps {STEPS}` (the dam break in process, 22 318 particles, time per step "
        f"after a warm-up) on an OpenMP build and a oneTBB one (-DCOSPH_PARALLEL) "
        f"({repeat} rounds, each running every row on both builds in turn, {os.cpu_count()} "
        f"cores; the load average before each run was {min(loads):.1f} to {max(loads):.1f}). "
        "\"Busy\": one competing `sh -c 'while :; do :; done'`. The ratio is OpenMP's quiet "
        "one-thread time per step over the row's, within each round; above 1 is faster. "
        "Measured, round by round: quiet, two threads against the same build's one, OpenMP "
        f"{paired(('OpenMP', 'quiet', 2), ('OpenMP', 'quiet', 1))}, oneTBB "
        f"{paired(('oneTBB', 'quiet', 2), ('oneTBB', 'quiet', 1))} (target 1.8), and oneTBB's "
        f"two threads against OpenMP's two {paired(('oneTBB', 'quiet', 2), ('OpenMP', 'quiet', 2))}"
        f", its one thread against OpenMP's one "
        f"{paired(('oneTBB', 'quiet', 1), ('OpenMP', 'quiet', 1))}; busy, oneTBB's "
        "two threads against OpenMP's one-thread fallback, run next to it, "
        f"{paired(('oneTBB', 'busy', 2), ('OpenMP', 'busy', 1))}; busy, two threads, of "
        f"OpenMP's quiet one thread, OpenMP {busy_two('OpenMP'):.2f}, oneTBB "
        f"{busy_two('oneTBB'):.2f}, and OpenMP's fallback "
        f"{statistics.median(against(('OpenMP', 'busy', 1))):.2f} (target 0.8). Stalls: "
        f"{STALL_RUNS} more quiet two-thread runs of each build, in turn; a run over {STALL} "
        "times its build's median counts as stalled: "
        + ", ".join(f"{runtime} {stalled(ms)} (median {statistics.median(ms):.3f} ms, slowest "
                    f"{max(ms):.3f} ms)" for runtime, ms in stall_times.items())
        + ". Such stalls come in spells on this virtual machine, when a thread loses its core "
        "to the host for a while: under OpenMP a loop then waits at its barrier for that "
        "thread's share; under oneTBB the other thread takes its chunks.")
    return cr.write_table("parallel_runtimes", ["runtime", "machine", "threads",
                                                "time per step (ms, median)", "range (ms)",
                                                "OpenMP quiet one thread / this", "range"],
                          rows, preamble=preamble)
