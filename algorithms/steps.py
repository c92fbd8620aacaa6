"""The closed set of step records an algorithm generator may yield.

A generator yields one frame per step a person can step to. Frames come in
two shapes:

* A *lean frame*: a plain tuple ``(line, x, y, v1, v2, ...)`` of numbers.
  ``line`` is the index of the pseudo-code line being run; its kind (see
  ``CodeLine.kind``) says what the frame does to pixel ``(x, y)``. The values
  ``v1, v2, ...`` are named once, by the ``Start`` record. Lean frames are
  plain tuples because they are recorded in bulk (millions of them) and a
  tuple of numbers is the cheapest thing Python can yield.
* A *rich record*: one of the frozen dataclasses below, for things that do
  not fit in a few numbers (the start of a run, a batch of named variables,
  a table snapshot, a note).

Every generator's first frame is a ``Start`` record.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

# Kinds of pseudo-code line. A frame takes the kind of the line it names.
PLOT = "plot"    # the frame writes pixel (x, y)
VISIT = "visit"  # the frame looks at pixel (x, y) but does not write it
CALC = "calc"    # the frame only updates variables
KINDS = (PLOT, VISIT, CALC)

# Stored for x and y when a frame has no pixel.
NO_PIXEL = -(2 ** 31)


@dataclass(frozen=True, slots=True)
class CodeLine:
    """One line of an algorithm's pseudo-code."""

    text: str
    kind: str = CALC
    branch: str = ""  # the decision outcome this line stands for, e.g. "E"
    # Candidate offsets for frames on this line, where they differ from
    # Start.candidates (a two-region algorithm has two pairs of them).
    candidates: tuple[tuple[int, int], ...] = ()

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"unknown code-line kind {self.kind!r}")


@dataclass(frozen=True, slots=True)
class Start:
    """First frame of every run: names the values of the lean frames."""

    line: int
    values: tuple[str, ...] = ()
    constants: Mapping[str, object] = field(default_factory=dict)
    # Name of the value written into a plotted pixel (a packed 0xRRGGBB
    # colour), or None when pixels take the primitive's ink colour.
    pixel_value: str | None = None
    # Offsets from the previous frame's pixel to the pixels a decision
    # chooses between (Bresenham's E and NE), for highlighting.
    candidates: tuple[tuple[int, int], ...] = ()
    # Name of the value whose sign or size decides the branch, if any.
    decision: str | None = None


@dataclass(frozen=True, slots=True)
class Vars:
    """A batch of named variables set at this frame."""

    line: int
    values: Mapping[str, object]
    pixel: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True)
class Table:
    """A snapshot of a table (edge table, active edge table, ...)."""

    line: int
    name: str
    columns: tuple[str, ...]
    rows: tuple[tuple, ...]
    pixel: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True)
class Note:
    """A sentence worth showing at this frame."""

    line: int
    text: str
    pixel: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True)
class Span:
    """A run of pixels x_start .. x_end - 1 on row y, written at once.

    It writes only when its code line is a PLOT line, like a lean frame.
    ``value`` is the packed colour written into every pixel of the run when
    the run writes values (``Start.pixel_value``); None writes no colour.
    """

    line: int
    y: int
    x_start: int
    x_end: int
    value: float | None = None

    @property
    def pixel(self):
        # The first pixel of the run stands for the frame's position.
        return (self.x_start, self.y) if self.x_end > self.x_start else None


RICH_RECORDS = (Start, Vars, Table, Note, Span)


@dataclass(frozen=True, slots=True)
class Step:
    """A decoded frame, as panels and the command line see it."""

    index: int
    line: int
    kind: str
    pixel: tuple[int, int] | None
    values: Mapping[str, float]
    branch: str = ""
    record: object | None = None

    @property
    def writes(self) -> bool:
        """Does this step write its one pixel? (A Span writes its own run.)"""
        return self.kind == PLOT and self.pixel is not None and self.record is None
