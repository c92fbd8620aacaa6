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
    pairs: dict[tuple, list[str]] = {}
    default = tuple(getattr(trace.start, "candidates", ()) or ())
    for k, line in enumerate(trace.code):
        if not line.branch:
            continue
        names = pairs.setdefault(tuple(line.candidates or default), [])
        if line.branch not in names:
            names.append(line.branch)
        position = names.index(line.branch)
        if position < 2:
            by_line[k] = position
    first = "/".join(names[0] for names in pairs.values() if names)
    second = "/".join(names[1] for names in pairs.values() if len(names) > 1)
    return by_line[np.asarray(trace.line, dtype=np.int64)], (first, second)
