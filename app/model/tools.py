"""How the window draws each algorithm's input, decided from its spec.

The drawing tool follows the inputs and the family, never the algorithm's
name: contours are drawn as polygons, k-times-3 points as triangles, the
one centre of a circle family algorithm with its radius options dragged
out; an option of kind "point" (a fill's seed) gets a marker on the grid.
Nothing here imports Qt.
"""
from __future__ import annotations

from app.model.drawing import CIRCLE, CONTOURS, FIXED, GROUPS, Tool
from app.model.geometry import ideal_paths, scene_paths, takes_circle
from app.model.inputs import contour_sizes, group_size, runnable_input


def drawing_mode(spec) -> str:
    inputs = spec.inputs
    if inputs.contours:
        return CONTOURS
    if inputs.multiple:
        return GROUPS
    if takes_circle(spec):
        return CIRCLE
    return FIXED


def drawing_tool(spec, options=None) -> Tool:
    """The drawing tool that places this algorithm's points (in groups as
    the run's ``options`` name them)."""
    return Tool(drawing_mode(spec), group_size(spec, options))


def circle_options(spec) -> tuple[str, ...]:
    """The options a radius drag sets: ("radius",), ("rx", "ry") or ()."""
    names = {option.name for option in spec.options if option.kind in ("int", "float")}
    if drawing_mode(spec) != CIRCLE:
        return ()
    if "radius" in names:
        return ("radius",)
    if {"rx", "ry"} <= names:
        return ("rx", "ry")
    return ()


def circle_kind(spec) -> str | None:
    """What the grid's rim handle stands for: "radius", "radii" or None."""
    return {1: "radius", 2: "radii"}.get(len(circle_options(spec)))


# Point options that are no place on the grid: a triangle run's offset moves
# the whole scene far from the origin, so it is typed, never clicked.
NOT_MARKERS = ("offset",)


def marker_option(spec):
    """The option placed by clicking a pixel (a fill's seed), or None."""
    return next((option for option in spec.options
                 if option.kind == "point" and option.name not in NOT_MARKERS), None)


def clamp_option(option, value: float):
    """A dragged value rounded and kept inside the option's range."""
    if option.kind == "int":
        value = round(value)
    if option.minimum is not None:
        value = max(value, option.minimum)
    if option.maximum is not None:
        value = min(value, option.maximum)
    return int(value) if option.kind == "int" else float(value)


def tool_hint(spec) -> str:
    """How to draw this algorithm's input, in a sentence or three."""
    mode = drawing_mode(spec)
    fine = "" if spec.inputs.integer else (" Points snap to 1/8 px; hold Ctrl to place them "
                                           "to 1/256 px.")
    if mode == CIRCLE:
        radii = circle_options(spec)
        text = ("Click to place the centre, or drag from an empty cell: the press is the "
                "centre, the drag the radius. Drag the square handle to change the radius.")
        if len(radii) == 2:
            text += " The drag sets rx and ry; hold Shift to keep them equal."
        return text
    if mode == CONTOURS:
        text = ("Click to add vertices; double-click, Enter or a click on the first vertex "
                "closes the polygon. Shift+click starts a new contour (a hole or a second "
                "part). Backspace removes the last vertex." + fine)
        marker = marker_option(spec)
        if marker is not None:
            text += (f" Place the {marker.name} with the {marker.name.capitalize()} tool (S), "
                     "the right-click menu, or by dragging its star.")
        return text
    if mode == GROUPS:
        return ("Click three points per triangle; further clicks add further triangles. "
                "A click on a vertex adds a point exactly there, to share it. "
                "Backspace removes the last point." + fine)
    return "Click the grid to place points; drag a handle to move one."


def placing_message(spec, points, breaks=(), options=None) -> str:
    """What to do next while the input is not complete, or ""."""
    inputs = spec.inputs
    size = group_size(spec, options)
    mode = drawing_mode(spec)
    n = len(points)
    if mode == CONTOURS:
        last = contour_sizes(n, breaks)[-1] if n else 0
        if n and last >= inputs.count:
            return ""
        missing = inputs.count - last
        return (f"Click on the grid to place vertices: {missing} more for "
                f"{'a polygon' if not breaks else 'this contour'}.")
    if mode == GROUPS:
        missing = (size - n % size) % size
        if not missing:
            return ""
        which = n // size + 1
        return (f"Click on the grid to place {missing} more point{'s' if missing > 1 else ''} "
                f"for {'segment' if size == 2 else 'triangle'} {which}.")
    if n >= inputs.count:
        return ""
    names = inputs.names
    following = names[n] if n < len(names) else "the next point"
    missing = inputs.count - n
    return (f"Click on the grid to place {following}"
            + (f" ({missing} more points to go)." if missing > 1 else "."))


def shape_paths(spec, points, options, breaks=()) -> list:
    """The ideal primitive of what is complete, as [(points, closed), ...]:
    each contour with enough vertices, each whole triangle. What is still
    being drawn is left to the grid's dashed preview."""
    inputs = spec.inputs
    if inputs.contours:
        return scene_paths(spec, runnable_input(spec, points, breaks), options)
    return ideal_paths(spec, runnable_input(spec, points, (), options), options)
