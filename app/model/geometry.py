"""The ideal primitive of a scene as geometry: its outline paths in grid
units and, for antialiasing, its exact coverage of every pixel.

Both the model (compare, the inspector, the drawing tools) and rendering
(the window's overlays, exported frames) need them; they live here, below
rendering, so that rendering depends on the model and never the reverse.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.steps import Vars


# ------------------------------------------------------------ ideal primitive
def takes_circle(spec) -> bool:
    """One centre and a radius (or radii): a circle, an ellipse, a seed fill
    inside a circle."""
    names = {option.name for option in spec.options}
    inputs = spec.inputs
    return (inputs.count == 1 and not inputs.contours and not inputs.multiple
            and bool(names & {"radius", "rx"}))


def ideal_paths(spec, points, options) -> list:
    """The ideal primitive as [(points, closed), ...] in grid units.

    A whole-pixel point (i, j) stands for its pixel's centre (i + 1/2,
    j + 1/2). Lines: the segment between the end pixels' centres (and the
    two triangles of a line drawn as triangles). Circles
    and ellipses: the exact curve of the radius options around the centre.
    Triangles given in threes: each triangle. Polygons and outlines: the
    closed polygon through the points. An antialiasing run's ``shape``
    option says how its points group: in threes, one polygon, or a segment.
    """
    inputs = spec.inputs
    if spec.name == "pipeline":
        return []  # its points are in the world; the window draws their projection
    if inputs.integer:
        centres = [(x + 0.5, y + 0.5) for x, y in points]
    else:
        centres = [(float(x), float(y)) for x, y in points]
    if not centres:
        return []
    if spec.name == "line-two-triangles" and len(centres) == 2:
        return [(centres, False)] + _two_triangles(points, spec, options)
    if takes_circle(spec):
        rx = options.get("rx", options.get("radius"))
        ry = options.get("ry", options.get("radius"))
        if len(centres) != 1 or not all(isinstance(r, (int, float)) and not isinstance(r, bool)
                                        for r in (rx, ry)):
            return []
        (cx, cy), angles = centres[0], np.linspace(0, 2 * np.pi, 241)
        return [(list(zip(cx + rx * np.cos(angles), cy + ry * np.sin(angles))), False)]
    shape = options.get("shape")
    if shape == "triangles":
        return [(centres[k:k + 3], True) for k in range(0, len(centres) - 2, 3)]
    if shape in ("polygon", "thick-line"):
        return [(centres, shape == "polygon")]
    if getattr(inputs, "multiple", False):
        count = inputs.count
        return [(centres[k:k + count], True) for k in range(0, len(centres) - count + 1, count)]
    if inputs.count == 4 and "segments" in options and len(centres) == 4:
        return [(bezier_samples(centres), False)]  # a cubic Bezier's control points
    closed = getattr(inputs, "contours", False) or inputs.count >= 3
    return [(centres, closed and len(centres) >= 3)]


def run_paths(spec, points, options, trace) -> list:
    """The primitive's outline for a recorded run, as the window and exported
    frames both draw it: the pipeline's is its clipped triangles on the screen
    (its points are in the world), every other algorithm's its ideal primitive."""
    if spec.name == "pipeline":
        return projected_paths(trace) if trace is not None else []
    return scene_paths(spec, points, options)


def projected_paths(trace) -> list:
    """The clipped triangles' outlines in window coordinates, [(corners, closed), ...]: the
    pipeline's primitive as the screen sees it, from its viewport steps."""
    paths = []
    for _, record in trace.records_of(Vars):
        if "x_win0" not in record.values:  # not a viewport step
            continue
        values = record.values
        corners = [(values[f"x_win{k}"], values[f"y_win{k}"]) for k in range(len(values))
                   if f"x_win{k}" in values]
        if len(corners) >= 3:
            paths.append(([tuple(float(v) for v in c) for c in corners], True))
    return paths


def _two_triangles(points, spec, options) -> list:
    """The rectangle's two triangles a line-two-triangles run fills."""
    from algorithms.core.registry import InputError
    from algorithms.triangles.line_triangles import triangles
    try:
        return [(list(t), True) for t in triangles(points, spec.resolve(options))]
    except InputError:
        return []


def bezier_samples(points, count: int = 121) -> list:
    """Points along the cubic Bezier curve of four control points."""
    t = np.linspace(0.0, 1.0, count)[:, None]
    p = np.asarray(points, dtype=float)
    curve = ((1 - t) ** 3 * p[0] + 3 * (1 - t) ** 2 * t * p[1] + 3 * (1 - t) * t * t * p[2]
             + t ** 3 * p[3])
    return [tuple(row) for row in curve.tolist()]


def scene_paths(spec, points, options) -> list:
    """``ideal_paths`` for points as a scene file holds them: a polygon's
    points are a list of contours there, each its own closed path."""
    if getattr(spec.inputs, "contours", False) and points and isinstance(points[0][0],
                                                                         (list, tuple)):
        return [path for contour in points for path in ideal_paths(spec, contour, options)]
    return ideal_paths(spec, points, options)


# ------------------------------------------------------------ exact coverage
def exact_reference(spec, points, options, grid) -> np.ndarray | None:
    """(H, W) exact coverage of the primitive an antialiasing run draws, or
    None where there is no single one (not antialiasing; a moving shape).
    ``grid`` is (W, H), or a window (x0, y0, x1, y1) of the grid's cells."""
    if spec is None or spec.family != "antialias" or not points:
        return None
    from algorithms import antialias
    from algorithms.exact import coverage as exact_coverage
    window = tuple(int(v) for v in grid)
    if spec.name in ("line-wu", "line-area"):
        if len(points) != 2:
            return None
        (px, py), (qx, qy) = points
        return exact_coverage.segment_coverage(
            (px + 0.5, py + 0.5), (qx + 0.5, qy + 0.5), float(options.get("width", 1.0)),
            window, options.get("caps", "butt"))
    if spec.name == "aa-temporal":
        return None
    try:
        return antialias.reference_coverage(points, options, window)
    except (ValueError, ArithmeticError):
        return None


def final_coverage(width: int, height: int, pixels, values) -> np.ndarray:
    """(H, W) coverage a run ends with: the value written last to each
    pixel (``pixels`` (n, 2) cells x, y in emission order), 0 elsewhere."""
    result = np.zeros((int(height), int(width)))
    pixels = np.asarray(pixels, dtype=np.int64).reshape(-1, 2)
    values = np.asarray(values, dtype=np.float64).ravel()
    if not len(pixels):
        return result
    x, y = pixels[:, 0], pixels[:, 1]
    keep = (x >= 0) & (x < width) & (y >= 0) & (y < height) & np.isfinite(values)
    flat = (y * width + x)[keep][::-1]
    flat, first = np.unique(flat, return_index=True)  # first of the reversed: the last write
    result.ravel()[flat] = values[keep][::-1][first]
    return result


def differences(before, after) -> np.ndarray:
    """(n, 2) array of cells (x, y) where two final rasters differ.

    A cell differs when one run wrote it and the other did not, or when
    both wrote a value (a colour) and the values differ.
    """
    if before is None or after is None or before.counts.shape != after.counts.shape:
        return np.zeros((0, 2), dtype=np.int64)
    differ = before.written() != after.written()
    if before.colors is not None and after.colors is not None:
        both = before.written() & after.written()
        differ |= both & (before.colors != after.colors)
    ys, xs = np.nonzero(differ)
    return np.stack([xs, ys], axis=1).astype(np.int64)
