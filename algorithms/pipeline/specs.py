"""The pipeline family's entries in the registry."""
from __future__ import annotations

from algorithms import registry as registry_module
from algorithms.registry import AlgorithmSpec, register
from algorithms.visibility import COLORS, FILL_RULE, TRIANGLES, Z

from .blend import ALPHA, DEPTH_WRITE, ORDER, blend, blend_code

# The families before this one register first (see triangles/specs.py).
registry_module.all_specs()

register(AlgorithmSpec(
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
    fragments=(("z", "z"), ("alpha", "alpha"), ("source", "src"), ("before", "dst"),
               ("color", "rgb"))))
