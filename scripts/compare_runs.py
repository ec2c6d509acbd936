#!/usr/bin/python3
"""Whether two run folders hold the same results, bit for bit.

Compares every timeseries.csv (as text) and every dataset of every HDF5
snapshot (*.h5: shape, type and each value's bits, so that NaNs compare and
-0 differs from +0) found below DIR_A with its counterpart below DIR_B, and
lists the files that only one side has. For checking that a change which
should not touch the physics (a restructure, a faster loop claimed to be
exact) leaves every number as it was.

Usage: scripts/compare_runs.py DIR_A DIR_B
Prints one line per difference and a summary; exits 1 if anything differs,
2 on bad usage.
"""
import pathlib
import sys

import h5py
import numpy as np


def compared_files(root):
    """The files that hold results, by their path below root."""
    return {p.relative_to(root): p for p in root.rglob("*")
            if p.is_file() and (p.name == "timeseries.csv" or p.suffix == ".h5")}


def dataset_names(h5):
    names = []
    h5.visititems(lambda name, item: names.append(name) if isinstance(item, h5py.Dataset) else None)
    return sorted(names)


def same_bits(a, b):
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    return a.tobytes() == b.tobytes()


def compare_h5(path_a, path_b):
    """The differences between two snapshot files, one string each."""
    differences = []
    with h5py.File(path_a, "r") as a, h5py.File(path_b, "r") as b:
        names_a, names_b = dataset_names(a), dataset_names(b)
        for name in sorted(set(names_a) ^ set(names_b)):
            differences.append(f"dataset {name} only in {'A' if name in names_a else 'B'}")
        for name in sorted(set(names_a) & set(names_b)):
            x, y = np.asarray(a[name][()]), np.asarray(b[name][()])
            if not same_bits(x, y):
                detail = f"shape {x.shape}/{y.shape}, type {x.dtype}/{y.dtype}"
                if x.shape == y.shape and x.dtype.kind == "f" == y.dtype.kind:
                    detail += f", {int(np.count_nonzero(x != y))} values differ, largest by " \
                              f"{float(np.nanmax(np.abs(x - y))) if x.size else 0.0:g}"
                differences.append(f"dataset {name} differs ({detail})")
    return differences


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    root_a, root_b = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    for root in (root_a, root_b):
        if not root.is_dir():
            print(f"compare_runs: {root} is not a folder", file=sys.stderr)
            return 2
    files_a, files_b = compared_files(root_a), compared_files(root_b)
    differing = 0
    for path in sorted(set(files_a) ^ set(files_b)):
        print(f"{path}: only in {root_a if path in files_a else root_b}")
        differing += 1
    common = sorted(set(files_a) & set(files_b))
    for path in common:
        if path.suffix == ".h5":
            differences = compare_h5(files_a[path], files_b[path])
        else:
            same = files_a[path].read_bytes() == files_b[path].read_bytes()
            differences = [] if same else ["text differs"]
        for difference in differences:
            print(f"{path}: {difference}")
        differing += bool(differences)
    print(f"compare_runs: {len(common)} files in both, {differing} differing or unmatched")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
