"""A step of a run in words, for a screen reader and for transcripts.

``describe(trace, i)`` says what step ``i`` does in one sentence, from the
trace's own records: "step 5 of 7: d = 1, above 0, so NE: plot (4, 2)".
The window announces it when a person steps, ``rasterlab run --describe``
prints one per line, and export writes them beside a GIF (``.txt``) or a
video (WebVTT captions). ``describe_steps(trace)`` gives one per step index.

Each family's steps are recognised by what their records hold, most
telling first:

* a decision (Bresenham's lines, the midpoint circle): the decision
  variable, how it compares with the threshold the pseudo-code tests,
  the branch taken and the pixel;
* a depth test (the z-buffer): the fragment's z against the buffer's;
* the edge functions of a triangle at a pixel: inside or outside, and
  the edge values that decide it;
* a span of the scan-line fill: the scan line, the crossings of the
  active edges and the pixels filled between them;
* a pixel written with a coverage (antialiasing): the coverage;
* anything else: the pseudo-code line, the pixel and the values of the step.

``numbers`` is the display setting of ``app/model/notation.py``: "exact"
reads a value the run keeps exactly (an ET's x, a barycentric weight) as p/q.
"""
from __future__ import annotations

import re

from algorithms.core.steps import PLOT, VISIT, Span, Table

from app.model.exact import exact_values
from app.model.notation import checked_numbers, colour, colour_names, number, tidy

# "if d <= 0", "if d < 0", "if e >= dx": the test a decision line makes.
_TEST = re.compile(r"\bif\s+(?P<name>[A-Za-z_]\w*)\s*(?P<op><=|<|>=|>)\s*(?P<bound>-?\d+(?:\.\d+)?)\b")
# The words for a value that passes (first) or fails (second) each test.
_RELATIONS = {"<=": ("at most", "above"), "<": ("below", "at least"),
              ">=": ("at least", "below"), ">": ("above", "at most")}
# A remark closing a pseudo-code line: "plot(x, y)   (offsets; ...)".
_REMARK = re.compile(r"\s+\([^()]*\)$")
EDGES = ("e0", "e1", "e2")
COVERAGE_NAMES = ("coverage", "intensity", "alpha")


def describe_steps(trace, numbers: str = "decimal") -> list[str]:
    """One description per step index of ``trace``."""
    return [describe(trace, i, numbers) for i in range(len(trace))]


def describe(trace, i: int, numbers: str = "decimal") -> str:
    """Step ``i`` of ``trace`` in one sentence (see the module text)."""
    checked_numbers(numbers)
    step = trace.step(i)
    variables = trace.variables_at(i)
    if numbers == "exact":
        variables.update(exact_values(trace, i, variables))
    words = _Words(trace, step, variables, numbers)
    for family in (words.decision, words.depth, words.edges, words.span, words.coverage):
        text = family()
        if text:
            break
    else:
        text = words.plain()
    return f"step {i} of {len(trace) - 1}: {text}"


class _Words:
    """The words of one step, by family; each returns "" when the step is not its kind."""

    def __init__(self, trace, step, variables: dict, numbers: str):
        self.trace, self.step, self.variables, self.numbers = trace, step, variables, numbers
        self.start = trace.start
        self.code = trace.code[step.line]

    def value(self, name: str) -> str:
        value = self.variables[name]
        if name in colour_names(self.start) and isinstance(value, (int, float)):
            return colour(value) or number(value, numbers=self.numbers)
        return number(value, numbers=self.numbers)

    def where(self) -> str:
        """What the step does to its pixel: "plot (5, 2)", "visit (3, 1)", or ""."""
        pixel = self.step.pixel
        if pixel is None:
            return ""
        verb = ("plot" if self.step.kind == PLOT else "visit" if self.step.kind == VISIT
                else "now at")
        return f"{verb} ({pixel[0]}, {pixel[1]})"

    # ------------------------------------------------------------ families
    def decision(self) -> str:
        name = getattr(self.start, "decision", None)
        if not self.step.branch or name not in self.variables:
            return ""
        text = f"{name} = {self.value(name)}"
        test = self._test(name)
        value = self.variables[name]
        if test is not None and isinstance(value, (int, float)):
            op, bound = test
            passes, fails = _RELATIONS[op]
            holds = _compare(value, op, bound)
            text += f", {passes if holds else fails} {number(bound)}"
        text += f", so {self.step.branch}"
        where = self.where()
        return f"{text}: {where}" if where else text

    def _test(self, name: str):
        """(operator, bound) of the test the pseudo-code makes on ``name``, if it makes one."""
        for line in (self.code, *self.trace.code):
            found = _TEST.search(line.text)
            if found and found["name"] == name:
                return found["op"], float(found["bound"])
        return None

    def depth(self) -> str:
        depth = getattr(self.start, "depth_value", None)
        if depth not in self.variables or "zb" not in self.variables or self.step.pixel is None:
            return ""
        x, y = self.step.pixel
        passed = self.step.kind == PLOT
        verdict = ("the depth test passes: colour and depth written" if passed
                   else "the depth test fails: the pixel keeps what it has")
        return (f"fragment at ({x}, {y}): {depth} = {self.value(depth)} against "
                f"ZB = {self.value('zb')}, {verdict}")

    def edges(self) -> str:
        if self.step.pixel is None or not all(name in self.variables for name in EDGES):
            return ""
        values = {name: self.variables[name] for name in EDGES}
        if not all(isinstance(value, (int, float)) for value in values.values()):
            return ""
        x, y = self.step.pixel
        listed = ", ".join(f"{name} = {self.value(name)}" for name in EDGES)
        # Inside is the side of the triangle's own winding: all edge values
        # of 2A's sign (a clockwise triangle's are all negative inside).
        area = self.variables.get("2A", 1)
        sign = -1 if isinstance(area, (int, float)) and area < 0 else 1
        wrong = [name for name in EDGES if sign * values[name] < 0]
        on_edge = [name for name in EDGES if values[name] == 0]
        if self.step.kind == PLOT:
            why = "inside: no edge value has the wrong sign"
            if on_edge:
                why += f", and the fill rule keeps a centre on edge {', '.join(on_edge)}"
            return f"pixel ({x}, {y}): {listed}; {why}, so plot it"
        if wrong:
            why = f"outside: {', '.join(wrong)} {'is' if len(wrong) == 1 else 'are'} " \
                  f"{'negative' if sign > 0 else 'positive'}"
        elif on_edge:
            why = f"on edge {', '.join(on_edge)}, and the fill rule leaves it out"
        else:
            why = "not written"
        return f"pixel ({x}, {y}): {listed}; {why}"

    def span(self) -> str:
        record = self.step.record
        if not isinstance(record, Span):
            return ""
        first, last = record.x_start, record.x_end - 1
        verb = "fill" if self.step.kind == PLOT else "scan"
        run = (f"{verb} pixels {first} to {last} of row {record.y}" if last > first
               else f"{verb} pixel {first} of row {record.y}" if last == first
               else f"nothing to fill on row {record.y}")
        crossings = self._crossings(record.y)
        if crossings:
            run = (f"scan line y = {record.y} + 1/2 crosses the edges at x = "
                   f"{', '.join(crossings)}; {run}")
        return run

    def _crossings(self, y: int) -> list[str]:
        """The x of each active edge on row ``y``, from the latest AET (an
        edge whose ymax is this row has left it: no crossing)."""
        found = self.trace.last_of(Table, at=self.step.index)
        hops = 0
        while found is not None and found[1].name != "AET" and hops < 8:
            found = self.trace.last_of(Table, at=found[0] - 1) if found[0] > 0 else None
            hops += 1
        if found is None or found[1].name != "AET":
            return []
        columns = found[1].columns
        if "x" not in columns or "ymax" not in columns:
            return []
        x, top = columns.index("x"), columns.index("ymax")
        return [_crossing(row[x], self.numbers) for row in found[1].rows if row[top] > y]

    def coverage(self) -> str:
        value_name = getattr(self.start, "pixel_value", None)
        name = next((n for n in (value_name, *COVERAGE_NAMES)
                     if n in self.variables and n not in colour_names(self.start)), None)
        if name is None or self.step.pixel is None or self.step.kind != PLOT:
            return ""
        if value_name is None or value_name in colour_names(self.start):
            return ""  # a run that writes colours, not coverages
        x, y = self.step.pixel
        branch = f"{self.step.branch} pixel " if self.step.branch else "pixel "
        return f"{branch}({x}, {y}) gets coverage {name} = {self.value(name)}"

    def plain(self) -> str:
        text = _line_text(self.code.text)
        where = self.where()
        shown = [name for name in self.step.values if name in self.variables][:4]
        values = ", ".join(f"{name} = {self.value(name)}" for name in shown)
        parts = [text] + ([where] if where else []) + ([values] if values else [])
        return "; ".join(parts)


def _compare(value: float, op: str, bound: float) -> bool:
    return {"<=": value <= bound, "<": value < bound, ">=": value >= bound,
            ">": value > bound}[op]


def _crossing(cell, numbers: str) -> str:
    """An AET's x as text: the integer edge walk keeps it as (whole, "e/dy")."""
    if isinstance(cell, (tuple, list)) and len(cell) == 2:
        whole, error = cell
        return f"{whole} + {error}"
    return number(cell, numbers=numbers)


def _line_text(text: str) -> str:
    """A pseudo-code line as one spoken phrase: whitespace collapsed, a
    closing remark in brackets and a block's colon left out (the window
    shows them; read aloud after every step they drown the step)."""
    text = _REMARK.sub("", " ".join(text.split())).rstrip(" :")
    return tidy(text)
