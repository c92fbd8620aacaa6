"""The pipeline's outside view: the world triangles, the camera and its view frustum seen
from above (x to the right, z downwards), as line segments for a view to draw."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from algorithms.pipeline.space import Camera, to_window


@dataclass
class OutsideView:
    triangles: list  # [(x0, z0), (x1, z1)] segments of the triangles' edges
    frustum: list  # segments of the frustum (near and far rectangles, the four side edges)
    eye: tuple | None  # (x, z) of the camera; None: not in the picture
    caption: str
    current: list = field(default_factory=list)  # segments of the triangle at the step
    title: str = "Scene from outside"
    y_down: bool = True  # a view from above: z grows downwards


def outside_view(points, options, grid) -> OutsideView | None:
    """None when the options make no camera (the run then says why)."""
    try:
        camera = Camera(options["eye"], options["target"], options["fov"], options["near"],
                        options["far"], grid[0] / grid[1])
        z = list(options.get("z") or ())
        world = [(float(x), float(y), float(z[k % len(z)]) if z else 0.0)
                 for k, (x, y) in enumerate(points)]
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None
    edges = []
    for n in range(len(world) // 3):
        tri = world[3 * n:3 * n + 3]
        edges += [((a[0], a[2]), (b[0], b[2])) for a, b in zip(tri, tri[1:] + tri[:1])]
    # The far rectangle is drawn no farther than the scene reaches, so the scene stays readable.
    reach = max([math.dist(camera.eye, p) for p in world] + [camera.near * 2])
    far = min(camera.far, 1.2 * reach)
    frustum, rectangles = [], []
    for distance in (camera.near, far):
        half_h = distance / camera.f
        half_w = half_h * camera.aspect
        corners = [[e + distance * f + sx * half_w * s + sy * half_h * u
                    for e, f, s, u in zip(camera.eye, camera.forward, camera.side, camera.up)]
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        rectangles.append(corners)
        frustum += [((a[0], a[2]), (b[0], b[2])) for a, b in zip(corners, corners[1:] + corners[:1])]
    frustum += [((a[0], a[2]), (b[0], b[2])) for a, b in zip(*rectangles)]
    eye = (camera.eye[0], camera.eye[2])
    caption = (f"From above: x to the right, z down. Camera at {tuple(round(v, 2) for v in camera.eye)}, "
               f"fov {camera.fov:g}\u00b0, near {camera.near:g}, far {camera.far:g}"
               + (" (drawn shorter)" if far < camera.far else ""))
    return OutsideView(edges, frustum, eye, caption)



def handle_places(points, options, grid) -> list | None:
    """Where the viewport puts each vertex on the grid: window (x, y), None for a vertex at or
    behind the eye (w <= 0, no place on the screen); None when the options make no camera."""
    try:
        camera = Camera(options["eye"], options["target"], options["fov"], options["near"],
                        options["far"], grid[0] / grid[1])
        z = list(options.get("z") or ())
        places = []
        for k, (x, y) in enumerate(points):
            clip = camera.to_clip(camera.to_eye([float(x), float(y),
                                                 float(z[k % len(z)]) if z else 0.0]))
            places.append(to_window(clip, *grid)[:2] if clip[3] > 0 else None)
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None
    return places
