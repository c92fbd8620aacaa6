"""The closed set of step records an algorithm generator may yield.

A generator yields one frame per step a person can step to. Frames come in
two shapes:

* A *lean frame*: a plain tuple ``(line, x, y, v1, v2, ...)`` of numbers:
  integers ``line``, ``x`` and ``y``, real numbers ``v1, v2, ...``.
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

from dataclasses import dataclass, field, fields
from operator import attrgetter
from typing import Mapping

# Kinds of pseudo-code line. A frame takes the kind of the line it names.
PLOT = "plot"    # the frame writes pixel (x, y)
VISIT = "visit"  # the frame looks at pixel (x, y) but does not write it
CALC = "calc"    # the frame only updates variables
KINDS = (PLOT, VISIT, CALC)

# Stored for x and y when a frame has no pixel.
NO_PIXEL = -(2 ** 31)

# Operations a pseudo-code line can be annotated with (CodeLine.ops), for
# the counts the speed/error report makes. Additions include subtractions
# and increments; round counts every float-to-integer conversion (floor,
# round, a cast); compare counts every test and loop condition;
# pixels_tested counts pixels whose inside/outside state is looked at;
# samples counts sample points evaluated (antialiasing).
OP_NAMES = ("int_add", "float_add", "mul", "div", "sqrt", "round", "compare",
            "pixels_tested", "samples")
# Quantities ``CodeLine.per`` may scale by, besides a value or constant name.
PER_PIXEL = "pixel"  # each pixel of the frame's Span run
PER_ROW = "row"      # each row of the frame's Table


@dataclass(frozen=True, slots=True)
class CodeLine:
    """One line of an algorithm's pseudo-code."""

    text: str
    kind: str = CALC
    branch: str = ""  # the decision outcome this line stands for, e.g. "E"
    # Candidate offsets for frames on this line, where they differ from
    # Start.candidates (a two-region algorithm has two pairs of them).
    candidates: tuple[tuple[int, int], ...] = ()
    # Operations one execution of the line performs ({"int_add": 2,
    # "compare": 1}, names from OP_NAMES). Every frame on the line is one
    # execution; Note records are commentary and execute nothing. Work of
    # a loop header that yields no frame of its own is counted on the
    # line of the loop body that does.
    ops: Mapping[str, int] = field(default_factory=dict, compare=False)
    # Work that grows with a quantity of the frame: {quantity: ops per
    # unit}. The quantity is PER_PIXEL (the pixels of a Span run), PER_ROW
    # (the rows of a Table), or the name of a value of the frame or of a
    # Start constant (the number of active edges, of vertices, ...).
    per: Mapping[str, Mapping[str, int]] = field(default_factory=dict, compare=False)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"unknown code-line kind {self.kind!r}")
        for counts in (self.ops, *self.per.values()):
            for name, count in counts.items():
                if name not in OP_NAMES:
                    raise ValueError(f"unknown operation {name!r}; use one of {', '.join(OP_NAMES)}")
                if not isinstance(count, int) or count < 0:
                    raise ValueError(f"operation {name}: {count!r} is not a count")


@dataclass(frozen=True, slots=True, kw_only=True)
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
    # Name of the value holding the packed 0xRRGGBB colour for the colour
    # buffer, where that is not pixel_value itself: an antialiasing run names
    # its coverage (0..1) as pixel_value and a blended colour here.
    color_value: str | None = None
    # Name of the value a PLOT frame writes into the per-pixel depth buffer
    # (Raster.depth), for runs that keep one (the z-buffer).
    depth_value: str | None = None
    # True when a write replaces the pixel's picture, as the frames of an
    # animation do: a pixel written again is then not overdraw.
    replaces: bool = False
    # A second per-pixel buffer the run keeps besides the colour buffer
    # (the accumulation buffer of supersampling, a stencil): the value that
    # sets it and the buffer's name. Any frame with a pixel and a value
    # there sets it, written or not; a Vars record whose "cleared" names the
    # buffer clears it (app/model/buffers.py shows it at any step).
    buffer_value: str | None = None
    buffer_name: str = ""
    # Names of further values that hold packed 0xRRGGBB colours (a blend's
    # source and destination): panels and exports show them as #rrggbb.
    colour_values: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True, kw_only=True)
class Vars:
    """A batch of named variables set at this frame."""

    line: int
    values: Mapping[str, object]
    pixel: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True, kw_only=True)
class Table:
    """A snapshot of a table (edge table, active edge table, ...)."""

    line: int
    name: str
    columns: tuple[str, ...]
    rows: tuple[tuple, ...]
    pixel: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True, kw_only=True)
class Note:
    """A sentence worth showing at this frame.

    A note holds until the next one, unless it is ``brief``: then it speaks
    of its own pseudo-code line only, and is done once the run moves on to
    another line."""

    line: int
    text: str
    pixel: tuple[int, int] | None = None
    brief: bool = False


@dataclass(frozen=True, slots=True, kw_only=True)
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


def _quick_state(cls) -> None:
    """A slotted dataclass pickles through ``dataclasses.fields()`` on every
    instance, which costs more than the rest of recording a rich record;
    one C-level attrgetter gives the same state (the fields' values, in
    order) for the dataclass's own ``__setstate__``."""
    state = attrgetter(*(f.name for f in fields(cls)))  # every record has two fields or more
    cls.__getstate__ = lambda self: state(self)


for _record in RICH_RECORDS:
    _quick_state(_record)


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
