"""The textures family's entries in the registry."""
from __future__ import annotations

from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.triangles.edges import BASE_OPTIONS, TRIANGLES, explain
from algorithms.triangles.specs import make_kernel

from . import texels
from .sampling import FILTERS, WRAPS
from .triangle import code_lines, generator


OPTIONS = BASE_OPTIONS + (
    Option("uv", "numbers", (0.0, 0.0, 1.0, 0.0, 0.0, 1.0), "texture coordinates u,v per "
           "point (2 numbers each), or for three points shared by every triangle"),
    Option("w", "numbers", (), "a clip-space w per vertex (or three, shared), all > 0; "
           "none: w = 1 everywhere"),
    Option("texture", "text", "checker:8", "checker:N (N squares per unit of uv, N a power of "
           "two up to 32), zoneplate (rings that alias), or a PNG file (sides powers of two up to "
           "1024; in a scene file, a path from the scene's folder)",
           choices=texels.BUILTIN),
    Option("perspective", "bool", True, "interpolate u/w, v/w and 1/w and divide "
           "(perspective-correct); off: interpolate u and v in screen space (affine)"),
    Option("filter", "choice", "bilinear", "how the texture is read at a pixel",
           choices=FILTERS),
    Option("wrap", "choice", "repeat", "texture coordinates outside 0..1: repeat or clamp "
           "to the edge texel", choices=WRAPS),
    Option("max_aniso", "int", 8, "anisotropic: at most this many probes", minimum=1,
           maximum=16),
    Option("samples", "int", 8, "reference: n x n sub-pixel points per pixel", minimum=1,
           maximum=32),
)

NOTES = (
    "Coverage is the triangle family's: snapped vertices, edge functions and the fill rule.",
    "u, v and their derivatives come from the planes of u/w, v/w and 1/w at the pixel "
    "centre; lambda = log2(rho), rho the longer of (du/dx, dv/dx) and (du/dy, dv/dy) in "
    "texels, as OpenGL defines it.",
    "Texel (i, j) covers [i, i+1) x [j, j+1) of texel space (u W, v H); v = 0 is the "
    "texture's bottom row. The pyramid is built once per texture (2 x 2 box averages).",
    "t0..t3 are the first four texels fetched (x, y, weight); fetches counts them all.",
)

FRAGMENTS = (("triangle", "@triangle"), ("weights", "@weights"), ("u", "u"), ("v", "v"),
             ("lod", "lambda"), ("level", "level"), ("fetches", "fetches"), ("color", "rgb"))

TRIANGLE_TEXTURE = AlgorithmSpec(
    name="triangle-texture", title="Textured triangle", family="textures",
    summary="look a texture up at every covered pixel: uv (affine or perspective-correct), "
            "nearest, bilinear, mip-mapped, anisotropic or the reference average",
    inputs=TRIANGLES, options=OPTIONS, code=code_lines, generator=generator,
    kernel=make_kernel("triangle-texture", generator, code_lines),
    notes=NOTES, explain=explain, uses_grid=True, fragments=FRAGMENTS,
    oracle=Oracle(
        "reference",
        "The covered pixels equal the exact triangle coverage; uv, its derivatives and lambda equal "
        "exact rational values to 1e-12; nearest and bilinear colours equal a texel lookup at the "
        "exact uv written in the test within half a level; the mip-mapped and "
        "anisotropic filters only stay within bounds of the module's own reference filter.",
        ("algorithms/textures/test_textures_reference.py",
         "algorithms/textures/test_textures_mapping.py",
         "algorithms/textures/test_textures_filters.py")),
)

# The module's algorithms, in the order they are listed.
SPECS = (TRIANGLE_TEXTURE,)
