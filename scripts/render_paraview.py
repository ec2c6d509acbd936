"""A picture of one moment of a cosph run, made by ParaView from the run's
snapshots with ParaView's default XDMF reader (docs/paraview.md): the water
coloured by pressure, the walls grey (a Threshold on `kind`), the solid, if
the run has one (a solid run alone has no water), coloured by its von Mises stress.

Not part of the tests. Needs ParaView (Debian: apt-get install paraview
xvfb); without a display run it under xvfb:

    xvfb-run -a pvpython scripts/render_paraview.py OUTDIR --out picture.png [--time T]

--time picks the snapshot at or before T (default: the last one).
"""
import argparse
import os
import sys

import numpy as np
from paraview import servermanager
from paraview import simple as pv
from paraview.vtk.util.numpy_support import vtk_to_numpy

# Kind codes of the water solver's particles (fluid/src/fluid_particles.hpp).
WATER, WALL = 0, 1
WALL_GREY = [0.6, 0.6, 0.6]
# Layout of the picture: the share of its width the particles take (the
# colour bars have the rest), and the band on top for the time, in pixels.
PARTICLES_WIDTH = 0.72
TITLE_HEIGHT = 50


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", help="a run's output folder (holds fluid.xdmf, solid.xdmf or both)")
    parser.add_argument("--out", default="picture.png", help="the PNG to write")
    parser.add_argument("--time", type=float, default=None, help="s; default the last snapshot")
    parser.add_argument("--width", type=int, default=1400, help="pixels")
    return parser.parse_args()


def snapshot_time(reader, wanted):
    """The last snapshot time at or before `wanted` (all of them if None)."""
    times = list(reader.TimestepValues) or [0.0]
    if wanted is None:
        return times[-1]
    earlier = [t for t in times if t <= wanted + 1e-12]
    if not earlier:
        sys.exit(f"render_paraview: no snapshot at or before t = {wanted} s (first {times[0]} s)")
    return earlier[-1]


def particle_spacing(source, time):
    """The particles' spacing, as the median distance to the nearest other
    particle over a sample of them: the size to draw each particle at."""
    source.UpdatePipeline(time)
    data = servermanager.Fetch(source)
    points = vtk_to_numpy(data.GetPoints().GetData())[:, :2]
    sample = points[np.linspace(0, len(points) - 1, min(200, len(points))).astype(int)]
    distances = np.linalg.norm(points[None, :, :] - sample[:, None, :], axis=2)
    distances[distances == 0.0] = np.inf
    return float(np.median(distances.min(axis=1)))


def show_particles(source, view, spacing):
    """Each particle a disc of the spacing's diameter, touching its neighbours."""
    display = pv.Show(source, view)
    display.SetRepresentationType("Point Gaussian")
    display.ShaderPreset = "Plain circle"
    display.GaussianRadius = 0.5 * spacing
    return display


def bounds(sources, time):
    """x0, x1, y0, y1 of everything in `sources` at `time`."""
    boxes = []
    for source in sources:
        source.UpdatePipeline(time)
        boxes.append(source.GetDataInformation().GetBounds()[:4])
    boxes = np.array(boxes)
    return boxes[:, 0].min(), boxes[:, 1].max(), boxes[:, 2].min(), boxes[:, 3].max()


def colour_by(display, view, array, title, colour_map, left):
    """Colours `display` by the point array `array`, over its range at the
    view's time, with a colour bar whose left edge is at `left` (0..1)."""
    pv.ColorBy(display, ("POINTS", array))
    display.RescaleTransferFunctionToDataRange(False, True)
    lut = pv.GetColorTransferFunction(array)
    lut.ApplyPreset(colour_map, True)
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = bar.LabelFontSize = 14
    bar.RangeLabelFormat = "%.4g"
    bar.WindowLocation = "Any Location"
    bar.Position = [left, 0.12]
    bar.ScalarBarLength = 0.7


def kind_threshold(source, kind):
    threshold = pv.Threshold(Input=source, Scalars=["POINTS", "kind"])
    threshold.LowerThreshold = kind
    threshold.UpperThreshold = kind
    threshold.ThresholdMethod = "Between"
    return threshold


def main():
    args = parse_args()
    fluid_path = os.path.join(args.outdir, "fluid.xdmf")
    solid_path = os.path.join(args.outdir, "solid.xdmf")
    has_fluid, has_solid = os.path.isfile(fluid_path), os.path.isfile(solid_path)
    if not has_fluid and not has_solid:
        sys.exit(f"render_paraview: neither {fluid_path} nor {solid_path} exists "
                 f"(is {args.outdir} a cosph run?)")

    # OpenDataFile picks the reader ParaView's File > Open would (Xdmf3ReaderS).
    fluid = pv.OpenDataFile(fluid_path) if has_fluid else None
    solid = pv.OpenDataFile(solid_path) if has_solid else None
    time = snapshot_time(fluid or solid, args.time)
    view = pv.CreateView("RenderView")
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0

    shown, sources = [], []
    if fluid:
        sources.append(fluid)
        water = kind_threshold(fluid, WATER)
        walls = kind_threshold(fluid, WALL)
        fluid_spacing = particle_spacing(fluid, time)
        water_display = show_particles(water, view, fluid_spacing)
        colour_by(water_display, view, "pressure", "water pressure (Pa)", "Cool to Warm",
                  PARTICLES_WIDTH + 0.02)
        walls_display = show_particles(walls, view, fluid_spacing)
        pv.ColorBy(walls_display, None)
        walls_display.AmbientColor = walls_display.DiffuseColor = WALL_GREY
        shown += ["water by pressure", "walls grey"]
    if solid:
        sources.append(solid)
        solid_display = show_particles(solid, view, particle_spacing(solid, time))
        solid.UpdatePipeline(time)
        if "von_mises" in solid.PointData.keys():
            colour_by(solid_display, view, "von_mises", "solid von Mises stress (Pa)",
                      "Viridis (matplotlib)", PARTICLES_WIDTH + (0.15 if fluid else 0.02))
            shown.append("solid by von Mises stress")
        else:
            pv.ColorBy(solid_display, None)
            shown.append("solid (no von_mises array)")

    label = pv.Text(Text=f"t = {time:.4g} s")
    label_display = pv.Show(label, view)
    label_display.Color = [0.0, 0.0, 0.0]
    label_display.WindowLocation = "Upper Left Corner"
    label_display.FontSize = 18

    # A flat picture of the x-y plane: the particles on the left, framed with
    # a margin, the colour bars in a column of their own on the right.
    x0, x1, y0, y1 = bounds(sources, time)
    margin = 0.03 * (x1 - x0)
    x0, x1, y0, y1 = x0 - margin, x1 + margin, y0 - margin, y1 + margin
    scale = PARTICLES_WIDTH * args.width / (x1 - x0)  # pixels per metre
    height = int(round((y1 - y0) * scale)) + TITLE_HEIGHT
    view.ViewSize = [args.width, height]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.5 * height / scale
    centre = [x0 + 0.5 * args.width / scale, y1 + TITLE_HEIGHT / scale - 0.5 * height / scale]
    view.CameraFocalPoint = centre + [0.0]
    view.CameraPosition = centre + [1.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    pv.SaveScreenshot(args.out, view, ImageResolution=[args.width, height],
                      FontScaling="Do not scale fonts", TransparentBackground=0)
    print(f"render_paraview: {args.out}: t = {time:g} s, {', '.join(shown)}")


if __name__ == "__main__":
    main()
