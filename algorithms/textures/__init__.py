"""The textures family: textured triangles (uv, w), texture filters and mip-maps.

See texels.py (textures and their pyramids), sampling.py (the mapping, the
level of detail and the filters) and triangle.py (the traversal).
"""
from .specs import SPECS  # noqa: F401  (the family's algorithms)
