"""The diff pair of compare mode never names one pane twice."""
import pytest

from app.model.compare import diff_pair


@pytest.mark.parametrize("old, a, b, count, expected", [
    ((0, 1), 1, 1, 2, (1, 0)),   # A picks B's pane: swapped
    ((0, 1), 0, 0, 2, (1, 0)),   # B picks A's pane: swapped
    ((0, 2), 2, 2, 3, (2, 0)),
    ((1, 2), 1, 1, 4, (2, 1)),
    ((0, 1), 3, 1, 4, (3, 1)),   # different panes: as picked
    ((0, 1), 0, 9, 3, (0, 2)),   # out of range: the last pane
    ((0, 0), 0, 0, 3, (1, 0)),   # an old pair that was already one pane is mended
])
def test_a_pane_is_never_diffed_against_itself(old, a, b, count, expected):
    assert diff_pair(old, a, b, count) == expected
