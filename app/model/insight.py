"""Read-outs that make a step's numbers readable at a glance.

Keyed on value *names*, never on algorithm names, so that any algorithm
that calls its edge functions e0, e1, e2 or its barycentric weights alpha,
beta, gamma gets them:

* ``row_tones``: a tone for a variables-panel row whose sign matters
  (an edge value's sign, a weight inside or outside [0, 1]);
* ``inside_chips``: a one-line summary of the step: each edge's sign, each
  weight, whether the pixel centre is inside, and what the step did;
* ``PixelTally``: pixels tested and filled so far in the run.

Nothing here imports Qt.
"""
from __future__ import annotations

import re
from fractions import Fraction

import numpy as np

from algorithms.core.steps import NO_PIXEL, PLOT, VISIT

POSITIVE, NEGATIVE, ZERO, INFO = "positive", "negative", "zero", "info"
IN, OUT = "in", "out"

EDGE = re.compile(r"^e(\d)$")
WEIGHTS = ("alpha", "beta", "gamma")
GREEK = {"alpha": "\u03b1", "beta": "\u03b2", "gamma": "\u03b3"}


def _base(name: str) -> str:
    """'e0 exactly' -> 'e0'; 'alpha_p' -> 'alpha'."""
    first = name.split()[0] if name.split() else name
    return first[:-2] if first.endswith("_p") else first


def _number(text) -> float | None:
    if isinstance(text, bool):
        return None
    if isinstance(text, (int, float)):
        return float(text)
    try:
        return float(Fraction(str(text).strip()))
    except (ValueError, ZeroDivisionError):
        return None


def row_tones(rows) -> dict[str, str]:
    """Tones for rows (name, text): edge values by sign, weights by range."""
    tones = {}
    for name, text in rows:
        base = _base(name)
        value = _number(text)
        if value is None:
            continue
        if EDGE.match(base):
            tones[name] = POSITIVE if value > 0 else NEGATIVE if value < 0 else ZERO
        elif base in WEIGHTS:
            tones[name] = POSITIVE if 0 <= value <= 1 else NEGATIVE
    return tones


def has_insight(value_names) -> bool:
    """Does a run name edge values or barycentric weights?"""
    return any(EDGE.match(name) or name in WEIGHTS for name in value_names)


def inside_chips(values: dict, kind: str) -> list[tuple[str, str, str]]:
    """(text, tone, tooltip) chips for one step's values, or [] when the
    step has neither edge values nor weights.

    The verdict reads the signs the way the half-plane test does: a centre
    is inside when all edge values have the same sign (positive for a
    counter-clockwise triangle, negative for a clockwise one), outside when
    they disagree, and on an edge, for the fill rule to decide, when one is
    zero. ``kind`` (the step's line kind) says what the step did with it.
    """
    edges = sorted((name, float(v)) for name, v in values.items() if EDGE.match(name))
    weights = [(name, float(values[name])) for name in WEIGHTS if name in values]
    if not edges and not weights:
        return []
    chips = []
    for name, value in edges:
        tone = POSITIVE if value > 0 else NEGATIVE if value < 0 else ZERO
        sign = ">" if value > 0 else "<" if value < 0 else "="
        chips.append((f"{name} {sign} 0", tone, f"{name} = {value:g}"))
    for name, value in weights:
        tone = POSITIVE if 0 <= value <= 1 else NEGATIVE
        chips.append((f"{GREEK[name]} {value:.3g}", tone,
                      f"{name} = {value!r} ({'inside' if tone == POSITIVE else 'outside'} [0, 1])"))
    verdict = _verdict(edges, weights)
    if verdict:
        chips.append(verdict)
    if kind == PLOT:
        chips.append(("filled", IN, "this step writes the pixel"))
    elif kind == VISIT:
        chips.append(("not filled", OUT, "this step tests the pixel and leaves it"))
    return chips


def _verdict(edges, weights):
    if edges:
        signs = {(v > 0) - (v < 0) for _, v in edges}
        zeros = [name for name, v in edges if v == 0]
        if {1, -1} <= signs:
            majority = 1 if sum(v > 0 for _, v in edges) * 2 > len(edges) else -1
            odd = [name for name, v in edges if v and (v > 0) - (v < 0) != majority]
            return ("outside", OUT, f"the signs disagree ({', '.join(odd)}): the centre "
                                    "lies on the outer side of that edge")
        if zeros:
            return (f"on {', '.join(zeros)}", ZERO, "the centre lies exactly on the edge: "
                                                    "the fill rule decides")
        return ("inside", IN, "all edge values have the same sign: the centre is inside")
    inside = all(0 <= v <= 1 for _, v in weights)
    return ("inside" if inside else "outside", IN if inside else OUT,
            "all weights in [0, 1]" if inside else "a weight lies outside [0, 1]")


class PixelTally:
    """Pixels tested (looked at, then written or left) and filled (written)
    up to any step of a trace, from cumulative counts made once."""

    def __init__(self, trace):
        kinds = np.array([line.kind for line in trace.code])
        has_pixel = trace.x != NO_PIXEL
        rich = np.zeros(len(trace), dtype=bool)
        rich[trace.steps_of()] = True
        kind = kinds[trace.line]
        filled = (kind == PLOT) & has_pixel & ~rich
        tested = filled | ((kind == VISIT) & has_pixel & ~rich)
        self._filled = np.cumsum(filled)
        self._tested = np.cumsum(tested)

    def at(self, index: int) -> tuple[int, int]:
        """(tested, filled) up to and including step ``index``."""
        return int(self._tested[index]), int(self._filled[index])
