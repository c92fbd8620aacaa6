"""The hard-case catalogue: every registered algorithm over hard inputs.

The shipped scenes (resources/scenes/*.json, read here as plain JSON) and
families of hard inputs chosen by what an algorithm takes (segments,
centres, polygons, outlines, triangles): zero-length and axis-aligned
segments, exact ties, huge and tiny coordinates, radius 0 and 1, degenerate
ellipses, collinear and repeated vertices, slivers and near-degenerate
triangles, vertices exactly on pixel centres and on scan lines, shared
edges, w near 0, every precision and fill rule.

tests/algorithms/test_stability.py runs every case through the checks each
algorithm's oracle declares; the families' reference tests take their
algorithm's cases (``cases_of``) and record them (``recorded``);
scripts/fingerprint.py takes a digest of every case.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from algorithms.core import registry
from algorithms.core.errors import InputError
from tests.support import ROOT, curve_oracles, record

GRID = (40, 32)


@dataclass(frozen=True)
class Case:
    name: str
    algorithm: str
    points: object
    options: dict = field(default_factory=dict)
    grid: tuple = GRID
    # True: must run; False: must be refused; None: either, as long as it is clean.
    valid: bool | None = True

    def __str__(self):
        return f"{self.algorithm}:{self.name}"


# ================================================================ catalogue
def scene_cases() -> list[Case]:
    """The shipped scenes, parsed from their JSON without the application."""
    cases = []
    for path in sorted((ROOT / "resources" / "scenes").glob("*.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        spec = registry.get(data["algorithm"])
        groups = [[tuple(p) for p in primitive["points"]] for primitive in data["primitives"]]
        points = groups if spec.inputs.contours else [p for group in groups for p in group]
        grid = (data["grid"]["width"], data["grid"]["height"])
        cases.append(Case(f"scene {path.stem}", spec.name, points, data.get("options", {}), grid))
    return cases


SEGMENTS = {
    "point": ((5, 5), (5, 5)),
    "point at origin": ((0, 0), (0, 0)),
    "point negative": ((-3, -7), (-3, -7)),
    "horizontal": ((2, 3), (30, 3)),
    "horizontal back": ((30, 3), (2, 3)),
    "vertical": ((4, 1), (4, 25)),
    "vertical back": ((4, 25), (4, 1)),
    "diagonal": ((1, 1), (25, 25)),
    "antidiagonal": ((25, 1), (1, 25)),
    "ties slope 1/2": ((0, 0), (28, 14)),
    "ties slope -1/2 back": ((28, 0), (0, 14)),
    "ties steep": ((3, 0), (9, 24)),
    "one step": ((7, 7), (8, 8)),
    "knight": ((7, 7), (9, 8)),
    "negative quadrant": ((-20, -5), (-2, -17)),
    "long shallow": ((0, 0), (4000, 3)),
    "huge coordinates": ((1_000_000_000, -1_000_000_000), (1_000_000_021, -999_999_993)),
    "beyond 32 bits": ((2 ** 40, 0), (2 ** 40 + 10, 3)),
}
LINE_OPTIONS = {
    "line-bresenham": [{}, {"symmetric": True}],
    "line-dda": [{}, {"dtype": "float32"}],
    "line-incremental": [{}, {"rounding": "round"}],
    "line-parametric": [{}, {"dt": "auto"}, {"dt": 0.5}, {"dt": 1.0}],
    "line-wu": [{}],
    "line-area": [{}],
    "line-dda-printed": [{}, {"variant": "x-only"}, {"variant": "add-first"},
                         {"variant": "x-truncate"}],
    "line-parametric-printed": [{}, {"dt": 0.1}],
    "line-bresenham-textbook": [{}, {"variant": "sign-reversed"}, {"variant": "as-printed"}],
}


# Real end points for the grid traversals: through corners, along grid
# lines, within one cell, and float fractions with long expansions.
REAL_SEGMENTS = {
    "through corners": ((1.0, 1.0), (9.0, 9.0)),
    "along a grid line": ((2.0, 5.0), (14.0, 5.0)),
    "along a column line": ((7.0, 1.5), (7.0, 12.25)),
    "inside one cell": ((3.2, 3.3), (3.7, 3.9)),
    "point at a fraction": ((4.125, 4.875), (4.125, 4.875)),
    "tenths": ((0.1, 0.7), (19.3, 13.9)),
    "steep back": ((12.75, 20.5), (11.25, 0.5)),
}


def random_segments(count=12, seed=7):
    rng = np.random.default_rng(seed)
    return {f"random {k}": tuple((int(rng.integers(-40, 40)), int(rng.integers(-40, 40)))
                                 for _ in range(2)) for k in range(count)}


def line_cases(spec) -> list[Case]:
    cases = []
    for options in LINE_OPTIONS.get(spec.name, [{}]):
        label = ",".join(f"{k}={v}" for k, v in options.items())
        real = {} if spec.inputs.integer else REAL_SEGMENTS
        for name, segment in {**SEGMENTS, **random_segments(), **real}.items():
            valid = None if name in ("huge coordinates", "beyond 32 bits") else True
            if spec.name == "line-implicit" and name == "long shallow":
                valid = True  # 4001 x 4 box: small enough
            cases.append(Case(f"{name} {label}".strip(), spec.name, segment, options, GRID, valid))
    return cases


def circle_cases(spec) -> list[Case]:
    centres = {"centre": (12, 10), "centre at origin": (0, 0), "negative centre": (-30, -4),
               "far centre": (1_000_000, -1_000_000)}
    cases = []
    if spec.name == "ellipse-midpoint":
        sizes = [(0, 0), (0, 5), (5, 0), (1, 1), (1, 7), (7, 1), (30, 2), (2, 30), (9, 9),
                 (100, 99), (1, 0), (0, 1)]
        for centre_name, centre in centres.items():
            for rx, ry in sizes:
                cases.append(Case(f"{centre_name} rx={rx} ry={ry}", spec.name, (centre,),
                                  {"rx": rx, "ry": ry}))
        return cases
    starts = [{}, {"start": "fraction"}] if spec.name == "circle-midpoint" else [{}]
    for centre_name, centre in centres.items():
        for r in (0, 1, 2, 3, 5, 7, 50, 4096):
            for extra in starts:
                cases.append(Case(f"{centre_name} r={r} {extra}", spec.name, (centre,),
                                  {"radius": r, **extra}))
    return cases


def circle_fill_cases(spec) -> list[Case]:
    """The circle cases, then other fill options and seeds on a radius-5 circle
    around (12, 10), whose ring passes through (12, 15)."""
    cases = circle_cases(spec)
    for options in FILL_OPTIONS:
        if options["outline"] == "8":
            label = ",".join(f"{k}={v}" for k, v in options.items())
            cases.append(Case(f"r=5 {label}", spec.name, ((12, 10),), {"radius": 5, **options}))
    ring = {"radius": 5, "seed": (12, 15)}
    cases += [
        Case("seed outside the circle", spec.name, ((12, 10),), {"radius": 5, "seed": (0, 0)}),
        Case("region fill of the ring", spec.name, ((12, 10),), {**ring, "mode": "region"}),
        Case("region fill of the ring, 4-connected", spec.name, ((12, 10),),
             {**ring, "mode": "region", "connectivity": "4"}),
        Case("seed on the ring", spec.name, ((12, 10),), ring, GRID, False),
        Case("seed off the grid", spec.name, ((12, 10),), {"radius": 5, "seed": (99, 5)},
             GRID, False),
    ]
    return cases


POLYGONS = {
    "triangle": [[(2.0, 2.0), (30.0, 5.0), (12.0, 25.0)]],
    "square on centres": [[(2.5, 2.5), (20.5, 2.5), (20.5, 20.5), (2.5, 20.5)]],
    "square on corners": [[(2.0, 2.0), (20.0, 2.0), (20.0, 20.0), (2.0, 20.0)]],
    "vertices on scan lines": [[(3.25, 4.5), (25.75, 9.5), (14.0, 22.5)]],
    "collinear": [[(1.0, 1.0), (10.0, 10.0), (20.0, 20.0)]],
    "all one point": [[(5.0, 5.0), (5.0, 5.0), (5.0, 5.0)]],
    "repeated vertices": [[(2.0, 2.0), (2.0, 2.0), (25.0, 4.0), (25.0, 4.0), (10.0, 20.0),
                           (2.0, 2.0)]],
    "sliver": [[(1.0, 1.0), (38.0, 30.0), (38.01, 30.004)]],
    "thin horizontal": [[(1.0, 10.4), (35.0, 10.45), (35.0, 10.6)]],
    "tiny": [[(1e-12, 1e-12), (3e-12, 1e-12), (1e-12, 4e-12)]],
    "tiny far from 0": [[(10.1, 10.1), (10.1 + 1e-9, 10.1), (10.1, 10.1 + 1e-9)]],
    "bowtie": [[(2.0, 2.0), (30.0, 25.0), (30.0, 2.0), (2.0, 25.0)]],
    "with hole": [[(1.0, 1.0), (35.0, 1.0), (35.0, 28.0), (1.0, 28.0)],
                  [(10.0, 10.0), (10.0, 20.0), (25.0, 20.0), (25.0, 10.0)]],
    "concave": [[(2.0, 2.0), (30.0, 2.0), (16.0, 10.0), (30.0, 25.0), (2.0, 25.0)]],
    "large coordinates": [[(1_000_000.25, 1_000_000.5), (1_000_030.0, 1_000_004.0),
                           (1_000_012.0, 1_000_025.5)]],
    "beyond the limit": [[(5e6, 5e6), (5e6 + 20, 5e6), (5e6, 5e6 + 20)]],
    "huge": [[(1e300, 0.0), (0.0, 1e300), (-1e300, 0.0)]],
}
POLYGON_OPTIONS = {
    "polygon-scanline": [{}, {"fill_rule": "nonzero"}, {"arithmetic": "float64"},
                         {"arithmetic": "float32"}],
    "polygon-tessellate": [{}, {"ties": "inclusive"}, {"ties": "strict"}],
    "polygon-brute-scanline": [{}, {"fill_rule": "nonzero"}],
    "polygon-scanline-integer": [{}, {"fill_rule": "nonzero"}],
    "polygon-tessellate-any": [{}, {"fill_rule": "nonzero"}],
    "polygon-scanline-xlow": [{}, {"fill_rule": "nonzero"}, {"arithmetic": "float64"}],
}


# The scan lines fill any contours by the fill rule: self-intersecting, with holes.
SCANLINES = ("polygon-scanline", "polygon-brute-scanline", "polygon-scanline-xlow",
             "polygon-scanline-integer", "polygon-tessellate-any")


def polygon_cases(spec) -> list[Case]:
    cases = []
    for options in POLYGON_OPTIONS.get(spec.name, [{}]):
        label = ",".join(f"{k}={v}" for k, v in options.items())
        for name, contours in POLYGONS.items():
            valid = True
            if spec.name == "stencil-triangle":
                # the last contour is the triangle; alone, it has the
                # triangles' limits (1e15 px), not the polygons'
                valid = len(contours[-1]) == 3 and name != "huge"
            elif name in ("beyond the limit", "huge"):
                valid = False
            elif spec.name not in SCANLINES and name in ("bowtie", "with hole"):
                valid = False
            elif spec.name == "polygon-convex" and name == "concave":
                valid = False
            elif spec.name == "polygon-tessellate" and name == "collinear":
                valid = None  # three points along a line fold back on themselves
            cases.append(Case(f"{name} {label}".strip(), spec.name, contours, options, GRID, valid))
    return cases


OUTLINES = {
    "square": [[(2, 2), (20, 2), (20, 20), (2, 20)]],
    "triangle": [[(1, 1), (30, 4), (10, 25)]],
    "repeated vertices": [[(2, 2), (2, 2), (25, 3), (25, 3), (12, 22)]],
    "off the grid": [[(-10, -10), (60, 5), (20, 50)]],
    "two outlines": [[(1, 1), (15, 1), (15, 15), (1, 15)], [(20, 5), (35, 5), (28, 25)]],
}
FILL_OPTIONS = [{"order": order, "connectivity": c, "outline": outline}
                for order in ("stack", "queue", "span") for c in ("4", "8")
                for outline in ("8", "4")]


def fill_cases(spec) -> list[Case]:
    cases = []
    for options in FILL_OPTIONS:
        label = ",".join(f"{k}={v}" for k, v in options.items())
        for name, contours in OUTLINES.items():
            cases.append(Case(f"{name} {label}", spec.name, contours, options))
        cases.append(Case(f"explicit seed {label}", spec.name, OUTLINES["square"],
                          {**options, "seed": (5, 5)}))
    cases += [
        Case("seed on the boundary", spec.name, OUTLINES["square"], {"seed": (2, 2)}, GRID, False),
        Case("seed off the grid", spec.name, OUTLINES["square"], {"seed": (100, 5)}, GRID, False),
        Case("collinear outline", spec.name, [[(1, 1), (10, 10), (20, 20)]], {}, GRID, False),
        Case("seed outside the outline", spec.name, OUTLINES["square"], {"seed": (30, 30)}),
    ]
    return cases


def _tri(*coords):
    return [(float(coords[k]), float(coords[k + 1])) for k in range(0, len(coords), 2)]


TRIANGLES = {
    "plain": _tri(2, 2, 30, 6, 12, 28),
    "clockwise": _tri(2, 2, 12, 28, 30, 6),
    "on pixel centres": _tri(2.5, 2.5, 30.5, 2.5, 2.5, 25.5),
    "on scan lines": _tri(1.25, 3.5, 33.75, 10.5, 8.0, 27.5),
    "collinear": _tri(1, 1, 10, 10, 20, 20),
    "repeated vertex": _tri(4, 4, 4, 4, 20, 9),
    "all one point": _tri(7, 7, 7, 7, 7, 7),
    "near-degenerate": _tri(1, 1, 37, 29, 37.001, 29.0005),
    "sliver": _tri(1, 1, 38, 30, 38.6, 29.2),
    "tiny": _tri(1e-12, 1e-12, 3e-12, 1e-12, 1e-12, 4e-12),
    "smaller than a snap step": _tri(10.5, 10.5, 10.501, 10.5, 10.5, 10.501),
    "mesh, shared edges": _tri(2, 2, 20, 3, 10, 20, 20, 3, 30, 22, 10, 20, 10, 20, 30, 22, 5, 30),
    "fan on a pixel centre": _tri(15.5, 12.5, 30, 12.5, 15.5, 28, 15.5, 12.5, 15.5, 28, 2, 12.5,
                                  15.5, 12.5, 2, 12.5, 15.5, 1, 15.5, 12.5, 15.5, 1, 30, 12.5),
    "outside the grid": _tri(-50, -50, -20, -45, -40, -10),
    "straddling the grid": _tri(-20, -5, 60, 10, 15, 45),
    "large coordinates": _tri(1e6, 1e6, 1e6 + 30, 1e6 + 4, 1e6 + 9, 1e6 + 25),
    "huge coordinates": _tri(1e14, 1e14, -1e14, 1e14, 0, -1e14),
    "beyond the limit": _tri(1e300, 0, 0, 1e300, -1e300, 0),
}
TRIANGLE_OPTIONS = [{}, {"fill_rule": "inclusive"}, {"fill_rule": "strict"},
                    {"precision": "float64"}, {"precision": "float32"},
                    {"subpixel_bits": 0}, {"subpixel_bits": 4}, {"cull": True},
                    {"colors": ("#ff0000", "#00ff00", "#0000ff"), "z": (0.1, 0.5, 0.9),
                     "s": (0.0, 1.0, 0.5), "w": (1.0, 1e-300, 2.0), "perspective": True},
                    {"s": (0.0, 1.0, 0.5), "w": (1e-300, 1e300, 1.0)}]
SPECIAL_TRIANGLE_OPTIONS = {
    "triangle-cramer": [{}], "triangle-trilinear": [{}], "triangle-wireframe": [{}],
    "triangle-columns": [{}, {"swap": "printed"}], "triangle-span-interpolate": [{}],
    "triangle-barycentric-printed": [{}, {"distance": "signed"}],
    "triangle-lininterp": [{}, {"listing": "corrected"}],
    "painter-split": [{}],
    "triangle-plane": [{}, {"colors": ("#ff0000", "#00ff00", "#0000ff"), "z": (0.0, 1e300, -1e300)},
                       {"precision": "float32", "s": (0.0, 1.0, 0.5)}, {"subpixel_bits": 0}],
    "triangle-perspective": [{}, {"w": (1.0, 1e-300, 1.0)}, {"w": (1e-300, 1e300, 1.0)},
                             {"w": (1e-6, 1.0, 1e6), "colors": ("#ff0000", "#00ff00", "#0000ff"),
                              "perspective": False}, {"precision": "float32"},
                             {"w": (5e-324, 1.0, 1.0)}, {"w": (0.0, 1.0, 1.0)}],
    "zbuffer": [{}, {"z": (0.2, 0.5, 0.9)}, {"z": (1e300, -1e300, 0.0)},
                {"depth_test": "less-equal", "clear_depth": -1e300}],
    "painter": [{}, {"z": (0.2, 0.5, 0.9)}, {"sort": "min"}, {"sort": "max"}],
    "aa-supersample": [{}, {"n": 1}, {"n": 8, "pattern": "jitter"},
                       {"pattern": "rotated-grid", "filter": "gaussian"}],
    "aa-adaptive": [{}, {"max_depth": 1}],
    "pipeline": [{}, {"shading": "phong", "clipping": "near"}, {"shading": "flat", "z": (0, 0, 60)}],
    "blend-over": [{}, {"alpha": (1.0, 0.5, 0.0), "depth_write": "all"},
                   {"order": "back-to-front", "z": (0.1, 0.5, 0.9)}],
    "triangle-texture": [{}, {"precision": "float32"}, {"w": (1.0, 1e-300, 2.0)},
                         {"w": (1e-300, 1e300, 1.0), "filter": "anisotropic"},
                         {"w": (1e-6, 1.0, 1e6), "filter": "trilinear", "wrap": "clamp"}],
}


def triangle_cases(spec) -> list[Case]:
    options_list = SPECIAL_TRIANGLE_OPTIONS.get(spec.name, TRIANGLE_OPTIONS)
    cases = []
    for options in options_list:
        label = ",".join(f"{k}={v}" for k, v in options.items())
        for name, points in TRIANGLES.items():
            usable = dict(options)
            if spec.name in ("zbuffer", "painter", "painter-split") and "z" not in usable:
                usable["z"] = tuple(0.1 + 0.8 * (k % 3) / 2 for k in range(len(points)))
            valid = None
            if name == "beyond the limit":
                valid = False
            elif name in ("plain", "clockwise", "on pixel centres", "mesh, shared edges"):
                valid = None if spec.family in ("visibility", "antialias") else True
            if any(w in (0.0, 5e-324) for w in usable.get("w", ())):
                valid = False
            cases.append(Case(f"{name} {label}".strip(), spec.name, points, usable, GRID, valid))
    return cases


def cases_for(spec) -> list[Case]:
    inputs = spec.inputs
    if spec.oracle.check in curve_oracles.CHECKS:  # the curve oracles bring their own cases
        return curve_oracles.cases(spec, lambda name, points, options, valid: Case(
            name, spec.name, points, options, GRID, valid))
    if inputs.contours:
        return fill_cases(spec) if spec.family == "fill" else polygon_cases(spec)
    if inputs.count == 2 and (inputs.integer or spec.family == "lines"):
        return line_cases(spec)
    if inputs.count == 1 and inputs.integer and spec.family == "fill":
        return circle_fill_cases(spec)
    if inputs.count == 1 and inputs.integer:
        return circle_cases(spec)
    if inputs.multiple:
        return triangle_cases(spec)
    return [Case("defaults", spec.name, (), {}, GRID, None)]


def catalogue() -> list[Case]:
    cases = scene_cases()
    for spec in registry.all_specs():
        if spec.name == "aa-temporal":
            # Its inputs are a wheel's centre or a triangle, not shapes to fill.
            cases += [Case("wheel", spec.name, [(20.0, 16.0)], {"frames": 4}),
                      Case("triangle", spec.name, TRIANGLES["plain"], {"frames": 3}),
                      Case("tiny triangle", spec.name, TRIANGLES["tiny"], {"frames": 3}, GRID, None),
                      Case("degenerate", spec.name, TRIANGLES["collinear"], {"frames": 3}, GRID,
                           None)]
            continue
        cases += cases_for(spec)
    return cases


CASES = catalogue()


def cases_of(name: str) -> list[Case]:
    """The catalogue's cases of one algorithm."""
    return [case for case in CASES if case.algorithm == name]


def recorded(case: Case):
    """The case's trace, or None when it is refused (test_stability checks
    refusals); a case that must run and is refused fails."""
    try:
        return record(case.algorithm, case.points, case.options, case.grid)
    except InputError:
        assert case.valid is not True, f"{case}: refused"
        return None
