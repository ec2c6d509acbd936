"""The output folder: the case as run and the commands to redo it."""

import os
import re
import shlex
import shutil
import sys
import time

from .errors import UsageError

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
