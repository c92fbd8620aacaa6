"""Which branch each step of a run took, for the plot of its decision
variable: the dots are coloured by the branch the code line names (E or
NE, E or SE, ...), not by the value's sign, which picks the branch only
where ties go the same way as the sign (a tie d = 0 goes to NE in one
variant and to E in another, and some variants branch on D > 0). A
decision may have any number of branches (an ear, a reflex vertex or a
blocked ear; hit, miss or split)."""
from __future__ import annotations

import numpy as np

NO_BRANCH = -1


def decision_branches(trace) -> tuple[np.ndarray, tuple[str, ...]]:
    """(codes, names): ``codes[i]`` is k when step i took the k-th branch
    of its decision, NO_BRANCH for a step that decides nothing; ``names``
    are the branches' names as the pseudo-code gives them, in that order
    ("E", "NE"; "E/S", "SE/SW" for a run with two decisions, such as the
    ellipse's two regions, whose k-th branches share a colour)."""
    by_line = np.full(len(trace.code), NO_BRANCH, dtype=np.int8)
    groups = branch_groups(trace)
    for k, line in enumerate(trace.code):
        if line.branch:
            by_line[k] = groups[candidate_offsets(trace, line)].index(line.branch)
    count = max((len(names) for names in groups.values()), default=0)
    names = tuple("/".join(group[k] for group in groups.values() if len(group) > k)
                  for k in range(count))
    return by_line[np.asarray(trace.line, dtype=np.int64)], names


def candidate_offsets(trace, line) -> tuple:
    """The candidate offsets frames on ``line`` (a CodeLine) decide between."""
    return tuple(line.candidates or getattr(trace.start, "candidates", ()) or ())


def branch_groups(trace) -> dict[tuple, list[str]]:
    """{candidate offsets: the branch names of the lines deciding between
    them, in pseudo-code order}: the order of the candidates themselves
    (E then NE; E then SE, S then SW for the ellipse's second region).
    A decision without candidate pixels is grouped under ()."""
    groups: dict[tuple, list[str]] = {}
    for line in trace.code:
        if line.branch:
            names = groups.setdefault(candidate_offsets(trace, line), [])
            if line.branch not in names:
                names.append(line.branch)
    return groups
