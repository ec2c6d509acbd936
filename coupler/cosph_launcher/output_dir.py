"""The output folder: the case as run and the commands to redo it, a lock
that keeps a second run out while one writes to it, and the policy for a
folder an earlier run wrote to (refused unless --overwrite; docs/restart.md,
"What is guaranteed")."""

import fcntl
import os
import re
import shlex
import shutil
import sys
import time

from .errors import UsageError

LOCK_NAME = ".cosph.lock"
# The launcher's children are handed its open lock under this variable (the
# descriptor's number; sphcore/output_lock.hpp): the folder is their run's.
# A process started by hand takes the lock itself, and is refused if another
# run holds it.
LOCK_FD_VARIABLE = "COSPH_OUT_LOCK_FD"

# The files a cosph run writes into its output folder (solvers, coupler,
# launcher, `cosph plot` into plots/), and nothing else: --overwrite removes
# these and leaves any other file alone.
OWN_FILE_RE = re.compile(
    r"^(?:timeseries\.csv|coupling\.csv|command\.txt|case\.pbtxt|coupler\.sock"
    r"|[A-Za-z0-9_-]+(?:_\d{6}|_last_good)\.h5|[A-Za-z0-9_-]+\.xdmf)(?:\.partial)?$")
CHECKPOINT_FILE_RE = re.compile(r"^[a-z]+_\d+\.h5(?:\.partial)?$")
PLOT_FILE_RE = re.compile(r"^(?:[A-Za-z0-9_.-]+\.png|movie\.(?:mp4|gif))$")


def lock_out_dir(out, what):
    """Creates OUT if needed and takes its lock for as long as this process
    lives (the returned file must stay open). A folder another run holds is
    refused, naming that run (`what` is this one's, recorded for the next)."""
    try:
        out.mkdir(parents=True, exist_ok=True)
        lock = open(out / LOCK_NAME, "a+")
    except OSError as err:
        raise UsageError(f"cannot prepare output folder {out}: {err}") from err
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        lock.seek(0)
        # The first line names the holder; a run started by hand adds its endpoint.
        holder = (lock.read().strip().splitlines() or [""])[0] or "a run that has not said which"
        lock.close()
        raise UsageError(f"{out} is in use by another run ({holder}); wait for it to "
                         f"finish or choose another --out") from None
    lock.seek(0)
    lock.truncate()
    lock.write(f"pid {os.getpid()}, started {time.strftime('%Y-%m-%d %H:%M:%S')}: {what}\n")
    lock.flush()
    return lock


def earlier_output(out):
    """The files an earlier cosph run left in OUT (paths, sorted)."""
    found = []
    if not out.is_dir():
        return found
    for path in out.iterdir():
        if path.is_file() and OWN_FILE_RE.match(path.name):
            found.append(path)
    for folder, pattern in (("checkpoints", CHECKPOINT_FILE_RE), ("plots", PLOT_FILE_RE)):
        if (out / folder).is_dir():
            found += [p for p in (out / folder).iterdir() if p.is_file() and pattern.match(p.name)]
    return sorted(found)


def clear_earlier_output(out, case, overwrite):
    """A folder an earlier run wrote to is refused unless `overwrite`; with it,
    that run's files are removed (the case being run excepted, when it is the
    folder's own case.pbtxt), so that no snapshot, row or checkpoint of it is
    mixed with this run's."""
    files = [p for p in earlier_output(out) if not (p.exists() and p.samefile(case))]
    if not files:
        return
    if not overwrite:
        names = ", ".join(str(p.relative_to(out)) for p in files[:4])
        more = f" and {len(files) - 4} more" if len(files) > 4 else ""
        raise UsageError(f"{out} holds the output of an earlier run ({names}{more}): "
                         f"give --overwrite to replace it, 'cosph resume {out}' to continue "
                         f"it, or choose another --out")
    try:
        for path in files:
            path.unlink()
        for folder in ("checkpoints", "plots"):
            if (out / folder).is_dir() and not any((out / folder).iterdir()):
                (out / folder).rmdir()
    except OSError as err:
        raise UsageError(f"cannot clear the earlier run's files from {out}: {err}") from err


def prepare_out_dir(out, case, plan_cmd, commands, cores):
    try:
        out.mkdir(parents=True, exist_ok=True)
        copy = out / "case.pbtxt"
        # Re-running from an output folder's own case.pbtxt must not truncate it.
        if not (copy.exists() and copy.samefile(case)):
            shutil.copyfile(case, copy)
            copy_outline_files(case, out)
        write_command_file(out, plan_cmd, commands, cores)
    except OSError as err:
        raise UsageError(f"cannot prepare output folder {out}: {err}") from err


# A region's outline file, named in the case relative to the case's folder.
OUTLINE_FILE_RE = re.compile(r'polygon_file\s*:\s*"([^"]+)"')


def copy_outline_files(case, out):
    """The outline files the case names, next to its copy at the same relative
    paths, so that the folder's case.pbtxt runs again as it is. Absolute paths
    need no copy; a path that leaves the case's folder is left to the solvers'
    own error if it is missing."""
    folder = case.resolve().parent
    for name in set(OUTLINE_FILE_RE.findall(case.read_text(errors="replace"))):
        relative = os.path.normpath(name)
        if os.path.isabs(relative) or relative.startswith(".."):
            continue
        source, target = folder / relative, out / relative
        if source.is_file() and not (target.exists() and target.samefile(source)):
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source, target)


def write_command_file(out, plan_cmd, commands, cores):
    """Everything needed to redo this run by hand (`cores`: for each command,
    the cores the launcher gave it, or None)."""
    lines = [f"# cosph run, {time.strftime('%Y-%m-%d %H:%M:%S %z')}",
             f"# working directory: {os.getcwd()}"]
    if os.environ.get("COSPH_BIN"):
        lines.append(f"# COSPH_BIN={os.environ['COSPH_BIN']}")
    lines += ["# launcher:", shlex.join(sys.argv),
              "# plan:", shlex.join(plan_cmd),
              "# processes, in start order:"]
    lines += [(f"taskset -c {','.join(map(str, c))} " if c else "") + shlex.join(cmd)
              for cmd, c in zip(commands, cores)]
    (out / "command.txt").write_text("\n".join(lines) + "\n")
