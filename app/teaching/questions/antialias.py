"""Question templates of the antialiasing family: the coverage of a pixel
under n x n supersampling.

Each variant draws a counter-clockwise triangle on the 1/2 px grid and an n
in 2..4, runs the real supersampler (a regular grid of samples, box filter)
and reads the answer from the frames of the asked pixel: one frame per
sample, with its position and whether it hit.
"""
from __future__ import annotations

import random
from collections import defaultdict
from fractions import Fraction

import numpy as np

from algorithms.core.steps import Table

from app.teaching.questions import triangle_draws as draws
from app.teaching.questions.model import NUMERICAL, Answer, Template, Worked

ALGORITHM = "aa-supersample"
OPTIONS = {"pattern": "grid", "filter": "box", "shape": "triangles"}


def _samples(trace, pixel) -> list:
    return [step for step in draws.frames_at(trace, pixel) if "hit" in step.values]


def _partial_pixels(trace) -> list:
    """The pixels some but not all of whose samples hit, from the sample frames."""
    hit = trace.series("hit")
    rows = np.flatnonzero(~np.isnan(hit))
    counts = defaultdict(lambda: [0, 0])
    for x, y, h in zip(trace.x[rows].tolist(), trace.y[rows].tolist(), hit[rows].tolist()):
        counts[(x, y)][0] += int(h)
        counts[(x, y)][1] += 1
    return sorted(p for p, (hits, total) in counts.items() if 0 < hits < total)


def _on_an_edge(points, pixel, n) -> bool:
    """Does a sample of ``pixel`` lie on the line of an edge? The answer would
    then rest on the tie rule (and for n = 3 on the 1/512 px lattice the
    samples are rounded to), which this question is not about."""
    for a in range(n):
        for b in range(n):
            sample = (pixel[0] + Fraction(2 * a + 1, 2 * n), pixel[1] + Fraction(2 * b + 1, 2 * n))
            for k in range(3):
                if draws.area2(points[(k + 1) % 3], points[(k + 2) % 3], sample) == 0:
                    return True
    return False


def _scene_input(scene):
    points, grid = draws.scene_triangles(scene, COVERAGE)
    options = dict(scene.options)
    if any(options.get(name, value) != value for name, value in OPTIONS.items()):
        raise ValueError("template aa-coverage needs a scene of triangles with pattern grid "
                         "and filter box")
    return points[:3], grid, int(options.get("n", 4))


def _coverage(seed, scene=None):
    rng = random.Random(seed)
    for _ in range(draws.ATTEMPTS):
        if scene is None:
            points, grid, n = draws.draw_triangle(rng), draws.GRID, rng.randint(2, 4)
        else:
            points, grid, n = _scene_input(scene)
        trace = draws.run(ALGORITHM, points, {**OPTIONS, "n": n}, grid)
        pixels = _partial_pixels(trace)
        rng.shuffle(pixels)
        pixel = next((p for p in pixels if not _on_an_edge(points, p, n)), None)
        if pixel is not None or scene is not None:
            break
    if pixel is None:
        raise ValueError("no pixel of the scene is partly covered with its samples off the edges")
    samples = _samples(trace, pixel)
    hits = sum(int(step.values["hit"]) for step in samples)
    value = Fraction(hits, n * n)
    positions = [record for _, record in trace.records_of(Table) if record.name == "samples"][0]
    offsets = sorted({row[1] for row in positions.rows}, key=Fraction)
    text = (f"A triangle has the vertices {draws.vertices_text(points)}. Pixel (i, j) is the "
            f"square [i, i+1) x [j, j+1), y up. It is supersampled with {n} x {n} samples on a "
            f"regular grid, at (i + u, j + v) for u, v in {{{', '.join(offsets)}}}, all weighted "
            f"equally. Give the "
            f"coverage of pixel p = {pixel}: the fraction of its samples inside the triangle, "
            f"as a fraction k/{n * n}.")
    rows = tuple((str(s + 1), row[1], row[2], "inside" if step.values["hit"] else "outside")
                 for s, (row, step) in enumerate(zip(positions.rows, samples)))
    summary = (f"{hits} of the {n * n} samples of p lie inside the triangle (each tested "
               f"against the three edges): coverage = {hits}/{n * n}"
               + ("" if value.denominator == n * n else f" = {draws.fraction_text(value)}") + ".")
    worked = Worked(("sample", "u", "v", "test"), rows, summary)
    answer = Answer(NUMERICAL, value, f"{hits}/{n * n}")
    picture_scene = draws.make_scene(ALGORITHM, points, {**OPTIONS, "n": n}, grid,
                                     "Coverage")
    return draws.question(COVERAGE, seed, "Coverage of a pixel", text, answer, worked,
                          picture_scene)


COVERAGE = Template("aa-coverage", "antialias",
                    "Supersampling: the coverage of pixel p with n x n samples (k/n^2)",
                    (ALGORITHM,), _coverage)

TEMPLATES = (COVERAGE,)
