"""What a finished recording gives the session, and what the session says of it."""
from __future__ import annotations

from dataclasses import dataclass

from algorithms.core.errors import InputError
from algorithms.core.raster import Raster
from algorithms.core.trace import FrameState, Trace

from .scene import Scene

CANCELLED_MESSAGE = "Recording cancelled: the previous scene and run are kept."


@dataclass
class Outcome:
    """A finished recording: the scene it was made of (an example shape
    when the algorithm refused the points), the algorithm compared against,
    its trace and replay cache."""

    scene: Scene
    previous: tuple | None
    trace: Trace | None
    final: Raster | None
    comparison: tuple | None = None
    compare_enabled: bool = False
    refusal: str | None = None  # None: not an algorithm switch
    last_state: FrameState | None = None


def example_note(spec, reason: str) -> str:
    return (f"{spec.title} refused the points drawn before ({reason}); "
            "showing an example shape instead.")


def kept_note(spec, grid, reason: str) -> str:
    return (f"{spec.title}: neither the points drawn nor its example shape can run on the "
            f"{grid[0]}x{grid[1]} grid ({reason}); the points are kept: add or move points, "
            "enlarge the grid or change the options.")


def failure(error: BaseException) -> str:
    """A failed recording's message: never empty (empty means installed)."""
    return str(error) if isinstance(error, InputError) and str(error) else \
        f"The run failed ({type(error).__name__}: {error}); the previous scene is kept."
