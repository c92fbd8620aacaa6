"""The antialiasing family's entries in the registry."""
from __future__ import annotations

from algorithms.core.registry import AlgorithmSpec, Inputs, Oracle

from .adaptive import ADAPTIVE_OPTIONS, adaptive, adaptive_code
from .filters import FILTER_OPTIONS, filter_code, post_filter
from .lines import AREA_OPTIONS, WU_OPTIONS, area_code, line_area, wu, wu_code
from .shapes import POINTS, SEGMENT, explain_samples
from .supersample import SUPERSAMPLE_OPTIONS, supersample, supersample_code
from .temporal import TEMPORAL_OPTIONS, temporal, temporal_code
from .wu_kernel import wu_pixels


AA_NOTES = (
    "Coverage is the fraction of the pixel square a shape covers (0..1); values are "
    "coverages, and the grid shows the ink blended over white by them.",
    "Vertices snap to 1/256 px and samples lie on a 1/512 px lattice: every inside test is "
    "exact.",
)


def _method(name, title, summary, inputs, options, code, generator, oracle, notes=(),
            explain=None, uses_grid=True, kernel=None):
    """The spec of one method; ``code(points, options)`` returns its ``Code``."""
    def listing(points, options):
        return tuple(code(points, options).lines)

    return AlgorithmSpec(name=name, title=title, family="antialias", summary=summary,
                         inputs=inputs, options=options, code=listing, generator=generator,
                         notes=AA_NOTES + tuple(notes), explain=explain, uses_grid=uses_grid,
                         kernel=kernel, oracle=oracle)


AA_SUPERSAMPLE = _method("aa-supersample", "Supersampling", "n x n samples per pixel (grid, jittered, random "
          "or rotated grid), weighted by a filter", POINTS, SUPERSAMPLE_OPTIONS,
          supersample_code, supersample, explain=explain_samples,
          notes=("weighted: w = h(u) + h(v), h = distance to the nearer pixel border; for the "
                 "4 x 4 grid exactly the kernel 1 2 2 1 / 2 3 3 2 / 2 3 3 2 / 1 2 2 1.",
                 "With n = 1, pattern grid and filter box the one sample is the centre: the "
                 "aliased picture."),
          oracle=Oracle(
              "exact",
              "Per pixel, the documented sample positions and whole-number filter weights "
              "applied to exact sample tests written in the test (jittered and random positions "
              "taken from the documented hash); and the exact coverage "
              "(algorithms/exact/coverage.py) within documented bounds as n grows.",
              ("algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_supersample.py")))
AA_ADAPTIVE = _method("aa-adaptive", "Adaptive supersampling", "corners and centre first; split a square "
          "in four where its samples disagree", POINTS, ADAPTIVE_OPTIONS, adaptive_code,
          adaptive, explain=explain_samples,
          notes=("Cheap where a pixel is wholly in or out, but a detail that falls between "
                 "the five samples of a square is missed.",
                 "Corners are shared by the squares of one pixel, not between pixels; "
                 "samples counts each tested point once per pixel."),
          oracle=Oracle(
              "exact",
              "The recursive corners-and-centre definition in Fractions written in the test; "
              "and the exact coverage (algorithms/exact/coverage.py) as a bound: the RMS error "
              "at edge pixels falls with max_depth and is below 0.05 at depth 4.",
              ("algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_methods.py")))
AA_FILTER = _method("aa-filter", "Post-filtering (convolution)", "render aliased, then blur: each pixel "
          "becomes a weighted average of its neighbourhood", Inputs(3, integer=False,
                                                                    names=("P0", "P1", "P2"),
                                                                    multiple=True),
          FILTER_OPTIONS, filter_code, post_filter, explain=explain_samples,
          notes=("The filter reads the aliased image and writes a new one; it blurs the "
                 "stairs but cannot recover detail the centres missed.",),
          oracle=Oracle(
              "exact",
              "The aliased image from the exact coverage of the pixel centres, convolved with "
              "the documented kernel in whole numbers (zero beyond the grid) and divided by its "
              "sum once, written in the test: equal on the catalogue and random triangles.",
              ("algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_methods.py")))
LINE_WU = _method("line-wu", "Xiaolin Wu's line", "two pixels per column along the minor axis, "
          "intensities 1 - f and f", SEGMENT, WU_OPTIONS, wu_code, wu, uses_grid=False,
          kernel=wu_pixels,
          notes=("Whole-pixel endpoints as in the line family: the segment joins the two "
                 "end pixels' centres; e counts the fraction in units of 1/dx, exactly.",),
          oracle=Oracle(
              "exact",
              "Xiaolin Wu's definition in Fractions: in each major column, the two pixels around "
              "the exact minor coordinate with 1 - f and f, for both endpoint rules; kernel and "
              "generator to the last bit.",
              ("algorithms/antialias/test_wu_kernel.py",
               "algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_lines.py")))
LINE_AREA = _method("line-area", "Area-sampled line", "intensity = the area of the pixel square that "
          "the line's rectangle covers", SEGMENT, AREA_OPTIONS, area_code, line_area,
          uses_grid=False,
          notes=("Areas come from the exact coverage reference (float64, vectorised).",),
          oracle=Oracle(
              "reference",
              "Pixel by pixel, the area of the pixel square inside the line's rectangle from "
              "shapely, to 1e-9 (and 16 ulps of the largest coordinate far from the origin); "
              "in sums, by plain geometry to 1e-12.",
              ("algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_lines.py")))
AA_TEMPORAL = _method("aa-temporal", "Temporal aliasing and motion blur", "a spinning wheel or moving "
          "triangle over several frames: one instant per frame, or averaged over the exposure",
          POINTS, TEMPORAL_OPTIONS, temporal_code, temporal,
          notes=("The wagon-wheel effect: a wheel with s spokes looks the same every 360/s "
                 "degrees, so a turn of speed per frame looks like the apparent speed.",
                 "temporal_frames(points, options, grid) gives the images as arrays."),
          oracle=Oracle(
              "reference",
              "Each frame equals the documented definition written in the test: the mean over "
              "its instants of the n x n samples the moved or turned shapes hold (whole-number "
              "sample tests); jittered instants are only held to one per stratum.",
              ("algorithms/antialias/test_antialias_reference.py",
               "algorithms/antialias/test_antialias_methods.py")))

# The module's algorithms, in the order they are listed.
SPECS = (AA_SUPERSAMPLE, AA_ADAPTIVE, AA_FILTER, LINE_WU, LINE_AREA, AA_TEMPORAL)
