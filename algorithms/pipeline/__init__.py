"""The pipeline family: what happens around rasterization. Blending transparent surfaces
(blend.py); the 3-D scene through transform, clipping, projection and shading (scene.py,
clip.py, stages.py)."""
from .specs import SPECS  # noqa: F401  (the family's algorithms)
