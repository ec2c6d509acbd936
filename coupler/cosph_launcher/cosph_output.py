"""Reading a cosph output folder, finished or still running: the case it ran,
timeseries.csv, the snapshot index of each solver, the last good state of a
run that blew up, and the published curves the case names.

Standard library only, like the launcher: this module says what a folder
holds; cosph_plot.py draws it.
"""

import math
import re
import shlex
import xml.etree.ElementTree as ElementTree
from pathlib import Path

PHASES = ("fluid", "solid")   # the snapshot names the solvers write (NAME.xdmf, NAME_*.h5)
LAST_GOOD = "last_good"      # NAME_last_good.h5: kept by a solver that ran alone and blew up


class OutputError(Exception):
    """The folder is not a cosph output folder, or a file in it is unreadable."""


# --------------------------------------------------------------------------
# The folder

def check_output_folder(folder):
    """An output folder holds timeseries.csv, a snapshot index or a last good
    state; anything else is refused, naming the folder."""
    folder = Path(folder)
    if not folder.is_dir():
        raise OutputError(f"{folder} is not a folder")
    marks = [folder / "timeseries.csv"] + [folder / f"{p}.xdmf" for p in PHASES] + \
        [folder / f"{p}_{LAST_GOOD}.h5" for p in PHASES]
    if not any(mark.is_file() for mark in marks):
        raise OutputError(f"{folder} is not a cosph output folder: it has no timeseries.csv, "
                          f"no fluid.xdmf or solid.xdmf and no *_{LAST_GOOD}.h5 "
                          f"(give the --out folder of a 'cosph run')")
    return folder


# --------------------------------------------------------------------------
# timeseries.csv

def read_timeseries(path):
    """{name: [values]} and {name: unit} of a cosph CSV ("t [s],front [m],...").

    A run still going may have written half a row: rows that do not parse
    are left out."""
    with open(path) as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    if not lines:
        raise OutputError(f"{path} is empty")
    names, units = [], {}
    for item in lines[0].strip().split(","):
        match = re.match(r"^\s*([^\[]+?)\s*(?:\[(.*)\])?\s*$", item)
        name = match.group(1) if match else item.strip()
        names.append(name)
        units[name] = match.group(2) if match and match.group(2) is not None else ""
    columns = {name: [] for name in names}
    for line in lines[1:]:
        fields = line.strip().split(",")
        if len(fields) != len(names):
            continue
        try:
            values = [float(v) for v in fields]
        except ValueError:
            continue
        for name, value in zip(names, values):
            columns[name].append(value)
    return columns, units


# --------------------------------------------------------------------------
# Snapshots

def snapshot_index(folder, phase):
    """[(time, path)] of the snapshots NAME.xdmf lists, in time order; files
    it lists that are gone are left out."""
    index = Path(folder) / f"{phase}.xdmf"
    if not index.is_file():
        return []
    try:
        root = ElementTree.parse(index).getroot()
    except ElementTree.ParseError as err:
        raise OutputError(f"{index}: not a readable XDMF file ({err})") from err
    snapshots = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time, item = grid.find("Time"), grid.find("Geometry/DataItem")
        if time is None or item is None or not item.text:
            continue
        path = Path(folder) / item.text.strip().split(":")[0]
        if path.is_file():
            snapshots.append((float(time.get("Value")), path))
    return sorted(snapshots, key=lambda s: s[0])


def last_good(folder, phase):
    """The NAME_last_good.h5 a solver kept when its run blew up, or None."""
    path = Path(folder) / f"{phase}_{LAST_GOOD}.h5"
    return path if path.is_file() else None


# --------------------------------------------------------------------------
# The case: a small reader of protobuf text format

TOKEN_RE = re.compile(r"""\s*(?:(\#[^\n]*)|("(?:[^"\\]|\\.)*"|'(?:[^'\\]|\\.)*')|([{}\[\]:,;<>])|([^\s{}\[\]:,;<>"'#]+))""")


def _tokens(text):
    position = 0
    while position < len(text):
        match = TOKEN_RE.match(text, position)
        if not match or match.end() == position:
            if text[position:].strip():
                raise OutputError(f"cannot read case text near {text[position:position + 30]!r}")
            return
        position = match.end()
        comment, string, symbol, word = match.groups()
        if comment is not None:
            continue
        if string is not None:
            yield ("string", re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)),
                                    string[1:-1]))
        elif symbol is not None:
            yield ("symbol", symbol)
        elif word is not None:
            yield ("word", word)


def parse_text_format(text):
    """A protobuf text-format message as {field: [values]}; a value is a str,
    a float, or a nested message. Enough for the case files, whose schema the
    launcher does not have: cosph-case checks them."""
    tokens = list(_tokens(text))
    message, _ = _parse_message(tokens, 0, None)
    return message


def _parse_message(tokens, k, closing):
    message = {}
    while k < len(tokens):
        kind, value = tokens[k]
        if kind == "symbol" and value == closing:
            return message, k + 1
        if kind != "word":
            raise OutputError(f"unexpected {value!r} in case text")
        name, k = value, k + 1
        if k < len(tokens) and tokens[k] == ("symbol", ":"):
            k += 1
        values, k = _parse_value(tokens, k)
        message.setdefault(name, []).extend(values)
        if k < len(tokens) and tokens[k][0] == "symbol" and tokens[k][1] in ",;":
            k += 1
    if closing is not None:
        raise OutputError("case text ends inside a message")
    return message, k


def _parse_value(tokens, k):
    if k >= len(tokens):
        raise OutputError("case text ends where a value was expected")
    kind, value = tokens[k]
    if kind == "symbol" and value in "{<":
        nested, k = _parse_message(tokens, k + 1, "}" if value == "{" else ">")
        return [nested], k
    if kind == "symbol" and value == "[":
        values, k = [], k + 1
        while tokens[k] != ("symbol", "]"):
            more, k = _parse_value(tokens, k)
            values += more
            if tokens[k] == ("symbol", ","):
                k += 1
        return values, k + 1
    if kind == "string":
        # Adjacent strings concatenate, as in protobuf text format.
        while k + 1 < len(tokens) and tokens[k + 1][0] == "string":
            k += 1
            value += tokens[k][1]
        return [value], k + 1
    try:
        return [float(value)], k + 1
    except ValueError:
        return [value], k + 1   # an enum or bool word


def first(message, name, default=None):
    values = message.get(name) if message else None
    return values[0] if values else default


def read_case(folder):
    """The case the run used: its parsed text (case.pbtxt, the launcher's
    copy), and the original case file's path from command.txt if known."""
    folder = Path(folder)
    copy = folder / "case.pbtxt"
    case = parse_text_format(copy.read_text()) if copy.is_file() else {}
    return case, original_case_path(folder)


def original_case_path(folder):
    """The case file cosph-case planned the run from (command.txt, "# plan:")."""
    command = Path(folder) / "command.txt"
    if not command.is_file():
        return None
    lines = command.read_text().splitlines()
    for k, line in enumerate(lines[:-1]):
        if line.strip() == "# plan:":
            words = shlex.split(lines[k + 1])
            if len(words) >= 3 and words[1] == "plan":
                return Path(words[2])
    return None


# --------------------------------------------------------------------------
# Published curves the case names (proto/case.proto, message Reference)

class Reference:
    """One published curve, in the run's units: t [s] and the value in the
    unit of the timeseries.csv column it is compared with."""

    def __init__(self, column, label, t, value, path):
        self.column, self.label, self.t, self.value, self.path = column, label, t, value, path


def reference_folder(repo):
    return Path(repo) / "validation" / "reference"


def find_reference_file(name, repo, case_path, folder):
    """A name in the repository's validation/reference/, else a path relative
    to the case file's folder (the original, then the output folder's copy)."""
    places = [reference_folder(repo)]
    if case_path is not None:
        places.append(Path(case_path).parent)
    places.append(Path(folder))
    for place in places:
        candidate = place / name
        if candidate.is_file():
            return candidate
    raise OutputError(f"reference file '{name}' the case names is in none of: " +
                      ", ".join(str(p) for p in places))


def read_reference_csv(path):
    """Column names and {name: [values]} of a reference CSV: '#' comment lines,
    one header row, then numbers."""
    with open(path) as f:
        lines = [line.strip() for line in f if line.strip() and not line.startswith("#")]
    if len(lines) < 2:
        raise OutputError(f"{path}: no header row and data")
    names = [n.strip() for n in lines[0].split(",")]
    columns = {n: [] for n in names}
    for line in lines[1:]:
        values = line.split(",")
        if len(values) != len(names):
            raise OutputError(f"{path}: row {line!r} has {len(values)} values, the header "
                              f"{len(names)}")
        for n, v in zip(names, values):
            columns[n].append(float(v))
    return names, columns


def read_references(case, repo, case_path, folder):
    """The case's `reference` entries, each read and scaled to the run's units."""
    references = []
    for entry in case.get("reference", []):
        name, column = first(entry, "file"), first(entry, "column")
        if not name or not column:
            raise OutputError("a reference of the case lacks its file or its column")
        path = find_reference_file(name, repo, case_path, folder)
        names, data = read_reference_csv(path)
        if len(names) < 2:
            raise OutputError(f"{path}: a reference needs a time and a value column")
        time_name = first(entry, "time_column") or names[0]
        value_name = first(entry, "value_column") or names[1]
        for wanted in (time_name, value_name):
            if wanted not in data:
                raise OutputError(f"{path} has no column '{wanted}' (it has {', '.join(names)})")
        time_scale = float(first(entry, "time_scale", 0.0)) or 1.0
        value_scale = float(first(entry, "value_scale", 0.0)) or 1.0
        if not all(math.isfinite(s) for s in (time_scale, value_scale)):
            raise OutputError(f"reference {name}: time_scale and value_scale must be finite")
        references.append(Reference(
            column, first(entry, "label") or path.name,
            [time_scale * t for t in data[time_name]],
            [value_scale * v for v in data[value_name]], path))
    return references
