"""The picture of the pipeline's stage at a step, for the view beside the grid: the world from
above (model), eye space from above (view), clip space's x against w with the planes x = +-w
(projection, clip), NDC's square (divide) and the window (viewport, rasterization). Each
shows every triangle, the one at the step drawn apart; line segments, as outside_view's."""
from __future__ import annotations

import math

import numpy as np

from algorithms.core.steps import Vars
from algorithms.pipeline.space import PLANES, Camera, distance
from algorithms.pipeline.stages import pipeline_code

from .outside_view import OutsideView, outside_view

STAGES = ("model", "view", "projection", "clip", "divide", "viewport", "fan")


def _ring(corners) -> list:
    return [(a, b) for a, b in zip(corners, corners[1:] + corners[:1])]


class StagePictures:
    """The stage pictures of one pipeline run, each made once per stage and triangle."""

    def __init__(self, trace, points, options, grid):
        self._args = (trace, points, options, grid)
        at = pipeline_code(options).at
        lines = np.array([at[key] for key in STAGES])
        self._steps = np.nonzero(np.isin(trace.line, lines))[0]
        self._keys = [STAGES[int(np.nonzero(lines == trace.line[i])[0][0])]
                      for i in self._steps]
        self._made = {}

    def stage_at(self, index: int) -> str:
        """The stage step ``index`` is in: the latest stage line at or before it ("fan":
        rasterizing); "model" before the first."""
        k = int(np.searchsorted(self._steps, index, side="right")) - 1
        return self._keys[k] if k >= 0 else "model"

    def at(self, index: int) -> OutsideView | None:
        trace = self._args[0]
        stage = self.stage_at(index)
        key = (stage, trace.variables_at(index).get("triangle", 1))
        if key not in self._made:
            self._made[key] = stage_view(*self._args, index, stage)
        return self._made[key]


def _vertices(points, options, grid):
    camera = Camera(options["eye"], options["target"], options["fov"], options["near"],
                    options["far"], grid[0] / grid[1])
    z = list(options.get("z") or ())
    world = [[float(x), float(y), float(z[k % len(z)]) if z else 0.0]
             for k, (x, y) in enumerate(points)]
    eyes = [camera.to_eye(p) for p in world]
    return camera, world, eyes, [camera.to_clip(e) for e in eyes]


def _polygons(trace, index, prefix) -> list:
    """The clipped polygons of the triangles done by the step, from the divide or viewport
    steps' variables: [(x, y) corners] per triangle."""
    found = []
    for step, record in trace.records_of(Vars, hi=index + 1):
        values = record.values
        if f"{prefix[0]}0" in values:
            found.append([(values[f"{prefix[0]}{k}"], values[f"{prefix[1]}{k}"])
                          for k in range(len(values)) if f"{prefix[0]}{k}" in values])
    return found


def stage_view(trace, points, options, grid, index, stage) -> OutsideView | None:
    """The picture of ``stage`` at step ``index``; None when the options make no camera."""
    try:
        camera, world, eyes, clips = _vertices(points, options, grid)
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None
    triangle = int(trace.variables_at(index).get("triangle", 1)) - 1
    if stage == "model":
        view = outside_view(points, options, grid)
        if view is not None:
            view.current = _ring([(p[0], p[2]) for p in world[3 * triangle:3 * triangle + 3]])
            view.title = "Model: the world"
        return view
    if stage == "view":
        return _eye_view(camera, eyes, triangle)
    if stage in ("projection", "clip"):
        return _clip_view(clips, triangle, trace.variables_at(index), stage)
    if stage == "divide":
        polygons = _polygons(trace, index, ("x_ndc", "y_ndc"))
        return _flat_view(polygons, [(-1, -1), (1, -1), (1, 1), (-1, 1)], "Divide: NDC",
                          "x_ndc to the right, y_ndc up, each in -1 .. 1: the square is the "
                          "view volume seen from the camera")
    polygons = _polygons(trace, index, ("x_win", "y_win"))
    width, height = grid
    title = "Viewport: window" if stage == "viewport" else "Rasterize: window"
    return _flat_view(polygons, [(0, 0), (width, 0), (width, height), (0, height)], title,
                      f"x_win to the right, y_win up, the grid's {width} x {height} pixels")


def _eye_view(camera, eyes, triangle) -> OutsideView:
    reach = max([-e[2] for e in eyes] + [camera.near * 2])
    far = min(camera.far, 1.2 * reach)
    half = math.tan(math.radians(camera.fov) / 2) * camera.aspect
    frustum = [((-half * d, -d), (half * d, -d)) for d in (camera.near, far)]
    frustum += [((0.0, 0.0), (-half * far, -far)), ((0.0, 0.0), (half * far, -far))]
    edges = [s for n in range(len(eyes) // 3)
             for s in _ring([(e[0], e[2]) for e in eyes[3 * n:3 * n + 3]])]
    current = _ring([(e[0], e[2]) for e in eyes[3 * triangle:3 * triangle + 3]])
    return OutsideView(edges, frustum, (0.0, 0.0),
                       "From above: x_eye to the right, z_eye down; the camera at the origin "
                       "looks up the picture, towards -z", current, "View: eye space")


def _clip_view(clips, triangle, variables, stage) -> OutsideView:
    reach = max([abs(c[3]) for c in clips] + [1.0]) * 1.1
    planes = [((-reach, reach), (0.0, 0.0)), ((0.0, 0.0), (reach, reach))]  # x = -w, x = w
    edges = [s for n in range(len(clips) // 3)
             for s in _ring([(c[0], c[3]) for c in clips[3 * n:3 * n + 3]])]
    current = _ring([(c[0], c[3]) for c in clips[3 * triangle:3 * triangle + 3]])
    caption = "x_clip to the right, w up; inside between the lines x = -w and x = w"
    title = "Projection: clip space"
    if stage == "clip":
        title = "Clip: planes that cut"
        corners = clips[3 * triangle:3 * triangle + 3]
        # A plane cuts when some corner lies outside it (all outside: nothing is left).
        cut = [plane for plane in PLANES if any(distance(plane, c) < 0 for c in corners)]
        caption += "; cut by " + (", ".join(cut) if cut else "no plane")
    return OutsideView(edges, planes, (0.0, 0.0), caption, current, title, y_down=False)


def _flat_view(polygons, frame, title, caption) -> OutsideView:
    edges = [s for corners in polygons[:-1] for s in _ring(corners)]
    current = _ring(polygons[-1]) if polygons else []
    return OutsideView(edges, _ring(frame), None, caption, current, title,
                       y_down=False)
