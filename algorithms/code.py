"""Pseudo-code built line by line under names, so generators yield names, not numbers.

A family writes its pseudo-code once with ``Code.add(key, text, ...)`` and
its generator yields ``code.at[key]`` (or a local bound to it before a hot
loop): inserting a line then never shifts the lines the generator names.
"""
from __future__ import annotations

from .steps import CALC, CodeLine


class Code:
    """Pseudo-code lines built by key, so generators can name lines by key."""

    def __init__(self):
        self.lines: list[CodeLine] = []
        self.at: dict[str, int] = {}

    def add(self, key: str, text: str, kind: str = CALC, branch: str = "", ops=None,
            per=None, candidates=()) -> None:
        if key in self.at:
            raise ValueError(f"pseudo-code line {key!r} is defined twice")
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
