"""Interpolation, depth buffers and antialiasing: error against exact values."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from algorithms.core import registry
from algorithms.core.errors import InputError

from .counting import Rows, add_costs, median_seconds, op_counts, timed, written_count
from .measure_areas import snapped


# ========================================================= interpolation
def measure_interpolation(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """Affine against perspective-correct interpolation, against the exact value."""
    from algorithms.exact import triangles as exact_triangles

    size = settings.interpolation_grid
    triangle = ((2.25, 3.5), (size - 2.75, size * 0.25 + 0.125), (size * 0.375, size - 2.5))
    s = (0.0, 1.0, 0.5)
    perspective = registry.get("triangle-perspective")
    affine = registry.get("triangle-barycentric")
    for ratio in settings.w_ratios:
        w = (1.0, float(ratio), (1.0 + float(ratio)) / 2)
        options = perspective.resolve({"s": s, "w": w})
        trace = perspective.record(list(triangle), options, (size, size))
        written = trace.writes()
        pixels = np.stack([trace.x[written], trace.y[written]], axis=1)
        s_affine = trace.series("s_affine")[written]
        s_persp = trace.series("s_persp")[written]
        exact_tri = [(Fraction(x), Fraction(y)) for x, y in triangle]
        snapped_tri = [(snapped(x, 8), snapped(y, 8)) for x, y in exact_tri]
        truth = np.array([float(exact_triangles.perspective_correct(
            exact_triangles.barycentric(snapped_tri, (Fraction(2 * int(i) + 1, 2),
                                                      Fraction(2 * int(j) + 1, 2))),
            [Fraction(v) for v in s], [Fraction(v) for v in w])) for i, j in pixels])
        for variant, values in (("affine", s_affine), ("perspective-correct", s_persp)):
            error = np.abs(values - truth)
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "interpolation", "w ratio", perspective.name if variant != "affine"
                else "triangle-perspective", variant, "w ratio", ratio, metric, v, unit)
            add("max error", float(error.max()), "of the attribute's range")
            add("rms error", float(np.sqrt(np.mean(error ** 2))), "of the attribute's range")
        tick()
    # Cost per covered pixel: the affine blend (barycentric with s) and the
    # perspective-correct one.
    for spec, variant, options in ((affine, "affine", {"s": s}),
                                   (perspective, "perspective-correct", {"s": s, "w": (1.0, 4.0, 2.5)})):
        resolved = spec.resolve(options)
        trace, once = timed(lambda: spec.record(list(triangle), resolved, (size, size)))
        seconds = median_seconds(lambda: spec.record(list(triangle), resolved, (size, size)),
                                 settings.generator_repeats, once=once)
        add_costs(rows, "interpolation", "cost", spec.name, variant, "triangle", "one",
                   op_counts(trace), written_count(trace), seconds)
    _depth_precision(settings, rows)


DEPTH_BUFFERS = ("fixed 24-bit", "float32", "float64", "float32 reversed")
DEPTH_GAP = 1e-3  # the second surface lies this fraction of its depth behind the first


def depth_values(z: np.ndarray, near: float, far: float, kind: str) -> np.ndarray:
    """Stored depth of eye-space depths z in [near, far] in a buffer of ``kind``.

    Standard (fixed 24-bit, float32, float64): d = f (z - n) / (z (f - n))
    in [0, 1], 0 at near, computed as A - B / z with A = f / (f - n),
    B = f n / (f - n) in the buffer's type (float64 for the fixed buffer,
    then rounded to a multiple of 1 / (2^24 - 1)). Reversed float32:
    d = n (f - z) / (z (f - n)) = B' / z - A', 1 at near and 0 at far, so
    the far depths, which crowd together, sit where floats are densest.
    """
    if kind == "fixed 24-bit":
        d = far / (far - near) - far * near / (far - near) / z
        return np.round(d * (2 ** 24 - 1))
    t = {"float32": np.float32, "float64": np.float64, "float32 reversed": np.float32}[kind]
    zt = z.astype(t)
    if kind == "float32 reversed":
        a, b = t(near / (far - near)), t(far * near / (far - near))
        return b / zt - a
    a, b = t(far / (far - near)), t(far * near / (far - near))
    return a - b / zt


def _depth_precision(settings, rows) -> None:
    """Where two surfaces 0.1 % of their depth apart fight, by far/near ratio.

    Eye depths z run log-uniformly from near to far / 1.001 (every decade
    of distance weighs the same); the second surface lies at z * 1.001. A
    depth fights when the stored values do not put the nearer surface
    strictly in front (so the drawing order decides).
    """
    for ratio in settings.near_far:
        near, far = 1.0, float(ratio)
        z = np.geomspace(near, far / (1 + DEPTH_GAP), settings.depth_rows)
        for kind in DEPTH_BUFFERS:
            front = depth_values(z, near, far, kind)
            back = depth_values(z * (1 + DEPTH_GAP), near, far, kind)
            fighting = (front <= back) if kind == "float32 reversed" else (front >= back)
            first = float(z[np.argmax(fighting)]) if fighting.any() else 0.0
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "interpolation", "depth precision", "z-buffer", kind, "far/near", ratio,
                metric, v, unit)
            add("z-fighting fraction", float(np.mean(fighting)), "of log depth range")
            add("first fighting depth", first, "x near (0: none)")


# ========================================================== antialiasing
def antialias_available() -> str:
    """'' when the antialiasing module can be measured, else why not."""
    try:
        from algorithms import antialias
        needed = ("supersample_image", "reference_coverage", "PATTERNS", "FILTERS")
        missing = [name for name in needed if not hasattr(antialias, name)]
        if missing:
            return f"algorithms.antialias lacks {', '.join(missing)}"
        grid = (8, 8)
        points = [(1.2, 1.1), (6.7, 2.3), (3.1, 6.6)]
        antialias.supersample_image(points, {"n": 2}, grid, colors=False)
        antialias.reference_coverage(points, {}, grid)
    except Exception as error:  # noqa: BLE001 - any failure means: leave it out
        return f"{type(error).__name__}: {error}"
    return ""


def measure_antialias(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """RMS and max error against exact coverage, by pattern, filter and samples; time."""
    from algorithms import antialias

    size = settings.aa_grid
    points = []
    for _ in range(settings.aa_triangles):
        points += [(float(rng.uniform(1, size - 1)), float(rng.uniform(1, size - 1)))
                   for _ in range(3)]
    grid = (size, size)
    reference = antialias.reference_coverage(points, {}, grid)
    edge = (reference > 0) & (reference < 1)
    for pattern in antialias.PATTERNS:
        for filter_name in antialias.FILTERS:
            for n in settings.aa_samples:
                options = {"pattern": pattern, "filter": filter_name, "n": n}
                image = lambda: antialias.supersample_image(  # noqa: E731
                    points, options, grid, colors=False)
                (coverage, _), once = timed(image)
                seconds = median_seconds(image, settings.repeats, once=once)
                error = coverage - reference
                add = lambda metric, v, unit="": rows.add(  # noqa: E731
                    "antialiasing", "supersampling", "aa-supersample",
                    f"{pattern} {filter_name}", "samples per pixel", n * n, metric, v, unit)
                add("rms error", float(np.sqrt(np.mean(error ** 2))), "coverage")
                add("max error", float(np.abs(error).max()), "coverage")
                add("edge rms error", float(np.sqrt(np.mean(error[edge] ** 2))) if edge.any()
                    else 0.0, "coverage")
                add("kernel time", 1e9 * seconds / (size * size), "ns/px")
                add("samples", n * n, "per pixel")
        tick()
    if hasattr(antialias, "adaptive_image"):
        for depth in settings.aa_depths:
            options = {"max_depth": depth}
            image = lambda: antialias.adaptive_image(points, options, grid)  # noqa: E731
            try:
                (coverage, spent), once = timed(image)
            except InputError:
                continue
            seconds = median_seconds(image, settings.generator_repeats, once=once)
            error = coverage - reference
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "antialiasing", "adaptive", "aa-adaptive", "adaptive", "max depth", depth,
                metric, v, unit)
            add("rms error", float(np.sqrt(np.mean(error ** 2))), "coverage")
            add("max error", float(np.abs(error).max()), "coverage")
            add("samples", float(spent.mean()), "per pixel")
            add("generator time", 1e6 * seconds / (size * size), "us/px")
