"""The pipeline family's entries in the registry."""
from __future__ import annotations

from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.visibility.zbuffer_painter import COLORS, FILL_RULE, TRIANGLES, Z

from .blend import ALPHA, DEPTH_WRITE, ORDER, blend, blend_code


BLEND_OVER = AlgorithmSpec(
    name="blend-over", title="Transparency: over and the z-buffer", family="pipeline",
    summary="composite transparent triangles with CB = alpha src + (1 - alpha) CB; the "
            "result depends on the drawing order",
    inputs=TRIANGLES, options=(Z, COLORS, ALPHA, ORDER, DEPTH_WRITE, FILL_RULE),
    code=lambda points, options: tuple(blend_code(options).lines), generator=blend,
    notes=("z and alpha are interpolated exactly at the pixel centre, then rounded once.",
           "Opaque fragments (alpha = 1) write their depth; transparent ones do not, so "
           "surfaces behind them still show.",
           "over is not commutative: sort transparent triangles back to front. Triangles "
           "that pierce each other cannot be sorted as wholes."),
    uses_grid=True,
    fragments=(("triangle", "@triangle"), ("z", "z"), ("alpha", "alpha"), ("source", "src"), ("before", "dst"),
               ("color", "rgb")),
    oracle=Oracle(
        "reference",
        "The colour buffer from `over` composited per pixel in the test, coverage and depth order "
        "in exact Fractions, within half a colour level, for the input and back-to-front orders.",
        ("algorithms/pipeline/test_pipeline_reference.py",
         "algorithms/pipeline/test_pipeline_blend.py")),
)

# ---------------------------------------------------------------- the 3-D pipeline

from algorithms.textures import texels  # noqa: E402
from algorithms.textures.sampling import FILTERS  # noqa: E402

from .stages import CLIPPINGS, SHADINGS, explain, pipeline, pipeline_code  # noqa: E402

PIPELINE_OPTIONS = (
    Option("z", "numbers", (), "world z per point (or three shared); none: 0"),
    Option("colors", "colors", (), "a colour per point (or three shared); none: light grey"),
    Option("normals", "numbers", (), "x,y,z per point (or for three shared); none: each "
           "triangle's face normal"),
    Option("uv", "numbers", (), "u,v per point (or for three shared), for a texture"),
    Option("texture", "text", "none", "none, checker:N, zoneplate or a PNG file; multiplies "
           "the shaded colour", choices=("none",) + texels.BUILTIN),
    Option("filter", "choice", "trilinear", "how the texture is read", choices=FILTERS),
    Option("eye", "numbers", (16.0, 12.0, 40.0), "the camera's position x,y,z"),
    Option("target", "numbers", (16.0, 12.0, 0.0), "the point the camera looks at"),
    Option("fov", "float", 40.0, "vertical field of view in degrees (0 .. 180)", minimum=0.0,
           maximum=180.0),
    Option("near", "float", 1.0, "distance of the near plane (> 0)", minimum=0.0),
    Option("far", "float", 100.0, "distance of the far plane (> near)", minimum=0.0),
    Option("clipping", "choice", "all", "clip against all six planes, only the near one, or "
           "none (then every vertex must have w > 0)", choices=CLIPPINGS),
    Option("shading", "choice", "gouraud", "flat, Gouraud or Phong, one directional light",
           choices=SHADINGS),
    Option("light", "numbers", (-1.0, -1.0, -2.0), "the direction the light travels x,y,z"),
)

PIPELINE = AlgorithmSpec(
    name="pipeline", title="The pipeline from a 3-D scene", family="pipeline",
    summary="world triangles: view and projection, clipping in clip space, divide, viewport, "
            "then rasterize, depth test and shade",
    inputs=TRIANGLES, options=PIPELINE_OPTIONS,
    code=lambda points, options: tuple(pipeline_code(options).lines), generator=pipeline,
    notes=("Points are world x, y (z from the z option): with the default camera the z = 0 "
           "plane faces the viewer, so triangles drawn on the grid appear much as drawn.",
           "Clip space: inside when -w <= x, y, z <= w; the near plane is z = -w.",
           "Attributes are interpolated perspective-correctly; depth is window z, linear "
           "on screen.",
           "Shading: colour = base (0.2 + 0.8 max(0, N.L)), L the light's direction reversed.",
           "A fragment's panel rows retrace it: its weights, then its clip, NDC and window "
           "coordinates from the corners of its fan triangle."),
    explain=explain, uses_grid=True,
    fragments=(("triangle", "@triangle"), ("depth", "depth"), ("w", "w"), ("u", "u"), ("v", "v"), ("color", "rgb")),
    oracle=Oracle(
        "reference",
        "Flat, Gouraud and Phong colours equal the shading formulas written in the test within 1.5 "
        "levels; the near clipping keeps exactly the part in front (Fractions), and a clipped run "
        "equals the unclipped one beyond the near plane. A triangle no plane cuts gives exactly "
        "the fragments of its projection, computed again in the test, with depths to 1e-9.",
        ("algorithms/pipeline/test_pipeline_reference.py",
         "algorithms/pipeline/test_pipeline_stages.py")),
)

# The module's algorithms, in the order they are listed.
SPECS = (BLEND_OVER, PIPELINE)
