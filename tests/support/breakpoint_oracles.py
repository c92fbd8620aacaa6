"""The scenes of the breakpoint tests and their oracles: each walks a trace
one frame at a time (``trace.step(i)``) in plain Python and lists the frames
where a condition holds."""
from algorithms.core.steps import Span, Table

BRESENHAM = [((4, 5), (28, 15)), ((20, 2), (5, 22)), ((30, 20), (1, 9)), ((2, 3), (20, 3)),
             ((6, 1), (9, 22))]
POLYGON = [[(2.0, 2.0), (29.0, 3.5), (22.25, 12.0), (28.0, 21.0), (14.5, 15.0), (3.0, 20.0)],
           [(8.0, 6.0), (16.5, 6.0), (12.0, 11.5)]]
TRIANGLES = [(2.5, 2.0), (20.0, 4.25), (9.0, 17.5), (20.0, 4.25), (29.0, 19.0), (9.0, 17.5)]
# The second triangle lies behind the first where they overlap.
ZBUFFER = dict(points=[(2.0, 2.0), (28.0, 4.0), (14.0, 20.0),
                       (4.0, 18.0), (26.0, 18.0), (14.0, 1.0)],
               options={"z": (0.2, 0.25, 0.3, 0.6, 0.6, 0.6)})


def frames(trace):
    return [trace.step(i) for i in range(len(trace))]


def first_after(events, index, direction):
    """The oracle's answer: the nearest listed frame in the direction given."""
    if direction > 0:
        later = [e for e in events if e > index]
        return later[0] if later else None
    earlier = [e for e in events if e < index]
    return earlier[-1] if earlier else None


def sign_events(trace):
    events, last = [], None
    for step in frames(trace):
        d = step.values.get("d")
        if d is None:
            continue
        sign = (d > 0) - (d < 0)
        if last is not None and sign != last:
            events.append(step.index)
        last = sign
    return events


def branch_events(trace):
    events, last = [], None
    for step in frames(trace):
        if not step.branch:
            continue
        if last is not None and step.branch != last:
            events.append(step.index)
        last = step.branch
    return events


def aet_events(trace):
    events, last = [], ()
    for step in frames(trace):
        table = step.record
        if isinstance(table, Table) and table.name == "AET":
            edges = tuple(row[table.columns.index("edge")] for row in table.rows)
            if edges != last:
                events.append(step.index)
            last = edges
    return events


def row_of(step, by_value):
    if isinstance(step.record, Span):
        return step.record.y
    if by_value:
        return step.values.get("y")
    return None if step.pixel is None else step.pixel[1]


def scanline_events(trace):
    steps = frames(trace)
    # Polygon fills write spans and carry the scan line as the value y.
    by_value = not any(s.pixel is not None and not isinstance(s.record, Span) for s in steps)
    events, last = [], None
    for step in steps:
        row = row_of(step, by_value)
        if row is None:
            continue
        if last is not None and row != last:
            events.append(step.index)
        last = row
    return events


def pixel_events(trace, pixel):
    x, y = pixel
    events = []
    for step in frames(trace):
        if step.kind not in ("plot", "visit"):
            continue
        span = step.record
        if isinstance(span, Span):
            if span.y == y and span.x_start <= x < span.x_end:
                events.append(step.index)
        elif step.pixel == (x, y):
            events.append(step.index)
    return events


def depth_fail_events(trace):
    """Fragments whose depth z is not nearer than the stored zb (test "less")."""
    return [step.index for step in frames(trace)
            if "z" in step.values and "zb" in step.values
            and not step.values["z"] < step.values["zb"]]
