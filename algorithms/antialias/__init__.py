"""The antialiasing family: estimating how much of each pixel a shape covers.

An aliased rasterizer asks one question per pixel: is the centre inside?
The answer is 0 or 1, and edges come out as stairs. The algorithms here
estimate the pixel's *coverage* instead, the fraction of its square the
shape covers (0..1; algorithms/exact/coverage.py computes it exactly):

* ``aa-supersample``: many samples per pixel, averaged by a filter;
* ``aa-adaptive``: a few samples, more only where they disagree;
* ``aa-filter``: the aliased image first, then blurred by a convolution;
* ``line-wu`` and ``line-area``: antialiased lines, by Xiaolin Wu's two
  pixels per column and by the exact area of the line's rectangle;
* ``aa-temporal``: a moving or spinning shape over several animation
  frames, sampled at one instant per frame (the wagon-wheel effect) or
  averaged over the frame's exposure (motion blur).

Every run names its coverage as the pixel value (``Start.pixel_value``), so
``run --json`` prints coverages in 0..1, and a packed colour as
``Start.color_value``: the ink blended over a white background by the
coverage (a grey for black ink), which the colour buffer shows.

Shapes (``shape``). ``triangles``: 3k points, k triangles, the union is
drawn. ``polygon``: all points form one contour, filled by ``fill_rule``
(evenodd or nonzero). ``thick-line``: 2k points, k segments, each the
rectangle of the segment widened by ``width`` / 2 on either side (``caps``
square also lengthens it by width / 2 at each end). Points are positions
in the plane (real numbers), as for triangles.

Samples and exactness. Vertices snap to multiples of 1/256 px (halves to
even), as the triangle family does. Sample positions lie on a lattice of
1/512 px, so every inside test is exact integer arithmetic (int64 in the
vectorised kernels, Python integers in the generators), and the generator
and the kernel of an algorithm give the same numbers to the last bit. A
sample exactly on an edge follows the same tie rule as pixel centres do
(left and bottom edges in; for polygons, the point nudged right and a
hair up decides). Per axis a sample sits at (2k + 1) / (2N) of the pixel
for a whole number k in 0..N-1:

* ``grid``: n x n samples, N = n, k = 0..n-1 (n = 1: the centre);
* ``rotated-grid``: an n x n grid turned by atan(1/n) so that no two of
  its n^2 samples share a row or a column of an n^2 x n^2 grid (n = 2 is
  the classic rotated-grid pattern); N = n^2, sample (i, j) at
  k_x = n i + j, k_y = n j + (n - 1 - i);
* ``jitter``: stratified: one uniformly random sample in each cell of the
  n x n grid, N = 256;
* ``random``: n^2 uniformly random samples, N = 256.

Positions are rounded to the 1/512 lattice (exact whenever N divides 256,
which holds for jitter, random and n a power of two). Jitter and random
take their numbers from a counter-based hash (SplitMix64's finaliser) of
(seed, x, y, sample): a pixel's samples depend on the seed and the pixel
only, so the generator, the kernel and any window of the grid agree.

Filters (``filter``) weigh the samples of one pixel; the filter's support
is the pixel itself. With h(k) = min(2k + 1, 2N - 2k - 1), which is 2N
times the sample's distance to the nearer pixel border along that axis:

* ``box``: every sample weighs 1 (the unweighted average);
* ``weighted``: w = h(k_x) + h(k_y). For the 4 x 4 grid this is the
  classic weighted kernel 1 2 2 1 / 2 3 3 2 / 2 3 3 2 / 1 2 2 1 (times 2),
  and for an n x n grid in general 1 + d_i + d_j (times 2), where d_i is
  how many samples lie between sample i and the pixel's border: weights
  grow by one per step inward along each axis. For other patterns it is
  the same function of the sample position;
* ``tent``: w = h(k_x) h(k_y), the product of two triangle functions that
  vanish at the pixel border;
* ``gaussian``: w = round(65536 exp(-r^2 / (2 sigma^2))), r the distance
  from the pixel centre in px, at least 1.

All weights are whole numbers W_s; coverage = sum(W_s hit_s) / sum(W_s) is
one correctly rounded division, and the weights normalised, W_s / sum W,
add up to exactly 1.
"""
from __future__ import annotations

# The package's modules, by idea: shapes (what is drawn, its exact tests,
# what every method shares), supersample, adaptive, filters (post-filtering),
# lines (Wu, area) and temporal; specs declares them. The names below are
# the family's public face.
from .adaptive import ADAPTIVE_OPTIONS, adaptive, adaptive_code, adaptive_image
from .filters import (FILTER_OPTIONS, KERNELS, aliased_image, filter_code, filter_image,
                      filter_kernel, filter_sums, post_filter)
from .lines import (AREA_OPTIONS, WU_OPTIONS, area_code, area_image, line_area, segment_window, wu,
                    wu_code, wu_image)
from .shapes import (BACKGROUND, INK, MAX_COORDINATE, POINTS, SEGMENT, SHAPE_OPTIONS, SHAPES,
                     SNAP, UNIT, WHITE, Shape, Shapes, explain_samples, reference_coverage)
from .supersample import (FILTERS, PATTERNS, SUPERSAMPLE_OPTIONS, lattice, normalised_weights,
                          random_bits, sample_strata, sample_weights, supersample, supersample_code,
                          supersample_image)
from .temporal import (TEMPORAL_OPTIONS, animation_frame_steps, apparent_speed, temporal,
                       temporal_code, temporal_frames, iter_temporal_frames, time_samples)
from . import specs
from . import subpixel_line

# The family's algorithms, in the order they are listed (line supersampling as printed last).
SPECS = specs.SPECS + subpixel_line.SPECS
