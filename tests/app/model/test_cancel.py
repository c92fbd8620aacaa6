"""Cancel stops a background recording within a few thousand steps, whatever
the family: the job checks for it every REPORT_EVERY steps."""
import pytest

from algorithms.core import registry
from app.model.recording import REPORT_EVERY, Job

# Long runs of families whose steps cost the most (a z-buffer's fragments,
# supersampling's samples) and the least (a line's pixels).
RUNS = [("zbuffer", [(1, 1), (2000, 30), (40, 1900), (5, 3), (1900, 1990), (1990, 10)], {},
         (2048, 2048)),
        ("aa-supersample", [(1, 1), (1500, 30), (40, 1400)], {"n": 4}, (1536, 1536)),
        ("line-bresenham", [(0, 0), (4_000_000, 1377)], {}, (4_000_001, 1400))]


@pytest.mark.parametrize("name, points, options, grid", RUNS, ids=[run[0] for run in RUNS])
def test_a_cancel_stops_the_run_within_one_report_interval(name, points, options, grid):
    seen = []

    def progressed(job, steps):
        seen.append(steps)
        if len(seen) == 1:
            job.cancel()  # as Esc does, from the first progress report on

    def work(monitor):
        return registry.get(name).record(points, options, grid, step_cap=50_000_000,
                                         monitor=monitor)
    job = Job(work, on_progress=progressed).start()
    assert job.wait(60)
    assert job.cancelled and job.result is None
    # The first check comes within 100 ms of the slowest steps (a z-buffer
    # fragment takes about 11 us: some 9,000 steps), and the run stopped
    # there: no report came after the cancel.
    assert seen[0] <= min(2 * REPORT_EVERY, 9000)
    assert len(seen) == 1
