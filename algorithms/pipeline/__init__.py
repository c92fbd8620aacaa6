"""The pipeline family: what happens around rasterization. Blending transparent surfaces
(blend.py); the 3-D scene through model, view, projection, clipping, divide, viewport,
rasterization and shading (space.py, stages.py)."""
from .specs import SPECS  # noqa: F401  (the family's algorithms)
