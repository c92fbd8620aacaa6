"""Which wrapped row of the pseudo-code an exported frame's code panel
starts at when the code does not fit: always the first row of a line (a
line cut at its top reads as nonsense, "= (b - a) / |b - a|"), with the
current line in view."""
from types import SimpleNamespace

import pytest

from app.render.text import TextParts


def first_row(lengths, current, room):
    # The rows of each code line, as the panel wrapped them (their text does not matter).
    panel = SimpleNamespace(wrapped=[["row"] * n for n in lengths])
    return TextParts._first_row(panel, current, room)


def line_starts(lengths):
    starts = [0]
    for n in lengths:
        starts.append(starts[-1] + n)
    return starts


@pytest.mark.parametrize("lengths, current, room", [
    ([2, 2, 2, 2, 1, 3, 1, 1], 7, 13),  # line-two-triangles at its last step: one row short
    ([2, 2, 2, 1, 1, 2, 1, 1], 7, 8),
    ([3, 1, 1, 1, 2, 1], 5, 6),
    ([2, 2, 2, 2, 2, 2], 3, 5),
    ([1, 1, 1, 1, 1, 1, 1, 1], 6, 4),
])
def test_the_panel_starts_on_a_line_and_shows_the_current_line(lengths, current, room):
    start = first_row(lengths, current, room)
    starts = line_starts(lengths)
    assert start in starts
    assert start <= starts[current] and starts[current] + lengths[current] <= start + room


def test_code_that_fits_starts_at_the_top():
    assert first_row([2, 1, 1], 2, 10) == 0
