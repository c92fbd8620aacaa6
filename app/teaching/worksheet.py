"""Worksheets: a run's step table with columns left blank, an empty grid with
the ideal shape to shade by hand, and the matching answer key.

Qt-free. ``build(scene, blank)`` picks the steps worth working by hand (those
that plot a pixel, take a branch or fill a span; the first MAX_ROWS of them)
from the step table (steptable.py) and keeps their cells as text. Writers
here give CSV, Markdown (with PNG grids drawn by Pillow) and LaTeX (a
``tabular`` to paste), escaping the title and cells with app/model/escape.py;
the PDF is drawn by app/gui/worksheet_pdf.py.
"""
from __future__ import annotations

import csv
import io
import json
from dataclasses import dataclass
from pathlib import Path

from algorithms.core.errors import InputError
from algorithms.core.steps import Span
from algorithms.core.trace import DEFAULT_STEP_CAP

from app.model import budget, runs
from app.model.escape import csv_row, latex_comment, latex_text, markdown_text
from app.model.files import manifest_bytes, write_atomically
from app.model.geometry import scene_paths
from app.model.staging import StagedFolder
from app.model.steptable import StepTable, cell_to_text

MAX_ROWS = 60
DEFAULT_BLANK = ("pixel", "choice")
FORMATS = ("pdf", "md", "tex", "csv")
FIXED = ("step", "line", "pixel", "choice")


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
        span = step.record if isinstance(step.record, Span) else None
        if step.writes or step.branch or (span is not None and span.x_end > span.x_start):
            steps.append(i)
    return steps


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
    keys = [c.key for c in table.columns if c.key in FIXED or (
        c.kind == "variable" and c.key not in table.constants)]
    blank = tuple(DEFAULT_BLANK if blank is None else blank)
    unknown = [name for name in blank if name not in keys]
    if unknown:
        raise InputError(f"--blank: no column {', '.join(unknown)} (columns: {', '.join(keys)})")
    steps = worked_steps(trace, MAX_ROWS + 1)
    note = "" if len(steps) <= MAX_ROWS else \
        f"The first {MAX_ROWS} such steps; the run goes on after step {steps[MAX_ROWS - 1]}."
    order = [table.keys.index(key) for key in keys]
    rows = tuple(tuple(table.text_row(i)[k] for k in order) for i in steps[:MAX_ROWS])
    writes = trace.written()
    return Worksheet(
        title=scene.title or spec.title, algorithm=spec.name,
        code=tuple(f"{n + 1}  {line.text}" for n, line in enumerate(trace.code)),
        constants=tuple((name, cell_to_text(value, numbers))
                        for name, value in table.constants.items()),
        columns=tuple(keys), rows=rows, blank=frozenset(blank), grid=(scene.width, scene.height),
        paths=tuple(scene_paths(spec, scene.points, spec.resolve(scene.options))),
        pixels=frozenset(map(tuple, writes.pixels.tolist())), note=note)


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
    lines = [f"# {kind}: {md(sheet.title)}", "", f"Algorithm: `{sheet.algorithm}`", "",
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
    lines += ["", f"![grid]({grid_image})", ""]
    return "\n".join(lines)


def latex(sheet: Worksheet, answers: bool) -> str:
    """A tabular to paste into a lecturer's document; blanks are left empty."""
    kind = "Answer key" if answers else "Worksheet"
    lines = [latex_comment(f"{kind}: {sheet.title} ({sheet.algorithm})"),
             r"\begin{tabular}{" + "|".join("l" for _ in sheet.columns) + "}", r"\hline",
             " & ".join(latex_text(c) for c in sheet.columns) + r" \\", r"\hline"]
    lines += [" & ".join(latex_text(cell) for cell in row) + r" \\" for row in sheet.cells(answers)]
    lines += [r"\hline", r"\end{tabular}", ""]
    return "\n".join(lines)


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
    write that fails removes the folders it made."""
    folder = Path(folder)
    made = [parent for parent in [folder, *folder.parents] if not parent.exists()]
    folder.mkdir(parents=True, exist_ok=True)
    staged = StagedFolder(folder, "worksheet")
    try:
        stage = staged.open()
        try:
            _write_files(sheet, stage, fmt, pdf_writer)
        except OSError as error:  # named where the person will look for the file
            raise OSError(str(error).replace(str(stage), str(folder))) from None
        names = file_names(fmt)
        (stage / MANIFEST).write_bytes(manifest_bytes(set(names) | set(_listed(folder))))
        staged.commit(names + [MANIFEST])
        return [folder / name for name in names]
    except BaseException:
        staged.discard()
        for parent in made:  # deepest first; a folder that holds anything stays
            try:
                parent.rmdir()
            except OSError:
                break
        raise


def _listed(folder: Path) -> list[str]:
    """The names the folder's manifest lists (the worksheets of other
    formats written there before), so that they stay the program's."""
    try:
        names = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    return [name for name in names if isinstance(name, str)] if isinstance(names, list) else []


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
