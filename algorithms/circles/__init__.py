"""The circle family: circles and ellipses around a centre, and curves.

``midpoint``  4- and 8-way symmetry, the midpoint circle and the midpoint ellipse
``variants``  Bresenham's circle and the other printed circle listings
``curves``    circles from real centres and radii, and curves beyond circles
``batch``     many midpoint circles at once, for large workloads
"""
from __future__ import annotations

from . import midpoint, variants, curves

# The family's algorithms, in the order they are listed.
SPECS = midpoint.SPECS + variants.SPECS + curves.SPECS
