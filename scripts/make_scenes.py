"""Write the example and hard-case scenes shipped in resources/scenes.

    python scripts/make_scenes.py

Each scene's description says what makes it hard and what to look for;
tests/app/test_shipped_scenes.py checks what the descriptions claim.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from algorithms import visibility  # noqa: E402
from app.scene import Scene, save  # noqa: E402


def star(cx, cy, outer, inner, points=5):
    """A star polygon whose edges cross (a pentagram when inner is 0)."""
    corners = [(cx + outer * math.cos(math.pi / 2 + 4 * math.pi * k / points),
                cy + outer * math.sin(math.pi / 2 + 4 * math.pi * k / points)) for k in range(points)]
    return [[round(x * 8) / 8, round(y * 8) / 8] for x, y in corners]


def fan(cx, cy, radius, count):
    """count triangles around (cx, cy), neighbours sharing their edges."""
    ring = [(cx + radius * math.cos(2 * math.pi * k / count),
             cy + radius * math.sin(2 * math.pi * k / count)) for k in range(count)]
    ring = [[round(x * 256) / 256, round(y * 256) / 256] for x, y in ring]
    points = []
    for k in range(count):
        points += [[cx, cy], ring[k], ring[(k + 1) % count]]
    return points


def visibility_scene(name, title, description):
    scene = visibility.SCENES[name]()
    width, height = scene["grid"]
    return Scene(scene["algorithm"], [list(p) for p in scene["points"]], dict(scene["options"]),
                 width, height, title=title, description=description)


SCENES = {
    "circle-radius-1": Scene("circle-midpoint", [[5, 5]], {"radius": 1}, 11, 11,
                             title="Radius 1",
                             description="The smallest real circle: the loop ends at once and "
                                         "the eight mirrors collapse onto four pixels."),
    "circle-radius-2": Scene("circle-midpoint", [[5, 5]], {"radius": 2}, 11, 11,
                             title="Radius 2",
                             description="Mirrors meet on the diagonal and the axes: watch that no "
                                         "pixel is written twice."),
    "circle-sqrt4-gaps": Scene("circle-sqrt4", [[16, 12]], {"radius": 10}, 32, 24,
                               title="4-way symmetry leaves gaps",
                               description="One pixel per column: where the circle is steep the "
                                           "columns jump and the outline breaks."),
    "polygon-horizontal-edges": Scene(
        "polygon-scanline", [[[2, 2.5], [14, 2.5], [14, 8.5], [22, 8.5], [22, 2.5], [29, 2.5],
                              [29, 18.5], [2, 18.5]]], {}, 32, 24,
        title="Horizontal edges and vertices on scan lines",
        description="Every vertex lies on a row of pixel centres; horizontal edges never enter "
                    "the edge table, and only bottom edges keep their centres."),
    "polygon-star-evenodd": Scene("polygon-scanline", [star(16, 12, 11, 0)],
                                  {"fill_rule": "evenodd"}, 32, 24,
                                  title="Self-intersecting star, even-odd",
                                  description="The centre pentagon is crossed twice and stays "
                                              "empty; switch fill_rule to nonzero to fill it."),
    "polygon-star-nonzero": Scene("polygon-scanline", [star(16, 12, 11, 0)],
                                  {"fill_rule": "nonzero"}, 32, 24,
                                  title="Self-intersecting star, non-zero winding",
                                  description="The centre has winding number 2, so non-zero "
                                              "winding fills it."),
    "triangle-sliver": Scene("triangle-bbox", [[1.5, 2.25], [30.5, 20.75], [30.25, 20.5]], {},
                             32, 24, title="A thin sliver",
                             description="Less than half a pixel wide: most of the bounding box "
                                         "is tested and only a few centres fall inside."),
    "triangle-fan-32": Scene("triangle-incremental", fan(16, 12, 10.5, 32), {}, 32, 24,
                             title="A fan of 32 triangles",
                             description="32 triangles share one vertex and their edges; with "
                                         "the top-left rule each pixel is covered once."),
    "painter-intersecting": visibility_scene(
        "painter-intersecting", "Painter's algorithm: intersecting triangles",
        "Two triangles pass through each other, so no drawing order is right everywhere."),
    "painter-cyclic": visibility_scene(
        "painter-cyclic", "Painter's algorithm: cyclic overlap",
        "Three triangles each lie partly over the next: any order gets one overlap wrong."),
}


def main() -> None:
    folder = ROOT / "resources" / "scenes"
    for name, scene in SCENES.items():
        save(scene, folder / f"{name}.json")
        print(folder / f"{name}.json")


if __name__ == "__main__":
    main()
