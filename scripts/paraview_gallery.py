"""ParaView's default reader on every shipped case: runs each case (in full,
or to --end-time), then draws one moment of it with scripts/render_paraview.py
into docs/figures/paraview_NAME.png, the pictures of docs/paraview.md.

Not part of the tests: it needs ParaView and xvfb (apt-get install paraview
xvfb) and takes minutes.

    /usr/bin/python3 scripts/paraview_gallery.py [--runs DIR] [--reuse]

--reuse draws from runs already in DIR/NAME (for example those that
`coupler/cosph run NAME --out DIR/NAME` left) instead of running again.
"""
import argparse
import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FIGURES = ROOT / "docs" / "figures"

# The moment each picture shows: the water mid-flight, the plate bent most,
# the piece broken off; the oscillating plate at a quarter period.
CASES = {
    "dam_break": 0.201,
    "oscillating_plate": 0.061,
    "elastic_plate": 0.201,
    "plate_fracture": 0.201,
}


def run_case(name, out):
    """A fresh run into `out`, this script's own folder: an earlier run there goes."""
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([str(ROOT / "coupler" / "cosph"), "run", name, "--out", str(out), "--quiet"],
                   check=True, cwd=ROOT)


def draw(name, out, time, attempts=3):
    """pvpython under xvfb-run; on a loaded machine the virtual X server is
    sometimes not up when ParaView opens its window (it aborts), so a failed
    attempt is tried again."""
    picture = FIGURES / f"paraview_{name}.png"
    command = ["xvfb-run", "-a", "pvpython", str(ROOT / "scripts" / "render_paraview.py"),
               str(out), "--out", str(picture), "--time", str(time)]
    for attempt in range(attempts):
        if subprocess.run(command, cwd=ROOT).returncode == 0:
            return picture
    sys.exit(f"paraview_gallery: pvpython failed {attempts} times on {out}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", default=str(ROOT / "out" / "gallery"),
                        help="where the runs go (default out/gallery)")
    parser.add_argument("--reuse", action="store_true", help="draw the runs already in --runs")
    args = parser.parse_args()
    runs = Path(args.runs)
    for name, time in CASES.items():
        out = runs / name
        if not args.reuse:
            run_case(name, out)
        elif not out.is_dir():
            sys.exit(f"paraview_gallery: {out} does not exist; run without --reuse")
        print(f"paraview_gallery: {os.path.relpath(draw(name, out, time), ROOT)}")


if __name__ == "__main__":
    main()
