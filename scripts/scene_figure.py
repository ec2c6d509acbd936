#!/usr/bin/python3
"""The picture of docs/scenes.md: the example scene drawn with shapes
(docs/examples/shapes_tank.pbtxt) at its start and after 0.3 s, each drawn by
`coupler/cosph plot`, side by side in docs/figures/scene_shapes.png.

  /usr/bin/python3 scripts/scene_figure.py [--out DIR]

DIR keeps the run (default a temporary folder, removed afterwards).
"""
import argparse
import glob
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

import cosph_results as cr  # noqa: E402

EXAMPLE = os.path.join(cr.REPO, "docs", "examples", "shapes_tank.pbtxt")
TIMES = (0.0, 0.3)  # s
FIGURE = os.path.join(cr.FIGURES, "scene_shapes.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="folder for the run (kept)")
    args = parser.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="cosph_scene_")
    try:
        cr.run_case(EXAMPLE, out, [f"run.end_time={TIMES[-1]}", "run.snapshot_interval=0.05"])
        plots = os.path.join(out, "plots")
        subprocess.run([os.path.join(cr.REPO, "coupler", "cosph"), "plot", out, "--into", plots,
                        "--times", ",".join(str(t) for t in TIMES)], check=True)
        # particles_tT.TTTTs.png, one for each snapshot drawn, in time order.
        drawn = sorted(glob.glob(os.path.join(plots, "particles_t*s.png")))
        images = [mpimg.imread(path) for path in drawn]
        height, width = images[0].shape[:2]
        fig, axes = plt.subplots(1, len(images), figsize=(len(images) * width / 100, height / 100),
                                 dpi=100)
        for ax, image in zip(axes, images):
            ax.imshow(image)
            ax.axis("off")
        fig.subplots_adjust(left=0, right=1, top=1, bottom=0, wspace=0)
        fig.savefig(FIGURE, dpi=100)
        print(f"wrote {os.path.relpath(FIGURE, cr.REPO)}")
    finally:
        if not args.out:
            shutil.rmtree(out, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
