"""The points an algorithm takes, kept flat with contour breaks: whether
they are complete, what of them can run, contours cut and joined. Nothing
here imports Qt, so the session, the scene and the compare logic share it."""
from __future__ import annotations


# The antialiasing family takes any number of points and reads them in the
# groups its "shape" option names: 3 per triangle, 2 per thick segment.
SHAPE_GROUPS = {"triangles": 3, "thick-line": 2}


def group_size(spec, options=None) -> int:
    """How many points make one primitive: the spec's count, or for a run
    whose ``shape`` option groups its points, that group's size."""
    inputs = spec.inputs
    if inputs.multiple and options:
        return SHAPE_GROUPS.get(options.get("shape"), inputs.count)
    return inputs.count


def complete(spec, points, breaks=(), options=None) -> bool:
    """Is there enough to run: at least one whole contour, one whole
    triangle, or exactly the points a fixed-count algorithm takes?"""
    inputs = spec.inputs
    if inputs.contours:
        return any(size >= inputs.count for size in contour_sizes(len(points), breaks))
    if inputs.multiple:
        return len(points) >= group_size(spec, options)
    return len(points) == inputs.count


def runnable_input(spec, points, breaks=(), options=None):
    """The points in the shape the algorithm takes, leaving out what is
    still being drawn: contours with too few vertices, a last incomplete
    triangle."""
    inputs = spec.inputs
    points = list(points)
    if inputs.contours:
        contours = split_contours(points, breaks)
        return [contour for contour in contours if len(contour) >= inputs.count]
    if inputs.multiple:
        size = group_size(spec, options)
        return points[:len(points) - len(points) % size]
    return points


def split_contours(points, breaks) -> list[list]:
    """The flat points cut at the break indices."""
    edges = [0, *breaks, len(points)]
    return [list(points[a:b]) for a, b in zip(edges, edges[1:])]


def contour_sizes(count: int, breaks) -> list[int]:
    edges = [0, *breaks, count]
    return [b - a for a, b in zip(edges, edges[1:])]


def clean_breaks(spec, count: int, breaks) -> tuple[int, ...]:
    """Breaks sorted, inside 1 .. count - 1; none unless the algorithm takes contours."""
    if not spec.inputs.contours:
        return ()
    return tuple(sorted({int(b) for b in breaks if 0 < int(b) < count}))


def flatten(spec, points) -> tuple[list[tuple], tuple[int, ...]]:
    """Points given flat or as contours (as scene files hold them) as one
    flat list and its breaks."""
    points = list(points)
    if spec.inputs.contours and points and _is_contour(points[0]):
        flat, breaks = [], []
        for contour in points:
            if flat:
                breaks.append(len(flat))
            flat += [tuple(p) for p in contour]
        return flat, tuple(breaks)
    return [tuple(p) for p in points], ()


def _is_contour(item) -> bool:
    return isinstance(item, (list, tuple)) and bool(item) and isinstance(item[0], (list, tuple))


def open_ended(spec) -> bool:
    """Does the algorithm take any number of points (a polygon's contour,
    k triangles) rather than exactly ``inputs.count``?"""
    inputs = spec.inputs
    return bool(getattr(inputs, "contours", False) or getattr(inputs, "multiple", False))


def clamp(point, width: int, height: int, integer: bool):
    """The point moved onto the grid: into its last pixel (whole-pixel
    inputs) or onto its edge (real ones)."""
    x, y = point
    if integer:
        return (min(max(int(x), 0), width - 1), min(max(int(y), 0), height - 1))
    return (min(max(float(x), 0.0), float(width)), min(max(float(y), 0.0), float(height)))
