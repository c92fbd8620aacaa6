"""The pipeline's matrices written out for the tests, from the camera's parameters alone."""
from __future__ import annotations

import numpy as np


def view_matrix(eye, target) -> np.ndarray:
    """World to eye space: the camera at the origin looking down -z, +y up."""
    eye, target = np.asarray(eye, float), np.asarray(target, float)
    forward = (target - eye) / np.linalg.norm(target - eye)
    side = np.cross(forward, [0.0, 1.0, 0.0])
    side /= np.linalg.norm(side)
    up = np.cross(side, forward)
    rotation = np.identity(4)
    rotation[0, :3], rotation[1, :3], rotation[2, :3] = side, up, -forward
    translation = np.identity(4)
    translation[:3, 3] = -eye
    return rotation @ translation


def projection_matrix(fov, aspect, near, far) -> np.ndarray:
    """OpenGL's perspective matrix: eye to clip space, w = -z_eye."""
    f = 1 / np.tan(np.radians(fov) / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                     [0, 0, -1, 0]])


def stages(points, z, options, grid) -> dict:
    """Each vertex's world, eye, clip, NDC and window coordinates as arrays, one row a vertex."""
    world = np.array([[x, y, z[k % len(z)] if z else 0.0, 1.0]
                      for k, (x, y) in enumerate(points)])
    eye = world @ view_matrix(options["eye"], options["target"]).T
    clip = eye @ projection_matrix(options["fov"], grid[0] / grid[1], options["near"],
                                   options["far"]).T
    ndc = clip[:, :3] / clip[:, 3:]
    window = np.column_stack([(ndc[:, 0] + 1) * grid[0] / 2, (ndc[:, 1] + 1) * grid[1] / 2,
                              (ndc[:, 2] + 1) / 2])
    return {"world": world[:, :3], "eye": eye[:, :3], "clip": clip, "ndc": ndc,
            "window": window}
