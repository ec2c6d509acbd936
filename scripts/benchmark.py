#!/usr/bin/python3
"""Runs build/bin/cosph-bench (particle-steps per second, time per step) and
writes docs/results/benchmark.md. Not part of the test suite.

usage: /usr/bin/python3 scripts/benchmark.py [--steps N]"""
import argparse
import os
import platform
import subprocess

import cosph_results as cr


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200)
    args = parser.parse_args()
    binary = os.path.join(os.environ.get("COSPH_BIN", os.path.join(cr.REPO, "build", "bin")),
                          "cosph-bench")
    output = subprocess.run([binary, "--steps", str(args.steps)], check=True, text=True,
                            stdout=subprocess.PIPE).stdout
    print(output)
    rows = []
    for line in output.splitlines()[1:]:
        solver, particles, threads, ms, rate = line.split()
        rows.append([solver, particles, threads, f"{float(ms):.3f}", f"{float(rate) / 1e6:.2f} M"])
    cpu = platform.processor() or platform.machine()
    cr.write_table("benchmark", ["solver", "particles", "threads", "time per step (ms)",
                                 "particle-steps/s"], rows,
                   preamble=f"`scripts/benchmark.py` ({args.steps} steps of the dam break from rest, "
                            f"{os.cpu_count()} cores, {cpu}). Particles counts water and wall "
                            "particles within reach of the water.")


if __name__ == "__main__":
    main()
