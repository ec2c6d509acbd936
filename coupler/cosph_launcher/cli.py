"""The command line: `cosph run CASE --out DIR`."""

import argparse
import os
import shlex
import sys
import time
from pathlib import Path

from .console import Console, emit, fmt_duration, fmt_size
from .errors import EXIT_BAD_INPUT, EXIT_FAILURE, EXIT_INTERRUPTED, EXIT_OK, Exit, Interrupted, UsageError
from .locate import (BUILD_HINT, available_cases, bin_dir, check_sets, find_exe, repo_dir,
                     resolve_case)
from .output_dir import clear_earlier_output, lock_out_dir, prepare_out_dir
from .plan import check_endpoint, child_commands, core_placement, run_plan
from .resume import (check_resume_sets, discard_later_checkpoints, last_complete_checkpoint,
                     recorded_run)
from .security import check_bind, default_endpoint, make_private_dir, with_key_args
from .supervise import Child, Run, SignalState

def print_summary(out, wall_s, children):
    sim = [c.progress.t for c in children if c.progress.t is not None]
    line = f"cosph: finished in {fmt_duration(wall_s)} wall time"
    if sim:
        line += f", simulated {min(sim):.4g} s"
    files = [out / "timeseries.csv"] if (out / "timeseries.csv").is_file() else []
    files += sorted(p for p in out.glob("*.xdmf") if p.is_file())
    lines = [line]
    cpu = [f"{c.tag} {fmt_duration(c.cpu_s)}" for c in children if c.cpu_s is not None]
    if cpu:
        lines.append("cosph: CPU time: " + ", ".join(cpu))
    lines.append(f"cosph: output in {out}:")
    lines += [f"  {p.name}  ({fmt_size(p.stat().st_size)})" for p in files]
    if not files:
        lines.append("  (no timeseries.csv or *.xdmf files were written)")
    emit(sys.stdout, "\n".join(lines) + "\n")


# --------------------------------------------------------------------------
# Command line

def build_parser(repo):
    parser = argparse.ArgumentParser(
        prog="cosph",
        description="Run SPH fluid-structure-interaction cases: starts the "
                    "fluid solver, the solid solver and the coupler as the case needs.",
        epilog="Run 'cosph run --help' for the options of a run, "
               "'cosph plot --help' for the pictures of one.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    cases = available_cases(repo / "cases")
    run = sub.add_parser(
        "run", help="run a case",
        description="Run a case and write its results to an output folder.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="available cases: " + (", ".join(cases) if cases else "(none found)") +
               f"\n\nExecutables are taken from $COSPH_BIN, else {repo / 'build' / 'bin'}."
               f"\nBuild them with:  {BUILD_HINT}"
               "\n\nexit codes: 0 success, 2 bad input, 130 interrupted, "
               "otherwise the failed process's code")
    run.add_argument("case", metavar="CASE",
                     help="case file, or the name of a case in cases/ (e.g. dam_break)")
    run.add_argument("--out", required=True, metavar="DIR",
                     help="output folder (created if needed); one an earlier run wrote "
                          "to is refused unless --overwrite is given")
    run.add_argument("--overwrite", action="store_true",
                     help="remove the files an earlier run wrote to --out (its snapshots, "
                          "CSVs, checkpoints, plots; no other file) before this run starts")
    run.add_argument("--set", action="append", default=[], metavar="FIELD=VALUE",
                     help="override a case field; may be repeated")
    run.add_argument("--endpoint", metavar="E",
                     help="coupling endpoint for multi-process runs (default "
                          "ipc://DIR/private/coupler.sock); tcp://HOST:PORT runs with fresh "
                          "CURVE keys in DIR/private (docs/coupling.md, \"Two hosts\")")
    run.add_argument("--bind-any", action="store_true",
                     help="let the coupler listen on a wildcard address such as "
                          "tcp://0.0.0.0:PORT (every network interface)")
    run.add_argument("--quiet", action="store_true", help="show no progress")
    run.add_argument("--no-pin", action="store_true",
                     help="in a multi-rate run, let the scheduler place the solvers "
                          "instead of giving each cores of its own")
    add_plot_parser(sub)
    resume = sub.add_parser(
        "resume", help="continue a stopped run from its last checkpoint",
        description="Continue a run that was stopped, killed or crashed from the last "
                    "checkpoint all its processes finished, with the case and settings "
                    "recorded in its output folder (case.pbtxt, command.txt); its "
                    "timeseries.csv, coupling.csv and snapshot indexes continue in place "
                    "(docs/restart.md).")
    resume.add_argument("dir", metavar="DIR", help="output folder of the run (its --out)")
    resume.add_argument("--set", action="append", default=[], metavar="run.end_time=T",
                        help="a later end time; no other field may change")
    resume.add_argument("--quiet", action="store_true", help="show no progress")
    return parser, run


def add_plot_parser(sub):
    plot = sub.add_parser(
        "plot", help="draw the pictures of a run",
        description="Draw PNGs of an output folder, finished, still running or blown up: "
                    "the gauges of timeseries.csv against time (one figure per physical "
                    "group, over the published curves the case names in its 'reference' "
                    "fields), and the particles of chosen snapshots (water by pressure, "
                    "walls grey, solid by von Mises stress, failed particles marked), with "
                    "the last good state of a run that blew up.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Needs numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py "
               "python3-matplotlib).\n--movie writes an MP4 with ffmpeg if it is installed "
               "(Debian: ffmpeg), else a GIF\nwith Pillow (Debian: python3-pil); Debian 12 "
               "has both packages.\n\nexit codes: 0 success, 2 not an output folder, a missing "
               "package or bad input,\n1 a file that could not be read or written")
    plot.add_argument("dir", metavar="DIR", help="output folder of a run (its --out)")
    plot.add_argument("--into", metavar="FOLDER",
                      help="where to write the pictures (default DIR/plots, created if needed)")
    plot.add_argument("--times", metavar="T1,T2,...",
                      help="draw the snapshots nearest these times [s] (default: four, "
                           "evenly spread over those written)")
    plot.add_argument("--movie", action="store_true",
                      help="also an animation of every snapshot (movie.mp4 or movie.gif)")


def cmd_plot(args):
    """Imports the plotting module only now: running cases needs none of it."""
    from . import cosph_output, cosph_plot
    try:
        times = cosph_plot.parse_times(args.times) if args.times is not None else None
        written = cosph_plot.plot_run(Path(os.path.abspath(os.path.expanduser(args.dir))),
                                      into=args.into, times=times, movie=args.movie,
                                      repo=repo_dir())
    except (cosph_output.OutputError, cosph_plot.PlotError) as err:
        raise UsageError(str(err)) from err
    except OSError as err:   # a file that h5py or the PNG writer could not handle
        emit(sys.stderr, f"cosph: {err}\n")
        return EXIT_FAILURE
    if not written:
        emit(sys.stdout, f"cosph: nothing to draw yet in {args.dir}\n")
    emit(sys.stdout, "".join(f"{path}\n" for path in written))
    return EXIT_OK


def cmd_resume(args, repo, signals, run_parser):
    """Runs the recorded run again from its last complete checkpoint."""
    check_sets(args.set)
    check_resume_sets(args.set)
    out = Path(os.path.abspath(os.path.expanduser(args.dir)))
    recorded = recorded_run(out, run_parser)
    lock = lock_out_dir(out, shlex.join(sys.argv))  # held until the run ends
    case = out / "case.pbtxt"
    if not case.is_file():
        raise UsageError(f"{case}: missing: is {out} the output folder of a cosph run?")
    sets = recorded.set + args.set   # a later --set wins
    folder = bin_dir(repo)
    _plan_cmd, names, separate_cores = run_plan(find_exe(folder, "cosph-case"), case, sets)
    for name in names:
        find_exe(folder, name)
    checkpoints = last_complete_checkpoint(out, names)
    sequence = int(checkpoints[names[0]].stem.split("_")[-1])
    discard_later_checkpoints(out, sequence)
    endpoint = recorded.endpoint or default_endpoint(out)
    commands = [cmd + ["--resume", str(checkpoints[name])] for name, cmd in
                zip(names, with_key_args(child_commands(names, folder, case, out, sets, endpoint),
                                         names, out, endpoint, recorded.bind_any))]
    emit(sys.stderr, f"cosph: resuming {out} from {sequence:09d}"
                     f" ({', '.join(str(p.name) for p in checkpoints.values())})\n")
    try:
        with open(out / "command.txt", "a") as record:
            record.write("# resumed:\n" + "\n".join(shlex.join(c) for c in commands) + "\n")
    except OSError as err:
        raise UsageError(f"cannot record the resume in {out / 'command.txt'}: {err}") from err
    args.no_pin = False
    return start_and_supervise(
        args, out, names, commands, separate_cores, signals, lock,
        on_cores=lambda placement: len(names) > 1 and make_private_dir(out, folder, endpoint,
                                                                       names))


def cmd_run(args, repo, signals):
    check_sets(args.set)
    case = resolve_case(args.case, repo)
    folder = bin_dir(repo)
    plan_cmd, names, separate_cores = run_plan(find_exe(folder, "cosph-case"), case, args.set)
    for name in names:
        find_exe(folder, name)

    out = Path(os.path.abspath(os.path.expanduser(args.out)))
    endpoint = args.endpoint or default_endpoint(out)
    if len(names) > 1:
        check_endpoint(endpoint)
        check_bind(endpoint, args.bind_any)
    elif args.endpoint:
        emit(sys.stderr, f"cosph: note: --endpoint is not used, {names[0]} runs alone\n")
    lock = lock_out_dir(out, shlex.join(sys.argv))  # held until the run ends
    clear_earlier_output(out, case, args.overwrite)
    commands = with_key_args(child_commands(names, folder, case, out, args.set, endpoint),
                             names, out, endpoint, args.bind_any)

    def prepare(placement):
        prepare_out_dir(out, case, plan_cmd, commands, [placement.get(n) for n in names])
        if len(names) > 1:
            make_private_dir(out, folder, endpoint, names)
    return start_and_supervise(args, out, names, commands, separate_cores, signals, lock,
                               on_cores=prepare)


def start_and_supervise(args, out, names, commands, separate_cores, signals, lock, on_cores):
    """Starts the processes, the solvers of a multi-rate run on cores of their
    own where that pays, and supervises them; on_cores(placement) runs first.
    Each child is handed `lock`, the output folder's."""
    allowed = os.sched_getaffinity(0)
    placement = {} if args.no_pin else core_placement(names, separate_cores, allowed)
    on_cores(placement)

    mode = "quiet" if args.quiet else ("tty" if sys.stderr.isatty() else "plain")
    console = Console(mode)
    children = [Child(n, c) for n, c in zip(names, commands)]
    for child, name in zip(children, names):
        child.cores = placement.get(name)
        child.lock_fd = lock.fileno()
    if placement:
        console.line(sys.stderr, "cosph: multi-rate run: " + ", ".join(
            f"{child.name} on core{'s' if len(child.cores) > 1 else ''} "
            f"{','.join(map(str, child.cores))}" for child in children if child.cores) +
            " (--no-pin: let the scheduler place them)")
    run = Run(children, console, signals)
    started = time.monotonic()
    signals.raise_now = False   # from here on, signals are handled by run.supervise()
    try:
        run.start()
        code = run.supervise()
    finally:
        run.kill_remaining()   # a no-op normally; a safety net if the launcher has a bug
        console.finish()
    if code == EXIT_OK:
        print_summary(out, time.monotonic() - started, run.children)
    return code


def main(argv):
    for stream in (sys.stdout, sys.stderr):
        stream.reconfigure(errors="replace")   # never die on a solver's odd bytes
    signals = SignalState()
    signals.install()
    repo = repo_dir()
    try:
        parser, run_parser = build_parser(repo)
        args = parser.parse_args(argv)
        if args.command == "plot":
            return cmd_plot(args)
        if args.command == "resume":
            return cmd_resume(args, repo, signals, run_parser)
        if args.command != "run":
            parser.print_help(sys.stderr)
            return EXIT_BAD_INPUT
        return cmd_run(args, repo, signals)
    except UsageError as err:
        emit(sys.stderr, f"cosph: {err}\n")
        return EXIT_BAD_INPUT
    except Exit as exit_:
        return exit_.code
    except Interrupted:
        emit(sys.stderr, "cosph: interrupted\n")
        return EXIT_INTERRUPTED
