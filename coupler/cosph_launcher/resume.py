"""`cosph resume DIR`: what a stopped run recorded in its output folder (the
case, the --set values, the endpoint) and the last checkpoint that every one
of its processes finished (docs/restart.md)."""

import re
import shlex
from pathlib import Path

from .errors import UsageError

# The only field a resume may change: a longer run continues the same one.
RESUMABLE_FIELDS = ("run.end_time",)
CHECKPOINT_RE = re.compile(r"^(?P<part>[a-z]+)_(?P<sequence>\d+)\.h5$")


def recorded_run(out, run_parser):
    """The launcher's arguments of the run that wrote OUT, from its command.txt."""
    command_file = out / "command.txt"
    try:
        lines = command_file.read_text().splitlines()
    except OSError as err:
        raise UsageError(f"{command_file}: cannot read it ({err.strerror}): "
                         f"is {out} the output folder of a cosph run?") from err
    try:
        launcher = shlex.split(lines[lines.index("# launcher:") + 1])
    except (ValueError, IndexError) as err:
        raise UsageError(f"{command_file}: has no '# launcher:' line") from err
    if "run" not in launcher:
        raise UsageError(f"{command_file}: its launcher line is not a 'cosph run'")
    return run_parser.parse_args(launcher[launcher.index("run") + 1:])


def check_resume_sets(sets):
    """Refuses every --set but those of RESUMABLE_FIELDS, naming the field."""
    for item in sets:
        field = item.split("=", 1)[0].strip()
        if field not in RESUMABLE_FIELDS:
            raise UsageError(f"cannot resume with --set {item}: {field} would change the run; "
                             f"a resume may change only {', '.join(RESUMABLE_FIELDS)}")


def part_of(name):
    """The checkpoint part of an executable: fluid, coupler or solid."""
    base = Path(name).name
    if base == "cosph-fluid":
        return "fluid"
    if base == "cosph-coupler":
        return "coupler"
    return "solid"


def last_complete_checkpoint(out, names):
    """{name: path} of the newest checkpoint that every process finished
    (a .partial is a write that never finished and is never used)."""
    folder = out / "checkpoints"
    parts = [part_of(n) for n in names]
    found = {part: set() for part in parts}
    if folder.is_dir():
        for path in folder.iterdir():
            match = CHECKPOINT_RE.match(path.name)
            if match and match["part"] in found:
                found[match["part"]].add(int(match["sequence"]))
    common = set.intersection(*found.values())
    if not common:
        have = ", ".join(f"{part}: {len(s)}" for part, s in found.items())
        raise UsageError(f"no checkpoint in {folder} that every process ({', '.join(parts)}) "
                         f"finished ({have}); the run stopped before its first "
                         f"(run.checkpoint_interval)")
    sequence = max(common)
    return {name: folder / f"{part}_{sequence:09d}.h5" for name, part in zip(names, parts)}


def discard_later_checkpoints(out, sequence):
    """Removes the checkpoints taken after `sequence`: parts of a set that
    some process never finished (one stopped before the others wrote theirs,
    a Ctrl-C whose checkpoint the coupler could not complete). The resumed run
    takes those steps again; left, they would count as the newest two when
    its own checkpoints are pruned (sphcore/src/checkpoint.cpp)."""
    folder = out / "checkpoints"
    try:
        for path in folder.iterdir():
            match = CHECKPOINT_RE.match(path.name)
            if match and int(match["sequence"]) > sequence:
                path.unlink()
    except OSError as err:
        raise UsageError(f"cannot remove the unfinished checkpoints from {folder}: {err}") from err
