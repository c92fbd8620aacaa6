"""Helpers shared by the tests of every package."""
from pathlib import Path

from algorithms.core import registry

# The project's top folder: resources, README.md and the packages live here.
ROOT = Path(__file__).resolve().parents[2]


def record(name, points, options=None, grid=(32, 24), monitor=None):
    """The trace of one run of algorithm ``name``, recorded as the program
    records it (options are resolved against the algorithm's defaults)."""
    return registry.get(name).record(points, options, grid, monitor=monitor)
