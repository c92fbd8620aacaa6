"""Speed against error: operation counts, errors against the exact oracles, timings.

Pure (numpy and the standard library); ``app/analysis/report.py`` turns the rows into
the report. This module runs the experiments in order; they live by idea in
``measure_curves`` (lines, circles), ``measure_areas`` (meshes, traversals,
seed fill) and ``measure_shading`` (interpolation, depth, antialiasing), and
the rows, counts and timings they share in ``counting``.

Every measurement is one row (``Row``): the family, the experiment, the
algorithm and its variant (the options that matter), the swept parameter
and its value, the metric, its value and its unit. The sweeps are seeded,
so two runs measure the same inputs and give the same counts and errors;
only the timings vary.

Operation counts. Each pseudo-code line carries the operations one
execution of it performs (``CodeLine.ops``; work that grows with a
quantity of the frame, such as the pixels of a Span run, in
``CodeLine.per``). A recorded trace names the line of every frame, so

    count[op] = sum over lines l of  executions(l) * ops[l][op]
              + sum over frames f with a scaled quantity q  of  q(f) * per[l][q][op],

executions(l) being ``np.bincount(trace.line)`` less the Note records
(commentary, no work). The counts are exact for what the annotations
describe and deterministic; the annotations say where they fold a loop
header into the body's line and where they give a lower bound.

Cost per pixel divides by the pixels the run wrote (duplicates included);
``ops`` is the sum of the arithmetic and comparison counts (int_add,
float_add, mul, div, sqrt, round, compare); pixels_tested and samples are
kept apart.

Timings are the median of repeats (``time.perf_counter``) of one pass of
the fast kernel, where the algorithm has one, and of recording the
generator into a Trace (``AlgorithmSpec.record``), over all the inputs of
a sweep point (its segments, shapes or triangles) at once; divided by the
pixels of that pass, as the counts are. The pass whose traces give the
counts is the warm-up that sizes the timed samples.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .counting import COLUMNS, SEED, Rows, op_counts, pareto_front, total_ops
from .measure_areas import (TRAVERSALS, exact_cover, measure_fill, measure_precision,
                            measure_traversal)
from .measure_curves import (CIRCLE_VARIANTS, IMPLICIT_MAX_BOX, LINE_VARIANTS, line_errors,
                             measure_circles, measure_lines)
from .measure_textures import measure_textures, texture_ticks
from .measure_visibility import measure_visibility
from .measure_shading import (DEPTH_BUFFERS, antialias_available, measure_antialias,
                              measure_interpolation)

# The names the report, the window and the tests take from here.
__all__ = ["COLUMNS", "DEPTH_BUFFERS", "FAMILIES", "IMPLICIT_MAX_BOX", "SEED", "Rows", "Settings",
           "antialias_available", "exact_cover", "line_errors", "measure_antialias", "op_counts",
           "pareto_front", "run", "settings", "tasks", "ticks", "total_ops"]


# ============================================================== settings
@dataclass(frozen=True)
class Settings:
    quick: bool
    repeats: int
    generator_repeats: int
    line_lengths: tuple
    segments: int
    traced_segments: int
    generator_max_length: int
    max_frames: int
    dda_max_length: int
    dda_lengths: int
    dda_segments: int
    radii: tuple
    circle_cost_radii: tuple
    hole_radius: int
    magnitudes: tuple
    mesh_cells: int
    cell_size: float
    traversal_grid: int
    traversal_count: int
    fill_radius: int
    interpolation_grid: int
    w_ratios: tuple
    near_far: tuple
    depth_rows: int
    aa_grid: int
    aa_triangles: int
    aa_samples: tuple
    aa_depths: tuple


def settings(quick: bool) -> Settings:
    if quick:
        return Settings(
            quick=True, repeats=3, generator_repeats=1,
            line_lengths=(100, 1000, 10_000, 100_000), segments=3, traced_segments=2,
            generator_max_length=1000, max_frames=20_000,
            dda_max_length=100_000, dda_lengths=17, dda_segments=6,
            radii=tuple(range(0, 33)) + (64, 256, 1024), circle_cost_radii=(100,),
            hole_radius=48,
            magnitudes=(10, 1e3, 1e5, 1e6, 1e7), mesh_cells=3, cell_size=6.0,
            traversal_grid=32, traversal_count=1, fill_radius=14,
            interpolation_grid=24, w_ratios=(1, 2, 10, 100, 10_000),
            near_far=(10, 1e3, 1e5, 1e7), depth_rows=4096,
            aa_grid=24, aa_triangles=3, aa_samples=(1, 2, 4, 8), aa_depths=(1, 3))
    return Settings(
        quick=False, repeats=7, generator_repeats=5,
        line_lengths=(100, 300, 1000, 3000, 10_000, 30_000, 100_000), segments=24,
        traced_segments=6, generator_max_length=10_000, max_frames=200_000,
        dda_max_length=100_000, dda_lengths=61, dda_segments=48,
        radii=tuple(range(0, 129)) + (256, 512, 1024, 2048, 4096),
        circle_cost_radii=(10, 100, 1000), hole_radius=256,
        magnitudes=(10, 100, 1e3, 1e4, 1e5, 1e6, 1e7), mesh_cells=6, cell_size=7.0,
        traversal_grid=64, traversal_count=6, fill_radius=60,
        interpolation_grid=64, w_ratios=(1, 1.5, 2, 4, 10, 100, 1000, 10_000, 1e6),
        near_far=(10, 100, 1e3, 1e4, 1e5, 1e6, 1e7), depth_rows=65_536,
        aa_grid=48, aa_triangles=6, aa_samples=tuple(range(1, 9)), aa_depths=(1, 2, 3, 4))


# ================================================================= run
FAMILIES = ("lines", "circles", "polygons", "fill", "triangles", "interpolation",
            "antialiasing", "textures", "visibility")


def tasks(config: Settings) -> list[tuple[str, str, Callable]]:
    """(family, label, measure) in order; each measure(config, rows, rng, tick)."""
    found = [("lines", "lines", measure_lines),
             ("circles", "circles", measure_circles),
             ("polygons", "meshes (polygons and triangles)", measure_precision),
             ("triangles", "traversals", measure_traversal),
             ("fill", "seed fill", measure_fill),
             ("interpolation", "interpolation and depth", measure_interpolation)]
    if not antialias_available():
        found.append(("antialiasing", "antialiasing", measure_antialias))
    found.append(("textures", "textures", measure_textures))
    found.append(("visibility", "painter and splitting", measure_visibility))
    return found


def ticks(config: Settings) -> int:
    """How many times the measures call tick(): the progress bar's length."""
    total = len(config.line_lengths) * len(LINE_VARIANTS)
    total += len(CIRCLE_VARIANTS) + len(config.magnitudes) + len(TRAVERSALS) + 1
    total += len(config.w_ratios) + texture_ticks() + 1  # and the visibility scenes
    if not antialias_available():
        from algorithms import antialias
        total += len(antialias.PATTERNS)
    return total


def run(config: Settings, progress: Callable[[int, int, str], None] | None = None,
        seed: int = SEED) -> tuple[Rows, dict]:
    """Every measurement, and how long each family took (seconds)."""
    rows = Rows()
    total = ticks(config)
    done = [0]
    seconds = {}
    for family, label, measure in tasks(config):
        def tick(label=label):
            done[0] += 1
            if progress:
                progress(min(done[0], total), total, label)
        if progress:
            progress(done[0], total, label)
        start = time.perf_counter()
        measure(config, rows, np.random.default_rng([seed, FAMILIES.index(family)]), tick)
        seconds[label] = time.perf_counter() - start
    if progress:
        progress(total, total, "done")
    return rows, seconds
