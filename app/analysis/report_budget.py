"""What a report will need, estimated from its settings before it starts.

The report's inputs are its settings (``--quick`` or full: line lengths,
radii, grid sizes, frame counts), so its memory is estimated from them, term
by term, as app/model/budget.py estimates a run's. The figures are upper
estimates: peaks measured (resident memory of the whole process) were 76 to
83 MB for the quick report and 92 MB for the full one, against estimates of
about 112 MB and 177 MB; tests/app/analysis/test_report_budget.py measures the
quick report's peak again (in the slow tests).
"""
from __future__ import annotations

from app.model.budget import DEFAULT_MEMORY_LIMIT, STEP_BYTES, BudgetError, size_text

# The interpreter, numpy, matplotlib and the algorithms, loaded.
BASE_BYTES = 96 * 1024 ** 2
LINE_PIXEL_BYTES = 64       # a measured line's pixels and errors, per pixel
CIRCLE_PIXEL_BYTES = 200    # a circle's pixels as Python objects, per pixel
CELL_BYTES = 8              # a grid cell of a buffer the measures make
DEPTH_ROW_BYTES = 64        # a depth row's values in every precision compared
SAMPLE_BYTES = 64           # an antialiasing sample's position, weight and owner


def estimate_report_memory(config) -> int:
    """Bytes a report with these settings needs at its peak (an upper estimate)."""
    largest_radius = max(config.radii + config.circle_cost_radii)
    terms = (
        STEP_BYTES * config.max_frames,                       # the longest traced run
        LINE_PIXEL_BYTES * max(config.line_lengths),
        CIRCLE_PIXEL_BYTES * 8 * (largest_radius + 1),
        CELL_BYTES * (2 * config.hole_radius + 2) ** 2,       # the concentric rings' grid
        STEP_BYTES * (2 * config.fill_radius + 1) ** 2,       # a seed fill's trace
        STEP_BYTES * config.traversal_grid ** 2,
        DEPTH_ROW_BYTES * config.depth_rows,
        SAMPLE_BYTES * config.aa_grid ** 2 * max(config.aa_samples) ** 2,
    )
    return BASE_BYTES + sum(int(term) for term in terms)


def check_report(config, memory_limit: int = DEFAULT_MEMORY_LIMIT) -> None:
    """Raise BudgetError (one line) when the report would not fit the memory limit."""
    memory = estimate_report_memory(config)
    if memory > memory_limit:
        kind = "quick report" if config.quick else "full report"
        raise BudgetError(f"the {kind} would need about {size_text(memory)} of memory, over "
                          f"the limit of {size_text(memory_limit)}; raise --memory-limit"
                          + ("" if config.quick else " or use --quick"))
