"""Which of a run's notes speaks for a step (the window's status line)."""
from __future__ import annotations

import bisect


def note_at(trace, note_steps: list[int], index: int) -> int | None:
    """The step of the note in force at step ``index``, or None.

    A note holds from its step until the next note; a brief one only while
    the run stays on the note's own pseudo-code line (a remark about
    building the edge table is done once the scan lines start).
    """
    k = bisect.bisect_right(note_steps, index) - 1
    if k < 0:
        return None
    step = note_steps[k]
    note = trace.record_at(step)
    if getattr(note, "brief", False) and (trace.line[step + 1:index + 1] != note.line).any():
        return None
    return step
