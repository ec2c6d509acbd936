"""Locating the repository, the cases and the executables."""

import os
import re
from pathlib import Path

from .errors import UsageError

BUILD_HINT = "cmake --preset release && cmake --build --preset release -j2"
CASE_SUFFIX = ".pbtxt"


def repo_dir():
    """The repository this package lies in (coupler/cosph_launcher/)."""
    return Path(__file__).resolve().parent.parent.parent


def available_cases(cases_dir):
    if not cases_dir.is_dir():
        return []
    return sorted(p.stem for p in cases_dir.glob("*" + CASE_SUFFIX) if p.is_file())


def resolve_case(arg, repo):
    """CASE may be a path, a bare name (dam_break) or a name with extension,
    the last two relative to <repo>/cases. An existing path wins."""
    path = Path(arg).expanduser()
    if path.is_file():
        return path.resolve()
    cases_dir = repo / "cases"
    candidates = [cases_dir / arg]
    if not arg.endswith(CASE_SUFFIX):
        candidates.append(cases_dir / (arg + CASE_SUFFIX))
    for candidate in candidates:
        if candidate.is_file():
            return candidate.resolve()
    names = available_cases(cases_dir)
    listing = ("available cases: " + ", ".join(names)) if names else \
        f"no *{CASE_SUFFIX} cases found in {cases_dir}"
    raise UsageError(f"unknown case '{arg}': it is not a file, and there is no "
                     f"{cases_dir / (Path(arg).stem + CASE_SUFFIX)}\n{listing}")


def bin_dir(repo):
    env = os.environ.get("COSPH_BIN")
    folder = Path(env).expanduser() if env else repo / "build" / "bin"
    origin = "from COSPH_BIN" if env else "default, COSPH_BIN is not set"
    if not folder.is_dir():
        raise UsageError(f"executable folder {folder} ({origin}) does not exist.\n"
                         f"Build the project first:  {BUILD_HINT}")
    return folder


def exe_path(folder, name):
    """A planned program: an absolute path (a case's solid.executable, which
    cosph-case resolved) as it is, a cosph-* name in the executable folder."""
    return Path(name) if os.path.isabs(name) else folder / name


def find_exe(folder, name):
    exe = exe_path(folder, name)
    if os.path.isabs(name) and not (exe.is_file() and os.access(exe, os.X_OK)):
        raise UsageError(f"{name} (the case's solid.executable) is gone or no longer "
                         f"executable")
    if not (exe.is_file() and os.access(exe, os.X_OK)):
        origin = "from COSPH_BIN" if os.environ.get("COSPH_BIN") else \
            "set COSPH_BIN to use another folder"
        raise UsageError(f"{name} not found (or not executable) in {folder} ({origin}).\n"
                         f"Build the project first:  {BUILD_HINT}")
    return exe


SET_RE = re.compile(r"^[A-Za-z_][A-Za-z0-9_.\[\]]*=.+$", re.DOTALL)


def check_sets(sets):
    for item in sets:
        if not SET_RE.match(item):
            raise UsageError(f"bad --set '{item}': expected FIELD=VALUE, e.g. "
                             f"--set fluid.spacing=0.005 (FIELD is a field name, "
                             f"dotted for nested fields; VALUE must not be empty)")


def set_args(sets):
    return [arg for item in sets for arg in ("--set", item)]
