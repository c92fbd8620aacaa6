"""Worksheets: a run's step table with columns left blank, an empty grid with
the ideal shape to shade by hand, and the matching answer key.

Qt-free. ``build(scene, blank)`` picks the steps worth working by hand (those
that plot a pixel, take a branch or fill a span, an empty span too, so that
no scan line goes missing; the first MAX_ROWS of them) from the step table
(steptable.py) and keeps their cells as text. A sheet states its inputs (P
and Q, the vertices, the centre and radius), leaves out columns that are
empty on every row, shows the decision variable after its update beside the
one tested ("d" and "d after": x and y are after the step too), and carries
the tables a student fills in by hand (ET and AET for a scan-line polygon).
The blank columns default to every column but the step (each of the others
gives an answer away: the line names the branch, d decides it). Writers
here give CSV, Markdown (with PNG grids drawn by Pillow) and LaTeX (a
``tabular`` to paste), escaping the title and cells with app/model/escape.py;
the PDF is drawn by app/gui/worksheet_pdf.py.
"""
from __future__ import annotations

import bisect
import csv
import io
from dataclasses import dataclass
from pathlib import Path

from algorithms.core.errors import InputError
from algorithms.core.steps import PLOT, Span, Table
from algorithms.core.trace import DEFAULT_STEP_CAP

from app.model import budget, runs
from app.model.escape import csv_row, latex_comment, latex_text, markdown_text
from app.model.files import write_atomically
from app.model.geometry import scene_paths
from app.model.staging import listed_names, write_folder
from app.model.steptable import StepTable, cell_to_text

MAX_ROWS = 60
GIVEN = ("step",)  # shown on the student's sheet unless asked otherwise
FORMATS = ("pdf", "md", "tex", "csv")
FIXED = ("step", "line", "pixel", "choice")
AFTER = " after"   # the decision variable after the step's update: "d after"
FIELDS = "Name: ______________________    Date: ____________"


@dataclass(frozen=True)
class HandTable:
    """A table the student fills in by hand (the ET, the AET by scan line)."""
    name: str
    columns: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    given: frozenset             # columns shown on the student's sheet too

    def cells(self, answers: bool) -> list[list[str]]:
        shown = [answers or column in self.given for column in self.columns]
        return [[cell if show else "" for cell, show in zip(row, shown)] for row in self.rows]


@dataclass(frozen=True)
class Worksheet:
    title: str
    algorithm: str
    code: tuple[str, ...]            # the numbered pseudo-code lines
    constants: tuple[tuple[str, str], ...]
    columns: tuple[str, ...]         # headings, in order
    rows: tuple[tuple[str, ...], ...]  # the answers, as text
    blank: frozenset                 # headings left blank on the student's sheet
    grid: tuple[int, int]
    paths: tuple                     # the ideal shape: ((points, closed), ...)
    pixels: frozenset                # what the run writes, for the key's grid
    note: str = ""                   # steps left out, when there are more than MAX_ROWS
    inputs: str = ""                 # "P = (3, 4), Q = (27, 15)", the vertices, ...
    tables: tuple = ()               # HandTable, ...

    def cells(self, answers: bool) -> list[list[str]]:
        """The rows as the sheet shows them: blanks where the student writes."""
        hidden = [column in self.blank and not answers for column in self.columns]
        return [["" if hide else cell for cell, hide in zip(row, hidden)] for row in self.rows]


def worked_steps(trace, limit: int | None = None) -> list[int]:
    """Steps that plot a pixel, take a branch or fill a span (the first ``limit``)."""
    steps = []
    for i in range(len(trace)):
        if limit is not None and len(steps) >= limit:
            break
        step = trace.step(i)
        filling = isinstance(step.record, Span) and step.kind == PLOT
        if step.writes or step.branch or filling:
            steps.append(i)
    return steps


def columns_of(table: StepTable) -> list[str]:
    """The step table's columns a sheet can show: the fixed ones, each
    variable that is not a constant, and the decision variable after its update."""
    keys = [c.key for c in table.columns if c.key in FIXED or (
        c.kind == "variable" and c.key not in table.constants)]
    decision = _decision(table.trace)
    if decision in keys:
        keys.insert(keys.index(decision) + 1, decision + AFTER)
    return keys


def _decision(trace) -> str | None:
    """The decision variable: the run's own, else a "d" it keeps (the printed circles)."""
    if trace.start.decision is not None:
        return trace.start.decision
    return "d" if "d" in trace.value_names else None


def default_blank(keys) -> tuple[str, ...]:
    return tuple(key for key in keys if key not in GIVEN)


def sheet_row(table: StepTable, i: int, keys: list[str]) -> tuple[str, ...]:
    """Step i's cells for ``keys`` as text, the decision variable after its update too."""
    cells = dict(zip(table.keys, table.text_row(i)))
    decision = _decision(table.trace)
    if decision is not None and decision + AFTER in keys:
        trace = table.trace
        after = trace.variables_at(i + 1) if i + 1 < len(trace) else trace.final_variables()
        cells[decision + AFTER] = cell_to_text(after.get(decision), table.numbers)
    return tuple(cells.get(key, "") for key in keys)


def inputs_text(spec, points, options) -> str:
    """The inputs as the sheet states them."""
    if spec.inputs.contours:
        return "; ".join(f"contour {n + 1}: " + " ".join(_point(p) for p in contour)
                         for n, contour in enumerate(points)) if len(points) > 1 else \
            "vertices: " + " ".join(_point(p) for p in points[0])
    names = spec.inputs.names or ("P",)
    parts = [f"{names[n % len(names)]}{'' if len(points) <= len(names) else n // len(names)}"
             f" = {_point(p)}" for n, p in enumerate(points)]
    parts += [f"{name} = {options[name]}" for name in ("radius", "seed") if name in options]
    return ", ".join(parts)


def _point(point) -> str:
    return "(" + ", ".join(f"{v:g}" for v in point) + ")"


def hand_tables(trace, steps, numbers: str) -> tuple[HandTable, ...]:
    """The ET as first built, and the AET at each scan line the sheet lists."""
    tables = dict((record.name, record) for _, record in reversed(list(trace.records_of(Table))))
    if "ET" not in tables:
        return ()
    et = tables["ET"]
    given = {"ymin", "edge"}
    result = [HandTable("ET", tuple(et.columns),
                        tuple(tuple(cell_to_text(v, numbers) for v in row) for row in et.rows),
                        frozenset(given & set(et.columns)))]
    aet_steps = [i for i, record in trace.records_of(Table) if record.name == "AET"]
    rows, seen = [], set()
    for i in steps:
        record = trace.step(i).record
        if not isinstance(record, Span) or record.y in seen:
            continue
        seen.add(record.y)
        at = bisect.bisect_right(aet_steps, i)
        aet = trace.record_at(aet_steps[at - 1]) if at else None
        columns = ("edge", "ymax", "x", "1/m") if aet is None else tuple(aet.columns)
        entries = [] if aet is None else [
            tuple(cell_to_text(v, numbers) for v in row) for row in aet.rows]
        # One row per active edge; a scan line with none keeps a row of its own.
        rows += [(str(record.y), *entry) for entry in entries or [("(empty)",)]]
    if rows:
        width = 1 + len(columns)
        rows = [row + ("",) * (width - len(row)) for row in rows]
        result.append(HandTable("AET at each scan line (sorted on x)", ("y", *columns),
                                tuple(rows), frozenset({"y"})))
    return tuple(result)


def build(scene, blank=None, memory_limit: int = budget.DEFAULT_MEMORY_LIMIT,
          time_limit: float = budget.DEFAULT_TIME_LIMIT, progress=None,
          numbers: str = "decimal") -> Worksheet:
    """The worksheet of the scene's run; a run over the budget is refused
    (BudgetError) before it starts. ``progress`` hears the recording's steps;
    ``numbers`` (decimal or exact: app/model/notation.py) is how its
    values read."""
    spec = scene.spec
    trace = runs.record(spec, scene.points, scene.options, (scene.width, scene.height),
                        DEFAULT_STEP_CAP, memory_limit, time_limit, progress)
    table = StepTable(trace, numbers)
    keys = columns_of(table)
    blank = tuple(default_blank(keys) if blank is None else blank)
    unknown = [name for name in blank if name not in keys]
    if unknown:
        raise InputError(f"--blank: no column {', '.join(unknown)} (columns: {', '.join(keys)})")
    steps = worked_steps(trace, MAX_ROWS + 1)
    note = "" if len(steps) <= MAX_ROWS else \
        f"The first {MAX_ROWS} such steps; the run goes on after step {steps[MAX_ROWS - 1]}."
    steps = steps[:MAX_ROWS]
    rows = [sheet_row(table, i, keys) for i in steps]
    # A column empty on every row (a count the run never sets) is left out.
    kept = [k for k, key in enumerate(keys) if key == "step" or any(row[k] for row in rows)]
    keys = [keys[k] for k in kept]
    rows = tuple(tuple(row[k] for k in kept) for row in rows)
    writes = trace.written()
    return Worksheet(
        title=scene.title or spec.title, algorithm=spec.name,
        code=tuple(f"{n + 1}  {line.text}" for n, line in enumerate(trace.code)),
        constants=tuple((name, cell_to_text(value, numbers))
                        for name, value in table.constants.items()),
        columns=tuple(keys), rows=rows, blank=frozenset(blank) & set(keys),
        grid=(scene.width, scene.height),
        paths=tuple(scene_paths(spec, scene.points, spec.resolve(scene.options))),
        pixels=frozenset(map(tuple, writes.pixels.tolist())), note=note,
        inputs=inputs_text(spec, scene.points, spec.resolve(scene.options)),
        tables=hand_tables(trace, steps, numbers))


def blank_choices(scene, numbers: str = "decimal") -> tuple[list[str], tuple[str, ...]]:
    """The columns a sheet of this scene has, and the ones blank by default
    (for a window that lets the lecturer choose)."""
    sheet = build(scene, blank=(), numbers=numbers)
    return list(sheet.columns), default_blank(sheet.columns)


# ------------------------------------------------------------------ writers
def csv_text(sheet: Worksheet, answers: bool) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(csv_row(sheet.columns))
    writer.writerows(csv_row(row) for row in sheet.cells(answers))
    return out.getvalue()


def markdown(sheet: Worksheet, answers: bool, grid_image: str) -> str:
    kind = "Answer key" if answers else "Worksheet"
    md = markdown_text
    lines = [f"# {kind}: {md(sheet.title)}", ""]
    if not answers:
        lines += [md(FIELDS), ""]
    lines += [f"Algorithm: `{sheet.algorithm}`", "", f"Inputs: {md(sheet.inputs)}", "",
              "```", *sheet.code, "```", ""]
    if sheet.constants:
        lines += ["Constants: " + ", ".join(f"{md(n)} = {md(v)}" for n, v in sheet.constants), ""]
    if not answers:
        lines += [f"Fill in the columns {md(', '.join(sorted(sheet.blank)))} and shade the "
                  "pixels the algorithm plots.", ""]
    lines += ["| " + " | ".join(md(column) for column in sheet.columns) + " |",
              "|" + "|".join("---" for _ in sheet.columns) + "|"]
    lines += ["| " + " | ".join(md(cell) for cell in row) + " |" for row in sheet.cells(answers)]
    if sheet.note:
        lines += ["", sheet.note]
    for table in sheet.tables:
        lines += ["", f"## {md(table.name)}", "",
                  "| " + " | ".join(md(column) for column in table.columns) + " |",
                  "|" + "|".join("---" for _ in table.columns) + "|"]
        lines += ["| " + " | ".join(md(cell) for cell in row) + " |"
                  for row in table.cells(answers)]
    lines += ["", f"![grid]({grid_image})", ""]
    return "\n".join(lines)


def latex(sheet: Worksheet, answers: bool) -> str:
    """A tabular to paste into a lecturer's document; blanks are left empty."""
    kind = "Answer key" if answers else "Worksheet"
    lines = [latex_comment(f"{kind}: {sheet.title} ({sheet.algorithm})"),
             latex_comment(f"Inputs: {sheet.inputs}")]
    if not answers:
        lines.append(latex_text(FIELDS) + r" \\")
    lines += _tabular(sheet.columns, sheet.cells(answers))
    for table in sheet.tables:
        lines += [latex_comment(table.name)] + _tabular(table.columns, table.cells(answers))
    return "\n".join(lines)


def _tabular(columns, rows) -> list[str]:
    lines = [r"\begin{tabular}{" + "|".join("l" for _ in columns) + "}", r"\hline",
             " & ".join(latex_text(c) for c in columns) + r" \\", r"\hline"]
    lines += [" & ".join(latex_text(cell) for cell in row) + r" \\" for row in rows]
    return lines + [r"\hline", r"\end{tabular}", ""]


def grid_png(sheet: Worksheet, answers: bool, cell: int = 24) -> bytes:
    """The grid (y up) with the ideal shape; the key shades what the run plots."""
    from PIL import Image, ImageDraw  # loaded here: the command line imports this module
    width, height = sheet.grid
    image = Image.new("RGB", (width * cell + 1, height * cell + 1), "white")
    draw = ImageDraw.Draw(image)
    if answers:
        for x, y in sheet.pixels:
            if 0 <= x < width and 0 <= y < height:
                top = (height - 1 - y) * cell
                draw.rectangle([x * cell, top, (x + 1) * cell, top + cell], fill="#8fa8d8")
    for k in range(width + 1):
        draw.line([(k * cell, 0), (k * cell, height * cell)], fill="#b0b0b0")
    for k in range(height + 1):
        draw.line([(0, k * cell), (width * cell, k * cell)], fill="#b0b0b0")
    for points, closed in sheet.paths:
        xy = [(px * cell, (height - py) * cell) for px, py in points]
        if closed:
            xy.append(xy[0])
        if len(xy) >= 2:
            draw.line(xy, fill="#d9480f", width=2)
    out = io.BytesIO()
    image.save(out, format="PNG")
    return out.getvalue()


MANIFEST = ".rasterlab-worksheet.json"  # the files the last worksheet wrote into its folder


def file_names(fmt: str) -> list[str]:
    """The names ``write`` gives the files of format ``fmt`` in its folder."""
    if fmt == "md":  # each sheet after the grid picture it shows
        return ["worksheet-grid.png", "worksheet.md", "answers-grid.png", "answers.md"]
    return [f"worksheet.{fmt}", f"answers.{fmt}"]


def write(sheet: Worksheet, folder, fmt: str, pdf_writer=None) -> list[Path]:
    """Write the worksheet and its answer key into ``folder``; the files
    written. They are staged and moved in together (app/model/staging.py),
    so a failure or a kill never leaves a new sheet beside an old key; a
    write that fails removes the folders it made. The worksheets of other
    formats written there before stay listed as the program's."""
    return write_folder(folder, "worksheet", file_names(fmt),
                        lambda stage: _write_files(sheet, stage, fmt, pdf_writer), MANIFEST,
                        keep=listed_names(folder, MANIFEST))


def _write_files(sheet: Worksheet, folder: Path, fmt: str, pdf_writer) -> None:
    for answers, stem in ((False, "worksheet"), (True, "answers")):
        path = folder / f"{stem}.{fmt}"
        if fmt == "csv":
            write_atomically(path, csv_text(sheet, answers).encode("utf-8"))
        elif fmt == "tex":
            write_atomically(path, latex(sheet, answers).encode("utf-8"))
        elif fmt == "md":
            image = folder / f"{stem}-grid.png"
            write_atomically(image, grid_png(sheet, answers))
            write_atomically(path, markdown(sheet, answers, image.name).encode("utf-8"))
        else:
            pdf_writer(sheet, path, answers)
