"""Scan-line fill templates: the AET at scan line y, the span filled at y,
and the edge table entry of an edge.

Drawn variants are triangles with whole-number vertices on a 16x12 grid,
no horizontal edge, and run the textbook's X_low table
(polygon-scanline-xlow: scan lines along whole y, an entry's x at the
edge's lower end), with no crossing exactly on a pixel's sample point
(i + 1/2), so no span end is a tie. A given scene may also run
polygon-scanline, whose scan lines run through the pixel centres; the
question states the convention of the scene's algorithm.
"""
from __future__ import annotations

import random
from fractions import Fraction

from algorithms.core.steps import Span, Table

from app.model.scene import Scene
from app.teaching.questions import common
from app.teaching.questions.model import Template, Worked

GRID = (16, 12)
XLOW, CENTRES = "polygon-scanline-xlow", "polygon-scanline"
ALGORITHMS = (XLOW, CENTRES)
ENTRY = ("ymax", "x", "1/m")
CONVENTION = {
    XLOW: ("scan line y runs along the whole number y; an edge goes into the edge table under "
           "ymin, the y of its lower end, as (ymax, x, 1/m): ymax the y of its upper end (it "
           "leaves the AET at scan line ymax), x the x of its lower end, 1/m = dx/dy; "
           "horizontal edges are left out"),
    CENTRES: ("row y's scan line runs through the pixel centres at y + 1/2; an edge goes into "
              "the edge table under ymin, the first row whose centre line it meets, as (ymax, "
              "x, 1/m): ymax the first row above it (it leaves the AET there), x where it meets "
              "the centre line of row ymin, 1/m = dx/dy; edges that meet no centre line are "
              "left out"),
}
FILLING = "on each scan line, pixels i with x_left <= i + 1/2 < x_right are filled"


def _draw(rng):
    points = tuple((rng.randint(0, GRID[0]), rng.randint(0, GRID[1])) for _ in range(3))
    return Scene(algorithm=XLOW, points=(points,), width=GRID[0], height=GRID[1])


def _well_posed(scene) -> bool:
    (a, b, c), = scene.points
    area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    if area == 0 or len({a[1], b[1], c[1]}) < 3:
        return False
    return all(not _tie(row) for row in _rows(common.trace_of(scene)).values())


def _tie(row) -> bool:
    """Does a crossing of this row lie exactly on a sample point i + 1/2?"""
    (_, aet), _ = row
    return any((Fraction(entry[2]) - Fraction(1, 2)).denominator == 1 for entry in aet.rows)


def _rows(trace) -> dict:
    """{y: ((step, the AET sorted for row y), [(step, span), ...])} of the rows with spans."""
    rows, aet = {}, None
    for i in range(len(trace)):
        record = trace.step(i).record
        if isinstance(record, Table) and record.name == "AET":
            aet = (i, record)
        elif isinstance(record, Span):
            rows.setdefault(record.y, (aet, []))[1].append((i, record))
    return rows


def _fill(name: str, seed: int, scene):
    if scene is None:
        scene, rng = common.drawn(seed, _draw, _well_posed)
    else:
        common.suited(name, ALGORITHMS, scene)
        options = scene.spec.resolve(scene.options)
        if options["fill_rule"] != "evenodd" or options["arithmetic"] != "exact":
            raise ValueError(f"{name}: the scene must fill by the even-odd rule in exact arithmetic")
        rng = random.Random(seed)
    trace = common.trace_of(scene)
    return scene, trace, rng


def _inputs(scene) -> str:
    return ", ".join(f"P{n + 1} = ({x:g}, {y:g})" for contour in scene.points
                     for n, (x, y) in enumerate(contour))


def _preamble(scene) -> str:
    return (f"Scan-line fill ({scene.algorithm}) of the polygon {_inputs(scene)} (edge PiPj "
            f"joins Pi to Pj): {CONVENTION[scene.algorithm]}; {FILLING}.")


def _entry_text(row, columns) -> str:
    cells = dict(zip(columns, row))
    return "(" + ", ".join(common.fraction_text(cells[c]) for c in ENTRY) + ")"


def _table_worked(table, summary: str) -> Worked:
    return Worked(tuple(table.columns), tuple(
        tuple(c if isinstance(c, str) else common.fraction_text(c) for c in row)
        for row in table.rows), summary)


def _spanned_rows(name, trace) -> dict:
    rows = {y: row for y, row in _rows(trace).items()
            if any(span.x_end > span.x_start for _, span in row[1])}
    if not rows:
        raise ValueError(f"{name}: the polygon fills no pixel")
    return rows


def aet_at(seed: int, scene=None):
    name = "fill-aet"
    scene, trace, rng = _fill(name, seed, scene)
    rows = _spanned_rows(name, trace)
    y = rng.choice(sorted(rows))
    (_, aet), _ = rows[y]
    entries = [_entry_text(row, aet.columns) for row in aet.rows]
    canonical = " ".join(entries)
    text = (f"{_preamble(scene)} What does the active edge table hold at scan line {y}, "
            "sorted on x, before the pixels of the line are filled? Answer with its entries "
            "in order as (ymax, x, 1/m) separated by spaces, fractions as p/q (e.g. "
            "(8, 19/7, 4/7) (8, 41/5, -4/5)).")
    answer = common.short(canonical, canonical.replace(", ", ","),
                          canonical.replace(", ", ",").replace(") (", ")("))
    worked = _table_worked(aet, f"At scan line {y} the AET holds {canonical}.")
    return common.question(name, seed, f"Scan line: the AET at y = {y}", text, answer, worked,
                           scene)


def span_at(seed: int, scene=None):
    name = "fill-span"
    scene, trace, rng = _fill(name, seed, scene)
    rows = _spanned_rows(name, trace)
    y = rng.choice(sorted(rows))
    (_, aet), spans = rows[y]
    runs = [f"{span.x_start}..{span.x_end - 1}" for _, span in spans if span.x_end > span.x_start]
    canonical = " ".join(runs)
    text = (f"{_preamble(scene)} Which pixels are filled on scan line {y}? Answer as "
            "first..last (e.g. 3..7), one run for each pair of crossings that fills a pixel, "
            "separated by spaces.")
    answer = common.short(canonical, canonical.replace("..", "-"), canonical.replace(" ", ", "))
    worked = _table_worked(aet, f"The AET sorted at scan line {y} pairs its crossings; the "
                                f"pixels with x_left <= i + 1/2 < x_right are {canonical}.")
    return common.question(name, seed, f"Scan line: the span at y = {y}", text, answer, worked,
                           scene)


def edge_entry(seed: int, scene=None):
    name = "fill-edge-entry"
    scene, trace, rng = _fill(name, seed, scene)
    et = next(record for _, record in trace.records_of(Table) if record.name == "ET")
    if not et.rows:
        raise ValueError(f"{name}: the polygon's edge table is empty")
    row = rng.choice(et.rows)
    edge = dict(zip(et.columns, row))["edge"]
    canonical = _entry_text(row, et.columns)
    text = (f"{_preamble(scene)} What is the edge table entry of edge {edge}? Answer as "
            "(ymax, x, 1/m), fractions as p/q (e.g. (8, 3, -4/5)).")
    answer = common.short(canonical, canonical.replace(", ", ","))
    worked = _table_worked(et, f"Edge {edge} is bucketed under ymin = "
                               f"{dict(zip(et.columns, row))['ymin']} as {canonical}.")
    return common.question(name, seed, f"Scan line: the ET entry of {edge}", text, answer,
                           worked, scene)


TEMPLATES = (
    Template("fill-aet", "fill", "Scan-line fill: the active edge table at scan line y",
             ALGORITHMS, aet_at),
    Template("fill-span", "fill", "Scan-line fill: the span filled at scan line y",
             ALGORITHMS, span_at),
    Template("fill-edge-entry", "fill",
             "Scan-line fill: the edge table entry (ymax, x at ymin, 1/m) of edge e",
             ALGORITHMS, edge_entry),
)
