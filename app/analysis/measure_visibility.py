"""The painter's algorithm against the painter with splitting (BSP): how many
pixels each gets wrong (against the z-buffer) and what the splitting costs.

Scenes: the painter's two failures (triangles that pierce each other, and
three that overlap in a cycle), the one it gets right, and seeded random
scenes of triangles at random depths.
"""
from __future__ import annotations

from algorithms.core import registry
from algorithms.visibility.zbuffer_painter import SCENES

from .counting import Rows, op_counts, total_ops

GRID = (32, 24)
METRICS = ("disagree", "splits", "pieces", "ops")


def random_scene(rng, count: int) -> dict:
    points = [(float(rng.uniform(1, GRID[0] - 1)), float(rng.uniform(1, GRID[1] - 1)))
              for _ in range(3 * count)]
    z = tuple(round(float(v), 3) for v in rng.uniform(0.05, 0.95, 3 * count))
    return {"points": points, "grid": GRID, "options": {"z": z}}


def visibility_scenes(rng, randoms: int) -> dict:
    scenes = {name.removeprefix("painter-"): make() for name, make in SCENES.items()}
    for k in range(randoms):
        scenes[f"random {k + 1} (6 triangles)"] = random_scene(rng, 6)
    return scenes


def measure_visibility(settings, rows: Rows, rng, tick=lambda: None) -> None:
    randoms = 2 if settings.quick else 6
    for name, scene in visibility_scenes(rng, randoms).items():
        for algorithm in ("painter", "painter-split"):
            spec = registry.get(algorithm)
            options = {"z": scene["options"]["z"]}
            trace = spec.record(scene["points"], options, scene["grid"])
            final = trace.final_variables()
            values = {"disagree": final["disagree"], "ops": total_ops(op_counts(trace)),
                      "splits": final.get("splits", 0),
                      "pieces": final.get("pieces", len(scene["points"]) // 3)}
            for metric in METRICS:
                rows.add("visibility", "painter", algorithm, algorithm, "scene", name, metric,
                         values[metric], "px" if metric == "disagree" else "")
    tick()
