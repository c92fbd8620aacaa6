"""An independent replay of a trace, one step and one pixel at a time, from
step 0: the oracle the vectorised ``Trace.replay`` is checked against."""
from algorithms.core.raster import Raster
from algorithms.core.steps import PLOT, Span


def slow_replay(trace, i: int) -> Raster:
    """The framebuffer after step i, decoded step by step with ``Trace.step``."""
    start = trace.start
    colour = start.color_value or start.pixel_value
    raster = Raster(trace.width, trace.height, colour is not None, start.depth_value is not None)
    raster.replaces = start.replaces
    for k in range(i % len(trace) + 1):
        step = trace.step(k)
        if isinstance(step.record, Span):
            for x in range(step.record.x_start, step.record.x_end):
                if step.kind == PLOT:
                    raster.write(x, step.record.y, step.record.value)
        elif step.writes:
            value = None if colour is None else trace.series(colour)[k]
            depth = None if start.depth_value is None else trace.series(start.depth_value)[k]
            raster.write(*step.pixel, value, depth)
    return raster
