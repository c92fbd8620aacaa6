"""Pseudo-code built line by line under names, so generators yield names, not numbers.

A family writes its pseudo-code once with ``Code.add(key, text, ...)`` and
its generator yields ``code.at[key]`` (or a local bound to it before a hot
loop): inserting a line then never shifts the lines the generator names.
A line that writes pixels is named ``plot...`` and only such lines are of
kind PLOT, so the name a generator yields says whether the frame plots.

Both rules are checked as the generator runs, for the shipped families and a
student's file alike: ``add`` refuses a line whose name and kind disagree,
and ``at`` refuses a name no line has.
"""
from __future__ import annotations

from algorithms.core.steps import CALC, PLOT, CodeLine

PLOT_PREFIX = "plot"


class LineNames(dict):
    """Line numbers by key; a key no line has is refused with its name."""

    def __missing__(self, key):
        known = ", ".join(self) or "none"
        raise ValueError(f"no pseudo-code line is named {key!r} (lines: {known})")


class Code:
    """Pseudo-code lines built by key, so generators can name lines by key."""

    def __init__(self):
        self.lines: list[CodeLine] = []
        self.at = LineNames()

    def add(self, key: str, text: str, kind: str = CALC, branch: str = "", ops=None,
            per=None, candidates=()) -> None:
        if key in self.at:
            raise ValueError(f"pseudo-code line {key!r} is defined twice")
        if (kind == PLOT) != key.startswith(PLOT_PREFIX):
            raise ValueError(f"pseudo-code line {key!r} is of kind {kind}; lines named "
                             f"{PLOT_PREFIX}... and only they are of kind {PLOT}")
        self.at[key] = len(self.lines)
        self.lines.append(CodeLine(text, kind, branch, tuple(candidates), ops=nonzero(ops or {}),
                                   per={k: nonzero(v) for k, v in (per or {}).items()}))

    def __len__(self) -> int:
        return len(self.lines)


def nonzero(counts: dict) -> dict:
    """Operation counts without the zero entries, equal names summed."""
    merged = {}
    for name, count in counts.items():
        if count:
            merged[name] = merged.get(name, 0) + count
    return merged


def listing(build):
    """A spec's ``code(points, options)`` from a function that builds a Code."""
    def code(points, options):
        return tuple(build(points, options).lines)
    code.__name__ = build.__name__
    return code

