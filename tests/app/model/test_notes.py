"""The note in force at a step: brief notes end when the run leaves their line."""
import numpy as np

from algorithms.core.steps import Note
from app.model.notes import note_at
from tests.support import record

# Two horizontal edges: the scan-line fill notes that it leaves them out.
SQUARE = [[(2, 2), (10, 2), (10, 8), (2, 8)]]


def test_the_left_out_note_shows_while_the_edge_table_is_built_only():
    trace = record("polygon-scanline", SQUARE, grid=(16, 12))
    notes = trace.steps_of(Note).tolist()
    assert len(notes) == 1 and "left out" in trace.record_at(notes[0]).text
    line = trace.record_at(notes[0]).line
    shown = [i for i in range(len(trace)) if note_at(trace, notes, i) is not None]
    # From the note's step through the steps on the same line, then never.
    assert shown[0] == notes[0] and shown == list(range(notes[0], shown[-1] + 1))
    assert all(int(trace.line[i]) == line for i in shown)
    assert int(trace.line[shown[-1] + 1]) != line
    assert len(shown) < len(trace) // 4


class _Run:
    """A trace's two queries note_at reads: line numbers and records."""

    def __init__(self, lines, records):
        self.line = np.array(lines)
        self.records = records

    def record_at(self, i):
        return self.records.get(i)


def test_a_lasting_note_holds_until_the_next_note():
    run = _Run([0, 1, 1, 2, 2, 3], {1: Note(line=1, text="a"), 4: Note(line=2, text="b")})
    assert [note_at(run, [1, 4], i) for i in range(6)] == [None, 1, 1, 1, 4, 4]
    brief = _Run(run.line, {1: Note(line=1, text="a", brief=True)})
    assert [note_at(brief, [1], i) for i in range(6)] == [None, 1, 1, None, None, None]
