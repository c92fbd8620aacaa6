"""Work a run does before its first frame, or between two frames, stays small or
hears a cancel: big buffers are not filled up front, long passes check in."""
import os

import pytest

from algorithms.registry import get
from algorithms.trace import Cancelled, RecordMonitor, watching

BIG = (4096, 4096)  # 16M pixels: a filled float64 buffer is 128 MiB
TRIANGLE = [(10.0, 10.0), (30.0, 12.0), (20.0, 28.0)]


def _resident_bytes() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _growth_until_first_pixel(name, points, options, grid) -> int:
    """Resident memory the run's generator gains up to its first pixel frame."""
    spec = get(name)
    frames = spec.generator(points, spec.resolve(options), grid)
    before = _resident_bytes()
    for frame in frames:
        if type(frame) is tuple:
            break
    grown = _resident_bytes() - before
    frames.close()
    return grown


@pytest.mark.parametrize("name", ["zbuffer", "painter"])
def test_the_big_buffers_are_not_filled_before_the_first_frame(name):
    # Filling one 16M-pixel buffer touches 128 MiB; a zeroed one touches
    # only the pages a fragment writes.
    assert _growth_until_first_pixel(name, TRIANGLE, {}, BIG) < 32 * 2 ** 20


def test_the_painters_final_comparison_hears_a_cancel():
    from algorithms import visibility
    monitor = RecordMonitor()
    monitor.cancel()
    with watching(monitor), pytest.raises(Cancelled):
        visibility.zbuffer_image(TRIANGLE, {}, BIG)


def _count_tested_samples(monkeypatch) -> list:
    from algorithms.antialias.shapes import Shapes
    tested = []
    real = Shapes.owners

    def counted(self, sx, sy):
        tested.append(sx.size)
        return real(self, sx, sy)

    monkeypatch.setattr(Shapes, "owners", counted)
    return tested


def test_a_temporal_band_is_tested_in_pieces_that_each_hear_a_cancel(monkeypatch):
    from algorithms.antialias.temporal import frame_bands
    tested = _count_tested_samples(monkeypatch)
    options = {"n": 8, "radius": 100.0}
    top, rows = next(frame_bands([(128.0, 128.0)], options, (256, 256), 0))
    band = rows.size * 64  # the band's pixels, 64 samples each
    assert len(tested) > 1 and sum(tested) <= band and max(tested) < band
    # a cancel is heard before the first piece is tested
    tested.clear()
    monitor = RecordMonitor()
    monitor.cancel()
    with watching(monitor), pytest.raises(Cancelled):
        next(frame_bands([(128.0, 128.0)], options, (256, 256), 0))
    assert tested == []
