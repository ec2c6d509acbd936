"""Pictures of a cosph run (`coupler/cosph plot DIR`): the gauges of
timeseries.csv against time, over the published curves the case names, and
the particles of chosen snapshots: water coloured by pressure, walls grey,
the solid by its von Mises stress, failed solid particles marked.

numpy, h5py and matplotlib (Debian's python3-numpy, python3-h5py,
python3-matplotlib) are imported only when pictures are drawn, so that the
launcher runs with the standard library alone.
"""

import importlib
import math
import shutil
from pathlib import Path

from . import cosph_output as output

DEBIAN_PACKAGES = {"numpy": "python3-numpy", "h5py": "python3-h5py",
                   "matplotlib": "python3-matplotlib"}
DPI = 110
PARTICLE_PICTURES = 4      # snapshots drawn when --times is not given
MOVIE_FRAMES_PER_S = 8


class PlotError(Exception):
    """What the user must fix (a missing package, a bad --times); exit 2."""


def libraries():
    """numpy, h5py and matplotlib.pyplot, or a PlotError naming the Debian
    packages to install."""
    modules, missing = {}, []
    for name in DEBIAN_PACKAGES:
        try:
            modules[name] = importlib.import_module(name)
        except ImportError:
            missing.append(name)
    if missing:
        raise PlotError("plot needs " + ", ".join(missing) + ": install " +
                        " ".join(DEBIAN_PACKAGES[m] for m in missing) +
                        " (apt-get install " + " ".join(DEBIAN_PACKAGES[m] for m in missing) + ")")
    modules["matplotlib"].use("Agg")   # files only, no display needed
    return modules["numpy"], modules["h5py"], importlib.import_module("matplotlib.pyplot")


# --------------------------------------------------------------------------
# Units: a value shown with the SI prefix that brings it near 1 to 999

PREFIXES = ((1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "\u00b5"))
UNPREFIXED = ("", "1")


def display_unit(unit, largest):
    """(factor, unit text): the values times factor are in the unit shown."""
    if unit in UNPREFIXED or not math.isfinite(largest) or largest <= 0:
        return 1.0, unit
    for scale, prefix in PREFIXES:
        if largest >= scale:
            return 1.0 / scale, prefix + unit
    scale, prefix = PREFIXES[-1]
    return 1.0 / scale, prefix + unit


def labelled(name, unit):
    return f"{name} [{unit}]" if unit not in UNPREFIXED else name


# --------------------------------------------------------------------------
# Gauges

# One figure per physical group, in this order: (file stem, title, what its
# y axis shows, the columns it takes (name, unit) -> bool). A column goes to
# the first group that takes it; those no group takes get a figure per unit.
GAUGE_GROUPS = (
    ("water_front", "Water: surge front (from the left wall) and height (above the floor)",
     "distance", lambda n, u: n in ("front", "height", "level")),
    ("tip", "Solid: free-end (tip) displacement", "displacement",
     lambda n, u: n.startswith("tip_")),
    ("broken_part", "Solid: centre of mass of the broken-off part", "position",
     lambda n, u: n.startswith("broken_")),
    ("forces", "Forces per metre of depth (wallK: the case's fluid.walls[K])", "force",
     lambda n, u: u == "N/m"),
    ("pressures", "Pressures and stresses", "stress", lambda n, u: u == "Pa"),
    ("energy", "Energy per metre of depth", "energy", lambda n, u: u == "J/m"),
    ("speed", "Largest particle speed", "speed", lambda n, u: u == "m/s"),
    ("counts", "Particle counts", "", lambda n, u: u == "1"),
    ("time_step", "Time step", "dt", lambda n, u: n == "dt"),
)
TIME = "t"


def group_columns(names, units):
    """[(stem, title, y quantity, [column names])] of the figures to draw."""
    groups = {stem: [] for stem, *_ in GAUGE_GROUPS}
    rest = {}
    for name in names:
        if name == TIME:
            continue
        stem = next((g[0] for g in GAUGE_GROUPS if g[3](name, units[name])), None)
        if stem:
            groups[stem].append(name)
        else:
            rest.setdefault(units[name], []).append(name)
    figures = [(stem, title, quantity, groups[stem])
               for stem, title, quantity, _ in GAUGE_GROUPS if groups[stem]]
    for unit, columns in rest.items():
        stem = "other_" + "".join(c if c.isalnum() else "_" for c in unit or "no_unit")
        figures.append((stem, f"Other gauges [{unit}]", "value", columns))
    return figures


def plot_gauges(np, plt, folder, into, title, references):
    """One PNG per group of timeseries.csv columns; returns their paths."""
    path = Path(folder) / "timeseries.csv"
    if not path.is_file():
        return []
    series, units = output.read_timeseries(path)
    if len(series[TIME]) == 0:
        return []
    t = np.array(series[TIME])
    written = []
    for stem, group_title, quantity, columns in group_columns(list(series), units):
        # Counts differ by orders of magnitude (3500 water particles, 2
        # failed): each on its own axes.
        panels = [[c] for c in columns] if stem == "counts" else [columns]
        fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                 figsize=(7.5, 2.0 + 2.4 * len(panels) if len(panels) > 1 else 4.2))
        for ax, panel in zip(axes[:, 0], panels):
            draw_gauge_panel(np, ax, t, series, units, panel, quantity, references)
        axes[-1, 0].set_xlabel("t [s]")
        axes[-1, 0].set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1e-9)
        fig.suptitle(f"{title}\n{group_title}", fontsize=10)
        fig.tight_layout()
        written.append(save(plt, fig, into / f"timeseries_{stem}.png"))
    return written


def draw_gauge_panel(np, ax, t, series, units, columns, quantity, references):
    """The columns against t, each published curve for one of them drawn as
    markers of its colour, over the run's time span only."""
    unit = units[columns[0]]
    same_unit = all(units[c] == unit for c in columns)
    in_span = [(r, [(tr, v) for tr, v in zip(r.t, r.value) if t[0] <= tr <= t[-1]])
               for r in references if r.column in columns]
    largest = max([float(np.nanmax(np.abs(series[c]))) for c in columns] +
                  [abs(v) for _, points in in_span for _, v in points])
    factor, shown = display_unit(unit, largest) if same_unit else (1.0, "")
    colours = {}
    for column in columns:
        (line,) = ax.plot(t, factor * np.array(series[column]), lw=1.3,
                          label=column if same_unit else labelled(column, units[column]))
        colours[column] = line.get_color()
    for reference, points in in_span:
        label = f"{reference.label}, {reference.column}"
        if not points:
            label += " (no point in this run's time span)"
        ax.plot([p[0] for p in points], [factor * p[1] for p in points], "o", mfc="none",
                mec=colours[reference.column], mew=1.3, ms=6, label=label)
    if same_unit:
        ax.set_ylabel(labelled(columns[0] if len(columns) == 1 else quantity, shown))
    ax.grid(alpha=0.3)
    if len(columns) > 1 or in_span:
        ax.legend(fontsize=8)


# --------------------------------------------------------------------------
# Particle pictures

class Frame:
    """What one picture shows: a snapshot of each phase (or None) and a name."""

    def __init__(self, time, paths, stem, note=""):
        self.time, self.paths, self.stem, self.note = time, paths, stem, note


def nearest(index, time):
    """The (time, path) of index nearest `time`."""
    return min(index, key=lambda entry: abs(entry[0] - time)) if index else None


def snapshot_frames(indices, times=None, count=PARTICLE_PICTURES):
    """Frames at the chosen times: `count` evenly spread over the snapshots
    written, or those nearest `times`. Each phase's snapshot is the one
    nearest the frame's time."""
    main = max(indices.values(), key=len)
    if not main:
        return []
    if times is None:
        picks = sorted({round(k * (len(main) - 1) / max(count - 1, 1)) for k in range(count)})
        times = [main[k][0] for k in picks]
    frames, seen = [], set()
    for wanted in times:
        paths = {phase: nearest(index, wanted) for phase, index in indices.items()}
        time = nearest(main, wanted)[0]
        key = tuple(sorted((p, str(e[1])) for p, e in paths.items() if e))
        if key in seen:
            continue
        seen.add(key)
        frames.append(Frame(time, {p: e[1] for p, e in paths.items() if e},
                            f"particles_t{time:.4f}s"))
    return frames


def last_good_frame(folder, indices):
    """The last good state a solver kept when its run blew up, with the other
    phase's snapshot nearest it; None if no solver kept one."""
    kept = {phase: output.last_good(folder, phase) for phase in output.PHASES}
    kept = {phase: path for phase, path in kept.items() if path}
    if not kept:
        return None
    return Frame(None, kept, "particles_last_good",
                 note="last good state: the run blew up after it")


def read_snapshot(np, h5py, path):
    """{field: array} of one .h5 snapshot, and its time."""
    with h5py.File(path, "r") as f:
        data = {name: np.array(f[name]) for name in f.keys()}
        time = float(f.attrs["time"]) if "time" in f.attrs else float("nan")
    return data, time


def von_mises(np, solid):
    """The solid's von Mises stress: the stored field, or (a solid model that
    writes only the stress tensor) computed from it as sph::von_mises does,
    sqrt((3 s:s - (tr s)^2) / 2) of the in-plane stress."""
    if "von_mises" in solid:
        return solid["von_mises"]
    if all(k in solid for k in ("stress_xx", "stress_xy", "stress_yy")):
        xx, xy, yy = solid["stress_xx"], solid["stress_xy"], solid["stress_yy"]
        squared = xx ** 2 + 2 * xy ** 2 + yy ** 2
        return np.sqrt(np.maximum(0.5 * (3 * squared - (xx + yy) ** 2), 0.0))
    return None


class Scene:
    """Loaded particles of one frame."""

    def __init__(self, np, h5py, frame):
        self.np, self.frame, self.fluid, self.solid, times = np, frame, None, None, []
        for phase, path in frame.paths.items():
            data, time = read_snapshot(np, h5py, path)
            setattr(self, phase, data)
            times.append(time)
        if frame.time is None:
            frame.time = max(times)
        self.stress = von_mises(np, self.solid) if self.solid is not None else None

    def water(self):
        """Which fluid particles are water (kind 0), not wall (kind 1)."""
        if "kind" in self.fluid:
            return self.fluid["kind"] == 0
        return self.np.ones(len(self.fluid["position"]), dtype=bool)

    def free(self):
        """Which solid particles are free (not held by a clamp)."""
        if "clamped" in self.solid:
            return self.solid["clamped"] == 0
        return self.np.ones(len(self.solid["position"]), dtype=bool)

    def positions(self):
        return [d["position"][:, :2] for d in (self.fluid, self.solid) if d is not None]


def typical_spacing(np, points):
    """Median distance from a sample of particles to its nearest neighbour:
    the lattice spacing of a snapshot's start."""
    if len(points) < 2:
        return None
    sample = points[np.linspace(0, len(points) - 1, min(200, len(points))).astype(int)]
    distances = np.sqrt(((sample[:, None, :] - points[None, :, :]) ** 2).sum(axis=2))
    distances[distances <= 0] = np.inf
    return float(np.median(distances.min(axis=1)))


class Look:
    """What every picture of a run shares, so pictures and movie frames
    compare: the view, the marker sizes and the colour ranges."""

    def __init__(self, np, scenes):
        points = np.concatenate([p for s in scenes for p in s.positions()])
        lo, hi = points.min(axis=0), points.max(axis=0)
        size = np.maximum(hi - lo, 1e-6)
        margin = 0.03 * size.max()
        self.xlim = (lo[0] - margin, hi[0] + margin)
        self.ylim = (lo[1] - margin, hi[1] + margin)
        first = scenes[0]
        self.spacing = {phase: typical_spacing(np, getattr(first, phase)["position"][:, :2])
                        for phase in output.PHASES if getattr(first, phase) is not None}
        pressures = [s.fluid["pressure"][s.water()] for s in scenes
                     if s.fluid is not None and "pressure" in s.fluid]
        pressures = np.concatenate(pressures) if pressures else np.zeros(0)
        self.pressure = colour_range(np, pressures, floor=None)
        stresses = [s.stress[s.free()] for s in scenes if s.stress is not None]
        self.stress = colour_range(np, np.concatenate(stresses) if stresses else np.zeros(0),
                                   floor=0.0)


def colour_range(np, values, floor):
    """The colour scale's ends: the 0.5th and 99.5th percentiles, so one
    spurious particle does not wash out the rest; down to 0 for a pressure."""
    values = values[np.isfinite(values)]
    if len(values) == 0:
        return (0.0, 1.0)
    lo = floor if floor is not None else min(0.0, float(np.percentile(values, 0.5)))
    hi = float(np.percentile(values, 99.5))
    return (lo, hi if hi > lo else lo + 1.0)


class Canvas:
    """A figure with the domain at equal aspect ratio and a colour bar per
    phase; sizes in inches, so marker sizes follow the particle spacing."""

    WIDTH = 7.0       # in, the particles' axes at most
    HEIGHT = 5.0      # in, the particles' axes at most
    MARGIN = (0.75, 0.45, 0.55, 0.5)   # left, bottom, top, right (in)
    BAR = (0.15, 1.15)                 # colour bar width, and room for one with its labels

    def __init__(self, np, plt, look, title, bars):
        self.np, self.plt, self.look = np, plt, look
        dx, dy = look.xlim[1] - look.xlim[0], look.ylim[1] - look.ylim[0]
        scale = min(self.WIDTH / dx, self.HEIGHT / dy)   # in per m
        self.ax_w, self.ax_h = dx * scale, dy * scale
        left, bottom, top, right = self.MARGIN
        width = left + self.ax_w + right + self.BAR[1] * len(bars)
        height = bottom + self.ax_h + top + (0.35 if self.ax_h < 2.5 else 0.0)
        self.fig = plt.figure(figsize=(width, height))
        self.ax = self.fig.add_axes([left / width, bottom / height, self.ax_w / width,
                                     self.ax_h / height])
        self.points_per_m = 72.0 * scale
        self.title = title
        # Per phase: the colour scale, and the factor from Pa to its unit.
        self.mappables, self.factors = {}, {}
        for k, (phase, cmap, (vmin, vmax), name) in enumerate(bars):
            factor, unit = display_unit("Pa", max(abs(vmin), abs(vmax)))
            x = left + self.ax_w + 0.25 + self.BAR[1] * k
            cax = self.fig.add_axes([x / width, bottom / height, self.BAR[0] / width,
                                     self.ax_h / height])
            mappable = plt.cm.ScalarMappable(norm=plt.Normalize(factor * vmin, factor * vmax),
                                             cmap=cmap)
            self.fig.colorbar(mappable, cax=cax, label=f"{name} [{unit}]",
                              extend="both" if vmin < 0 else "max")
            self.mappables[phase], self.factors[phase] = mappable, factor

    def marker_area(self, spacing):
        """Area in points^2 of a marker as wide as the particle spacing."""
        return (0.95 * spacing * self.points_per_m) ** 2 if spacing else 4.0

    def draw(self, scene):
        np, ax, look = self.np, self.ax, self.look
        ax.clear()
        ax.set_xlim(*look.xlim)
        ax.set_ylim(*look.ylim)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        handles = []
        if scene.fluid is not None:
            xy, water = scene.fluid["position"], scene.water()
            area = self.marker_area(look.spacing.get("fluid"))
            ax.scatter(xy[~water, 0], xy[~water, 1], s=area, c="0.65", marker="s", lw=0)
            mappable = self.mappables["fluid"]
            pressure = self.factors["fluid"] * scene.fluid["pressure"][water]
            ax.scatter(xy[water, 0], xy[water, 1], s=area, c=pressure,
                       cmap=mappable.cmap, norm=mappable.norm, lw=0)
        if scene.solid is not None:
            xy, free = scene.solid["position"], scene.free()
            area = self.marker_area(look.spacing.get("solid"))
            mappable = self.mappables["solid"]
            colours = self.factors["solid"] * (scene.stress if scene.stress is not None
                                               else np.zeros(len(xy)))
            ax.scatter(xy[free, 0], xy[free, 1], s=area, c=colours[free], cmap=mappable.cmap,
                       norm=mappable.norm, lw=0)
            if not free.all():
                ax.scatter(xy[~free, 0], xy[~free, 1], s=area, c="0.35", lw=0)
                handles.append(legend_marker("s", "0.35", "solid, clamped"))
            failed = scene.solid["failed"] > 0 if "failed" in scene.solid else None
            if failed is not None and failed.any():
                ax.scatter(xy[failed, 0], xy[failed, 1], s=max(area, 9.0), marker="x", c="red",
                           lw=0.8)
                handles.append(legend_marker("x", "red", f"solid, failed ({int(failed.sum())})"))
        if handles:
            ax.legend(handles=handles, loc="best", fontsize=8)
        note = f", {scene.frame.note}" if scene.frame.note else ""
        ax.set_title(f"{self.title}\nt = {scene.frame.time:.4f} s{note}", fontsize=10)


def legend_marker(marker, colour, label):
    """A legend entry of readable size, however small the particles are drawn."""
    from matplotlib.lines import Line2D
    return Line2D([], [], marker=marker, ls="", color=colour, ms=6, label=label)


def colour_bars(look, scenes):
    """(phase, colour map, range in Pa, name) of the colour bars the scenes need."""
    bars = []
    if any(s.fluid is not None for s in scenes):
        bars.append(("fluid", "viridis", look.pressure, "water pressure"))
    if any(s.solid is not None for s in scenes):
        bars.append(("solid", "plasma", look.stress, "solid von Mises stress"))
    return bars


def plot_particles(np, h5py, plt, folder, into, title, times):
    """One PNG per chosen snapshot, and one of the last good state of a run
    that blew up; returns their paths."""
    indices = {phase: output.snapshot_index(folder, phase) for phase in output.PHASES}
    frames = snapshot_frames(indices, times) if any(indices.values()) else []
    kept = last_good_frame(folder, indices)
    if kept:
        frames.append(kept)
    if not frames:
        return []
    scenes = [Scene(np, h5py, frame) for frame in frames]
    look = Look(np, scenes)
    written = []
    for scene in scenes:
        canvas = Canvas(np, plt, look, title, colour_bars(look, scenes))
        canvas.draw(scene)
        written.append(save(plt, canvas.fig, into / f"{scene.frame.stem}.png"))
    return written


# --------------------------------------------------------------------------
# Movie

def movie_writer(plt):
    """(writer class, file suffix): ffmpeg's MP4 if ffmpeg is installed, else
    pillow's GIF; a PlotError saying what to install if neither is there."""
    from matplotlib import animation
    if shutil.which("ffmpeg"):
        return animation.FFMpegWriter, ".mp4"
    try:
        importlib.import_module("PIL")
    except ImportError:
        raise PlotError("--movie needs ffmpeg (apt-get install ffmpeg, for an MP4) or "
                        "Pillow (apt-get install python3-pil, for a GIF); neither is "
                        "installed") from None
    return animation.PillowWriter, ".gif"


def plot_movie(np, h5py, plt, folder, into, title):
    """An animation of every snapshot; returns its path, or None if there are
    no snapshots."""
    writer_class, suffix = movie_writer(plt)
    indices = {phase: output.snapshot_index(folder, phase) for phase in output.PHASES}
    main = max(indices.values(), key=len)
    if not main:
        return None
    frames = snapshot_frames(indices, [time for time, _ in main])
    # The look from at most a dozen frames spread over the run: reading every
    # snapshot twice would double the time of a long run's movie.
    sample = frames[::max(1, len(frames) // 12)] + frames[-1:]
    look = Look(np, [Scene(np, h5py, f) for f in sample])
    first = Scene(np, h5py, frames[0])
    canvas = Canvas(np, plt, look, title, colour_bars(look, [first]))
    path = into / f"movie{suffix}"
    writer = writer_class(fps=MOVIE_FRAMES_PER_S)
    with writer.saving(canvas.fig, str(path), dpi=DPI):
        for frame in frames:
            canvas.draw(Scene(np, h5py, frame))
            writer.grab_frame()
    plt.close(canvas.fig)
    return path


# --------------------------------------------------------------------------

def save(plt, fig, path):
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def parse_times(text):
    """--times "0.1,0.2" -> [0.1, 0.2]."""
    try:
        times = [float(item) for item in text.replace(",", " ").split()]
    except ValueError:
        raise PlotError(f"bad --times '{text}': expected times in s separated by "
                        f"commas, e.g. --times 0.1,0.2") from None
    if not times or not all(math.isfinite(t) for t in times):
        raise PlotError(f"bad --times '{text}': expected times in s, e.g. --times 0.1,0.2")
    return times


def plot_run(folder, into=None, times=None, movie=False, repo=None):
    """Draws the pictures of an output folder into `into` (default
    FOLDER/plots); returns the paths written. Raises output.OutputError for a
    folder that is not an output folder, PlotError for what the user must fix."""
    folder = output.check_output_folder(folder)
    np, h5py, plt = libraries()
    if movie:
        movie_writer(plt)   # say what is missing before drawing anything
    into = Path(into) if into else folder / "plots"
    into.mkdir(parents=True, exist_ok=True)
    case, case_path = output.read_case(folder)
    title = output.first(case, "title") or folder.name
    repo = Path(repo) if repo else Path(__file__).resolve().parent.parent
    references = output.read_references(case, repo, case_path, folder)
    written = plot_gauges(np, plt, folder, into, title, references)
    written += plot_particles(np, h5py, plt, folder, into, title, times)
    if movie:
        path = plot_movie(np, h5py, plt, folder, into, title)
        if path:
            written.append(path)
    return written
