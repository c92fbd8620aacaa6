"""Which branch each step of a run took, for the plot of its decision
variable: the dots are coloured by the branch the code line names (E or
NE, E or SE, ...), not by the value's sign, which picks the branch only
where ties go the same way as the sign (a tie d = 0 goes to NE in one
variant and to E in another, and some variants branch on D > 0)."""
from __future__ import annotations

import numpy as np

NO_BRANCH = -1


def decision_branches(trace) -> tuple[np.ndarray, tuple[str, str]]:
    """(codes, names): ``codes[i]`` is 0 when step i took the branch of
    the first candidate of its pair, 1 the second's, NO_BRANCH for a step
    that decides nothing; ``names`` are the two branches' names as the
    pseudo-code gives them ("E", "NE"; "E/S", "SE/SW" for a run with two
    pairs, such as the ellipse's two regions)."""
    by_line = np.full(len(trace.code), NO_BRANCH, dtype=np.int8)
    pairs = branch_pairs(trace)
    for k, line in enumerate(trace.code):
        if line.branch:
            position = pairs[candidate_offsets(trace, line)].index(line.branch)
            by_line[k] = position if position < 2 else NO_BRANCH
    first = "/".join(names[0] for names in pairs.values() if names)
    second = "/".join(names[1] for names in pairs.values() if len(names) > 1)
    return by_line[np.asarray(trace.line, dtype=np.int64)], (first, second)


def candidate_offsets(trace, line) -> tuple:
    """The candidate offsets frames on ``line`` (a CodeLine) decide between."""
    return tuple(line.candidates or getattr(trace.start, "candidates", ()) or ())


def branch_pairs(trace) -> dict[tuple, list[str]]:
    """{candidate offsets: the branch names of the lines deciding between
    them, in pseudo-code order}: the order of the candidates themselves
    (E then NE; E then SE, S then SW for the ellipse's second region)."""
    pairs: dict[tuple, list[str]] = {}
    for line in trace.code:
        if line.branch:
            names = pairs.setdefault(candidate_offsets(trace, line), [])
            if line.branch not in names:
                names.append(line.branch)
    return pairs
