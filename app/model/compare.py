"""Compare mode: several algorithms on the same primitives, stepped together.

A *pane* is an algorithm with the options it sets; it runs on shared
primitives, a ``Scene`` (points, grid, and the options of the scene they
came from). Options the scene changed from their defaults carry over
to panes whose algorithm has an option of the same name and kind (a
circle's radius, a triangle's colours and depths), as they do when the
main window switches algorithm; the pane's own options win.

Besides the registered algorithms a pane may be ``EXACT``: the exact
coverage of the shapes an antialiasing run draws (``geometry.
exact_reference``), a run of one frame that the estimates aim at.

``diff`` sorts the cells of two rasters into only in A, only in B and in
both; cells in both whose values differ are counted apart. The values are
the coverage where both runs write coverages (antialiasing), the colour
where both write colours, and otherwise how often the cell was written (so
that a pixel two triangles of a mesh both fill shows up).

``linked_indices`` turns one position on the shared timeline into a step
per pane: by frame (step k everywhere, held at the end of shorter runs) or
by progress (the same fraction of every run).

Nothing here imports Qt (so not app.player either, which is a QObject;
the point helpers come from app.inputs, which the player uses too).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from algorithms.core import registry
from algorithms.core.errors import InputError
from algorithms.core.raster import Raster, check_grid

from app.model import colours
from app.model.geometry import exact_reference, final_coverage, run_paths
from app.model.inputs import split_contours
from app.model.scene import SHIPPED, Scene, load

EXACT = "exact-coverage"
EXACT_TITLE = "Exact coverage"
# The exact pane takes the inputs and shape options of this algorithm.
EXACT_BASE = "aa-supersample"
FRAME, PROGRESS = "frame", "progress"
LINKS = (FRAME, PROGRESS)
MIN_PANES, MAX_PANES = 2, 4
# Coverages closer than this count as the same value (float round-off of
# two ways to the same area).
COVERAGE_TOLERANCE = 1e-9
STEP_CAP = 2_000_000


# ------------------------------------------------------------------ panes
@dataclass(frozen=True)
class Pane:
    """An algorithm and the options this pane sets (name, value) pairs."""

    algorithm: str
    options: tuple = ()

    @classmethod
    def of(cls, algorithm: str, **options) -> "Pane":
        return cls(algorithm, tuple(sorted(options.items())))

    def settings(self) -> dict:
        return dict(self.options)


def spec_of(algorithm: str):
    """The spec whose inputs and options a pane takes (the exact pane
    borrows those of EXACT_BASE); raises InputError for an unknown name."""
    return registry.get(EXACT_BASE if algorithm == EXACT else algorithm)


def algorithm_names() -> list[str]:
    """Every algorithm a pane can run, the exact coverage last."""
    return [spec.name for spec in registry.all_specs()] + [EXACT]


def algorithm_title(algorithm: str) -> str:
    if algorithm == EXACT:
        return EXACT_TITLE
    try:
        return registry.get(algorithm).title
    except InputError:
        return algorithm


def parse_options(algorithm: str, text: str) -> tuple:
    """Options typed as ``key=value`` pairs, separated by spaces or ';'
    (a value may hold commas: ``colors=#ff0000,#00ff00``). Raises
    InputError naming the first bad pair."""
    spec = spec_of(algorithm)
    result = {}
    for part in re.split(r"[;\s]+", text.strip()):
        if not part:
            continue
        name, equals, value = part.partition("=")
        if not equals or not name:
            raise InputError(f"{part!r} is not key=value (options: "
                             f"{', '.join(o.name for o in spec.options) or 'none'})")
        result[name] = spec.option(name).parse(value)
    return tuple(sorted(result.items()))


def format_options(options) -> str:
    """The inverse of parse_options: ``key=value`` pairs for a text field."""
    return " ".join(f"{name}={value_text(value)}" for name, value in dict(options).items())


def value_text(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, (tuple, list)):
        return ",".join(value_text(v) for v in value)
    return str(value)


# -------------------------------------------------------------- primitives
def window_primitives(player) -> Scene:
    """The main window's complete primitives (not a contour or a triangle
    still being drawn) with the options it changed from their defaults."""
    spec = player.spec
    width, height = player.grid
    return Scene(algorithm=spec.name, points=player.input_points(),
                 options=_changed_options(spec, player.options), width=width, height=height,
                 title="the main window's scene")


def file_primitives(scene: Scene) -> Scene:
    """A shipped or saved scene with only the options it changed from their defaults."""
    spec = scene.spec
    return scene.replace(options=_changed_options(spec, spec.resolve(scene.options)))


def _changed_options(spec, options: dict) -> dict:
    return {o.name: options[o.name] for o in spec.options
            if o.name in options and options[o.name] != o.default}


def fit_points(source, points, breaks, target):
    """The points as ``target`` (a spec) takes them: contours, k triangles
    or a fixed number of points. Raises InputError saying why they do not
    fit. Whole-pixel inputs take the pixel a real point lies in."""
    src, dst = source.inputs, target.inputs
    points = [_convert(p, dst.integer) for p in points]
    if src.multiple:
        groups = [points[k:k + src.count] for k in range(0, len(points), src.count)]
    elif src.contours:
        groups = split_contours(points, breaks)
    else:
        groups = [points]
    if dst.contours:
        contours = [g for g in groups if len(g) >= dst.count]
        if not contours:
            raise InputError(f"{target.title} takes polygons of at least {dst.count} points; "
                             f"the scene has {len(points)} point{'s' * (len(points) != 1)}")
        return contours
    if dst.multiple:
        # A contour stands for a triangle only when it has three points.
        sizes = [len(g) for g in groups] if src.contours else [len(points)]
        wrong = [size != dst.count for size in sizes] if src.contours and dst.count > 1 else \
            [size % dst.count for size in sizes]
        if not points or any(wrong):
            raise InputError(f"{target.title} takes {dst.text()}; the scene has "
                             + " + ".join(str(s) for s in sizes) + " points")
        return points
    if len(points) != dst.count:
        raise InputError(f"{target.title} takes {dst.text()}; the scene has "
                         f"{len(points)} point{'s' * (len(points) != 1)}")
    return points


def _convert(point, integer: bool):
    x, y = point
    if integer:
        return (math.floor(x), math.floor(y))
    return (float(x), float(y))


def pane_options(pane: Pane, primitives: Scene) -> dict:
    """The options a pane runs with: the scene's changed options where the
    pane's algorithm has them (same name and kind), then the pane's own."""
    spec, source = spec_of(pane.algorithm), primitives.spec
    kinds = {o.name: o.kind for o in source.options}
    carried = {}
    for option in spec.options:
        value = primitives.options.get(option.name)
        if value is not None and kinds.get(option.name) == option.kind:
            try:
                carried[option.name] = option.check(value)
            except InputError:
                pass  # the value means something else here: keep the default
    return spec.resolve({**carried, **pane.settings()})


# ------------------------------------------------------------------ runs
class Run:
    """One pane recorded on the primitives, or the reason it could not be."""

    def __init__(self, pane: Pane, primitives: Scene, step_cap: int = STEP_CAP):
        self.pane = pane
        self.grid = tuple(primitives.grid)
        self.spec = None
        self.options: dict = {}
        self.points = None
        self.trace = None
        self.exact = None
        self.error = ""
        self._writes = None  # every write of the run (Trace.written), made on first use
        self._state = None  # the last FrameState replayed
        try:
            self.spec = spec_of(pane.algorithm)
            self.options = pane_options(pane, primitives)
            self.points = fit_points(primitives.spec, primitives.flat,
                                     primitives.breaks, self.spec)
            self._record(step_cap)
        except InputError as error:
            self.error = str(error)
        except Exception as error:  # noqa: BLE001 - a failing run must not end the program
            self.error = f"{algorithm_title(pane.algorithm)} cannot run on this input " \
                         f"({type(error).__name__}: {error})"

    def _record(self, step_cap: int) -> None:
        width, height = self.grid
        check_grid(width, height)
        if self.pane.algorithm != EXACT:
            self.trace = self.spec.record(self.points, self.options, self.grid, step_cap)
            return
        self.spec.inputs.check(self.points)
        exact = exact_reference(self.spec, self.points, self.options, self.grid)
        if exact is None or exact.shape != (height, width):
            raise InputError("no exact coverage for this input")
        self.exact = np.asarray(exact, dtype=np.float64)

    @property
    def ok(self) -> bool:
        return not self.error

    @property
    def title(self) -> str:
        text = algorithm_title(self.pane.algorithm)
        shown = format_options(self.pane.options)
        return f"{text} \u00b7 {shown}" if shown else text

    def __len__(self) -> int:
        if self.error:
            return 0
        return 1 if self.trace is None else len(self.trace)

    @property
    def last(self) -> int:
        return max(0, len(self) - 1)

    def paths(self) -> list:
        """The ideal primitive, as the main grid draws it."""
        if self.points is None:
            return []
        return run_paths(self.spec, self.points, self.options, self.trace)

    def state_at(self, i: int):
        """The replayed FrameState at step i (None for the exact pane or a failed run).
        The last one is kept: the diff and the pane ask for the same step."""
        if self.trace is None:
            return None
        i = min(max(int(i), 0), self.last)
        if self._state is None or self._state.index != i:
            self._state = self.trace.state_at(i)
        return self._state

    def raster_at(self, i: int) -> Raster | None:
        if self.error:
            return None
        if self.trace is not None:
            return self.state_at(i).raster
        return exact_raster(self.exact)

    @property
    def value_kind(self) -> str:
        """"coverage", "colour" or "" (the run writes no values)."""
        if self.exact is not None:
            return "coverage"
        start = None if self.trace is None else self.trace.start
        if start is None or start.pixel_value is None:
            return ""
        return "coverage" if start.color_value is not None else "colour"

    def values_at(self, i: int, raster: Raster | None = None) -> np.ndarray | None:
        """(H, W) value of each written cell at step i (NaN elsewhere): the
        coverage or colour; the write count for runs that write no values."""
        raster = raster if raster is not None else self.raster_at(i)
        if raster is None:
            return None
        written = raster.counts > 0
        kind = self.value_kind
        if kind == "coverage" and self.exact is not None:
            values = self.exact
        elif kind == "coverage":
            values = self._coverage_at(min(max(int(i), 0), self.last))
        elif kind == "colour":
            values = raster.colors.astype(np.float64)
        else:
            values = raster.counts.astype(np.float64)
        return np.where(written, values, np.nan)

    def _coverage_at(self, i: int) -> np.ndarray:
        if self._writes is None:
            self._writes = self.trace.written()
        writes = self._writes
        n = int(np.searchsorted(writes.steps, i, side="right"))
        return final_coverage(self.trace.width, self.trace.height, writes.pixels[:n],
                                     writes.values[:n])


def exact_raster(coverage: np.ndarray) -> Raster:
    """The exact coverage as a raster: cells with any coverage written
    once, in black ink over white by their coverage (as the antialiasing
    runs blend their default ink)."""
    height, width = coverage.shape
    raster = Raster(width, height, with_colors=True)
    covered = coverage > 0
    raster.counts[covered] = 1
    grey = np.clip(np.floor(255.0 * (1.0 - coverage) + 0.5), 0, 255).astype(np.int64)
    raster.colors[covered] = ((grey << 16) | (grey << 8) | grey)[covered]
    return raster


def run_panes(panes, primitives: Scene, step_cap: int = STEP_CAP) -> list[Run]:
    return [Run(pane, primitives, step_cap) for pane in panes]


# ------------------------------------------------------------------ diff
DIFF_CLASSES = ("only A", "only B", "both, same value", "both, different value")


@dataclass(frozen=True)
class Diff:
    """Cells of two rasters by where they were written. ``kind`` names
    the value compared in cells both wrote ("coverage", "colour", "write
    count"), or "" where the two runs write different kinds of value."""

    only_a: np.ndarray
    only_b: np.ndarray
    both_same: np.ndarray
    both_different: np.ndarray
    kind: str = ""

    @property
    def by_class(self) -> dict:
        """Cell counts keyed by DIFF_CLASSES, as the legend lists them."""
        masks = (self.only_a, self.only_b, self.both_same, self.both_different)
        return {name: int(mask.sum()) for name, mask in zip(DIFF_CLASSES, masks)}

    @property
    def counts(self) -> dict:
        return {"only A": int(self.only_a.sum()), "only B": int(self.only_b.sum()),
                "both": int(self.both_same.sum() + self.both_different.sum()),
                "both, different value": int(self.both_different.sum())}

    def cells(self) -> np.ndarray:
        """(n, 2) cells (x, y) that differ: in one run only, or valued differently."""
        ys, xs = np.nonzero(self.only_a | self.only_b | self.both_different)
        return np.stack([xs, ys], axis=1).astype(np.int64)

    def classes(self) -> np.ndarray:
        """(H, W) int8: 0 neither, 1 only A, 2 only B, 3 both same, 4 both different."""
        result = np.zeros(self.only_a.shape, np.int8)
        for code, mask in enumerate((self.only_a, self.only_b, self.both_same,
                                     self.both_different), start=1):
            result[mask] = code
        return result


def diff(a: Raster, b: Raster, values_a=None, values_b=None, kind_a: str = "",
         kind_b: str = "") -> Diff:
    """Compare two rasters of one grid (``values_*`` from ``Run.values_at``
    and ``kind_*`` from ``Run.value_kind``; without values the write
    counts are compared)."""
    if a.counts.shape != b.counts.shape:
        raise ValueError(f"rasters of different grids: {a.counts.shape} and {b.counts.shape}")
    in_a, in_b = a.counts > 0, b.counts > 0
    both = in_a & in_b
    kind = kind_a if kind_a == kind_b else None
    if kind is None:
        different = np.zeros_like(both)
        kind = ""
    else:
        if values_a is None or values_b is None:
            values_a, values_b = a.counts, b.counts
        values_a, values_b = np.asarray(values_a, float), np.asarray(values_b, float)
        if kind == "coverage":
            different = both & ~np.isclose(values_a, values_b, rtol=0.0,
                                           atol=COVERAGE_TOLERANCE)
        else:
            different = both & (values_a != values_b)
        kind = kind or "write count"
    return Diff(in_a & ~in_b, in_b & ~in_a, both & ~different, different, kind)


def diff_runs(a: Run, b: Run, index_a: int, index_b: int) -> Diff | None:
    """The diff of two panes at their steps, or None if either has no run
    or the two grids differ."""
    raster_a, raster_b = a.raster_at(index_a), b.raster_at(index_b)
    if raster_a is None or raster_b is None or raster_a.counts.shape != raster_b.counts.shape:
        return None
    return diff(raster_a, raster_b, a.values_at(index_a, raster_a), b.values_at(index_b, raster_b),
                a.value_kind, b.value_kind)


def diff_pair(old: tuple, a: int, b: int, count: int) -> tuple[int, int]:
    """The two panes the diff shows once a person picks ``a`` and ``b``,
    each within 0 .. count-1. A pane is never diffed against itself: picking
    for one side the pane the other side shows swaps the two."""
    a, b = (min(max(k, 0), count - 1) for k in (a, b))
    if a != b or count < 2:
        return a, b
    picked_a = a != old[0]
    other = old[0] if picked_a else old[1]  # the pane the picked side showed
    if other == a:
        other = (a + 1) % count
    return (a, other) if picked_a else (other, b)


# Colours of the diff view (light theme), in DIFF_CLASSES order: two hues
# far apart for the two runs, a quiet grey for agreement, black for a value
# that differs; each class also has a pattern (colours.DIFF_PATTERNS).
DIFF_COLOURS = colours.LIGHT.diff


# --------------------------------------------------------------- stepping
def timeline_last(runs) -> int:
    """The last position of the shared timeline: the longest run's last step."""
    return max([run.last for run in runs if run.ok] or [0])


def linked_indices(position: int, lasts, link: str = FRAME) -> list[int]:
    """The step each pane shows at ``position`` of the shared timeline
    (0 .. max(lasts)). By frame: that step, held at the end of a shorter
    run. By progress: the same fraction of each run, rounded half up."""
    if link not in LINKS:
        raise ValueError(f"link by {link!r}: use one of {', '.join(LINKS)}")
    top = max(list(lasts) or [0])
    position = min(max(int(position), 0), top)
    if link == FRAME:
        return [min(position, last) for last in lasts]
    if top == 0:
        return [0 for _ in lasts]
    # round(position * last / top) in integers: halves round up.
    return [(2 * position * last + top) // (2 * top) for last in lasts]


# ---------------------------------------------------------------- presets
@dataclass(frozen=True)
class Preset:
    """A comparison worth showing: its panes and the primitives it brings.

    The panes run on the main window's primitives when its algorithm is
    one of ``follows`` (names or families), else on ``example``.
    """

    key: str
    title: str
    description: str
    panes: tuple
    example: object = None  # a Scene, or a callable making one
    follows: tuple = ()
    diff: tuple = (0, 1)  # the two panes the diff shows

    def primitives(self, window_primitives: Scene | None = None) -> Scene:
        if window_primitives is not None and self.uses_window(window_primitives):
            return window_primitives
        example = self.example
        return example() if callable(example) else example

    def uses_window(self, window_primitives: Scene) -> bool:
        spec = window_primitives.spec
        return spec.name in self.follows or spec.family in self.follows


def _mesh() -> Scene:
    """A 4 x 3 block of squares, each cut along a diagonal: every vertex
    on a pixel centre, so that many centres lie exactly on shared edges."""
    points = []
    xs, ys = [3.5 + 6 * i for i in range(5)], [2.5 + 6 * j for j in range(4)]
    for j in range(3):
        for i in range(4):
            a, b = (xs[i], ys[j]), (xs[i + 1], ys[j])
            c, d = (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])
            points += [a, b, c, a, c, d]
    return Scene(algorithm="triangle-bbox", points=points,
                 title="a mesh of 24 triangles, vertices on pixel centres")


def _painter_scene() -> Scene:
    return file_primitives(load(SHIPPED / "painter-cyclic.json"))


PRESETS = (
    Preset("dda-bresenham", "DDA vs Bresenham",
           "Slope 5/12 passes exactly half-way between two pixels twice (x = 10 and "
           "x = 22). Bresenham's d <= 0 goes east at both. The DDA adds m = 5/12 in "
           "float64, which is not exact: at x = 10 its y is a hair above 7.5 and rounds up, "
           "at x = 22 a hair below 12.5 and rounds down, so the two differ in one pixel.",
           (Pane.of("line-dda"), Pane.of("line-bresenham")),
           Scene(algorithm="line-bresenham", points=((4, 5), (28, 15)),
                 title="a segment of slope 5/12"),
           follows=("lines",)),
    Preset("two-triangles", "Two skinny triangles vs Bresenham",
           "The segment widened into a rectangle 1 px across and filled as two triangles, "
           "against Bresenham's one pixel per column: the rectangle takes every centre "
           "within 1/2 px of the line, so where the line passes half-way between two "
           "centres of a column (every other column at slope 1/2) it takes both.",
           (Pane.of("line-two-triangles"), Pane.of("line-bresenham")),
           Scene(algorithm="line-two-triangles", points=((2, 3), (28, 16)),
                 title="a segment of slope 1/2"),
           follows=("line-two-triangles",)),
    Preset("dda-precision", "DDA float32 vs float64 on a long line",
           "Adding a float32 slope 4095 times drifts: some pixels land one row off the "
           "float64 result.",
           (Pane.of("line-dda", dtype="float32"), Pane.of("line-dda", dtype="float64")),
           Scene(algorithm="line-dda", points=((0, 0), (4095, 192)), width=4096, height=200,
                 title="a long shallow segment")),
    Preset("circles", "Midpoint vs square-root circles",
           "The midpoint circle against y = sqrt(r^2 - x^2) with 8-way and 4-way symmetry "
           "(the 4-way one leaves gaps where the circle is steep).",
           (Pane.of("circle-midpoint"), Pane.of("circle-sqrt8"), Pane.of("circle-sqrt4")),
           Scene(algorithm="circle-midpoint", points=((16, 12),), options={"radius": 10},
                 title="a circle of radius 10"),
           follows=("circles",)),
    Preset("scanline-edge", "Scan-line fill vs edge-function fill",
           "The ET/AET scan line, one contour per triangle, against the bounding-box "
           "edge-function fill of the same triangles. Both follow the top-left rule, so they agree; "
           "set arithmetic=float32 or fill_rule=inclusive on a pane to see them part.",
           (Pane.of("polygon-scanline"), Pane.of("triangle-bbox")),
           Scene(algorithm="triangle-bbox", points=((3.5, 2.5), (27.5, 5.5), (12.5, 21.5),
                                                    (27.5, 5.5), (29.5, 19.5), (12.5, 21.5)),
                 title="two triangles sharing an edge"),
           follows=("polygons", "triangles")),
    Preset("fill-rule", "Top-left vs inclusive fill rule on a mesh",
           "With the top-left rule every pixel centre on a shared edge goes to exactly one "
           "triangle; the inclusive rule gives it to both (written twice).",
           (Pane.of("triangle-bbox", fill_rule="top-left"),
            Pane.of("triangle-bbox", fill_rule="inclusive")),
           _mesh, follows=("triangles",)),
    Preset("painter-zbuffer", "Painter's algorithm vs z-buffer",
           "Three triangles overlapping in a cycle: any back-to-front order gets one overlap "
           "wrong, the z-buffer decides per pixel.",
           (Pane.of("painter"), Pane.of("zbuffer")),
           _painter_scene, follows=("visibility",)),
    Preset("supersample", "Supersampling n = 1 vs 4 vs exact",
           "One sample per pixel, 4 x 4 samples, and the exact area each pixel covers.",
           (Pane.of("aa-supersample", n=1), Pane.of("aa-supersample", n=4), Pane.of(EXACT)),
           Scene(algorithm="aa-supersample", points=((3.3, 2.6), (28.7, 8.2), (11.4, 21.1)),
                 title="a triangle"),
           follows=("aa-supersample", "aa-adaptive"), diff=(1, 2)),
)


def preset(key: str) -> Preset:
    for item in PRESETS:
        if item.key == key:
            return item
    raise InputError(f"unknown comparison {key!r}; known: {', '.join(p.key for p in PRESETS)}")


def window_panes(player) -> tuple:
    """The main window's algorithm and the one shown before it (the one
    its own comparison outlines) when that is of the same family, else a
    neighbour in the same family: a triangle fill is never set against a
    seed fill, which cannot run on its input."""
    spec = player.spec
    options = _changed_options(spec, player.options)
    mine = Pane(spec.name, tuple(sorted(options.items())))
    if player.previous is not None and player.previous[0].family == spec.family:
        other, other_options = player.previous
        return (mine, Pane(other.name, tuple(sorted(_changed_options(other, other_options)
                                                    .items()))))
    family = [s.name for s in registry.all_specs() if s.family == spec.family]
    others = [name for name in family if name != spec.name]
    return (mine, Pane(others[0] if others else spec.name))
