"""Write the example and hard-case scenes shipped in resources/scenes.

    python scripts/make_scenes.py

Each scene's description says what makes it hard and what to look for;
tests/app/model/test_shipped_scenes.py checks what the descriptions claim.
"""
from __future__ import annotations

import math
import random
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from algorithms.visibility import zbuffer_painter as visibility  # noqa: E402
from app.model.scene import Scene, save  # noqa: E402


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


def mesh(columns, rows, width, height, seed=7, margin=1.5):
    """A jittered grid of columns x rows cells, two triangles each, sharing edges."""
    rnd = random.Random(seed)
    corners = {}
    for r in range(rows + 1):
        for c in range(columns + 1):
            x = margin + c * (width - 2 * margin) / columns
            y = margin + r * (height - 2 * margin) / rows
            x += rnd.uniform(-1.2, 1.2) if 0 < c < columns else 0
            y += rnd.uniform(-1.2, 1.2) if 0 < r < rows else 0
            corners[c, r] = [round(x * 256) / 256, round(y * 256) / 256]
    points = []
    for r in range(rows):
        for c in range(columns):
            a, b, d, e = corners[c, r], corners[c + 1, r], corners[c + 1, r + 1], corners[c, r + 1]
            points += [a, b, d, a, d, e]
    return points


def siemens_star(cx, cy, radius, spokes):
    """spokes thin wedges around (cx, cy), each half of its angular period."""
    points = []
    for k in range(spokes):
        a0, a1 = 2 * math.pi * k / spokes, 2 * math.pi * (k + 0.5) / spokes
        points += [[cx, cy]] + [[round((cx + radius * math.cos(a)) * 256) / 256,
                                 round((cy + radius * math.sin(a)) * 256) / 256] for a in (a0, a1)]
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
    "triangle-mesh-1e6": Scene(
        "triangle-bbox", mesh(6, 4, 32, 24), {"precision": "float32", "offset": [1000000, 1000000]},
        32, 24, title="A mesh near x, y = 1,000,000",
        description="Edge functions evaluated a million pixels from the origin: float32 keeps "
                    "1/16 px of a coordinate and far less of a*x + b*y + c, so the mesh falls "
                    "apart into cracks; with precision fixed it stays watertight."),
    "triangle-behind-eye": Scene(
        "triangle-perspective", [[3, 12], [29, 12], [16, 21]],
        {"w": [1, 1, -0.5], "s": [0, 10, 5], "colors": ["#ff0000", "#00ff00", "#0000ff"],
         "near": 0.05}, 32, 24, title="A triangle straddling w = 0",
        description="The top vertex is behind the eye (w < 0): cut at w = near, the visible part "
                    "is the wedge below the front edge, not the triangle the corners outline."),
    "aa-siemens-star": Scene(
        "aa-supersample", siemens_star(24, 24, 23.5, 36), {"n": 1}, 48, 48,
        title="Aliasing: a Siemens star",
        description="Spokes narrower than a pixel near the centre alias into moire with one "
                    "sample per pixel; compare n = 1 with n = 4."),
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
