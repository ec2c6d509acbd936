"""The output folder: the case as run and the commands to redo it."""

import os
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
        write_command_file(out, plan_cmd, commands, cores)
    except OSError as err:
        raise UsageError(f"cannot prepare output folder {out}: {err}") from err


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
