"""The order of the Variables panel's rows: what the step decides and
changes first, the rest of the run's variables next, the constants last
(the panel folds them away).

A lecture at 1280 x 720 has room for a handful of rows: those must be the
decision variable, the branch chosen, the reasoning and its update, not the
run's set-up values (dx, dy, incrE, ...). The order is the same on every
step, so that a row stays where the eye found it.
"""
from __future__ import annotations

from dataclasses import dataclass

CHOICE = "choice"  # the branch a decision took (algorithms/core/trace.py)


@dataclass(frozen=True)
class RowOrder:
    decision: str | None = None  # the run's decision variable, if any
    variables: frozenset = frozenset()  # names the run sets, constants included
    constants: frozenset = frozenset()  # names the run never changes

    @classmethod
    def of(cls, trace) -> "RowOrder":
        """The order for ``trace``'s rows (an empty order without a run)."""
        if trace is None:
            return cls()
        start, final = trace.start.constants, trace.final_variables()
        moving = set(trace.value_names)
        constants = frozenset(name for name, value in start.items()
                              if name not in moving and _same(final.get(name), value))
        return cls(trace.start.decision, frozenset(final) | moving, constants)

    def arrange(self, rows) -> list:
        """``rows`` (name, text) in the panel's order: the decision variable,
        the branch chosen and the step's own explanation rows (names that
        are no variable: decision, update), then the other variables, then
        the constants; each group keeps the order it came in."""
        def rank(row) -> int:
            name = row[0]
            if name in self.constants:
                return 3
            if name == self.decision:
                return 0
            if name == CHOICE or name not in self.variables:
                return 1
            return 2
        return sorted(rows, key=rank)


def _same(a, b) -> bool:
    try:
        return bool(a == b)
    except (TypeError, ValueError):  # arrays: an answer per element
        return False
