"""`rasterlab report`: speed against error, written to a folder.

    rasterlab report [--quick] [--out DIR]

measures every algorithm family (app/analysis/measure.py) and writes into DIR
(default ./rasterlab-report):

* report.md: the headline findings, then tables per family;
* measurements.csv and measurements.json: every measurement, one row each
  (columns: measure.COLUMNS), the JSON with the settings and timings too;
* <family>.png: cost against error, one figure per family.

The files are written into a staging folder inside DIR and moved into
place together (app/model/staging.py), so a reader never sees half a file
and a full disk or a kill never leaves new files beside old ones. ``--quick`` measures fewer and smaller
cases (under a minute on a 2-core machine); the full report takes a few
minutes.
"""
from __future__ import annotations

import csv
import io
import json
import os
import platform
import tempfile
import time
from pathlib import Path

import numpy as np
from PIL import PngImagePlugin

from app.analysis import measure
from app.model.files import Output, listed, manifest_bytes, write_atomically
from app.model.staging import StagedFolder

from app.progress import TerminalBar

from .report_findings import View, findings, table
from .report_textures import section_textures
from .report_visibility import section_visibility
from .report_sections import (section_antialias, section_circles, section_fill,
                              section_interpolation, section_lines, section_precision)

DEFAULT_OUT = "rasterlab-report"
DOCUMENTS = ("report.md", "measurements.csv", "measurements.json")
MANIFEST = ".rasterlab-report.json"  # the files the last report wrote into its folder


class ReportError(Exception):
    """The report cannot be written; the message is one line for the person."""


# ============================================================ writing
def check_folder(out) -> Path:
    """Make the output folder (and its parents) and prove it takes files."""
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise ReportError(f"--out {out}: not a folder")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise ReportError(f"--out {out}: cannot create the folder "
                          f"({error.strerror or error})") from None
    try:
        handle, probe = tempfile.mkstemp(prefix=".rasterlab-", suffix=".tmp", dir=path)
        os.close(handle)
        os.unlink(probe)
    except OSError as error:
        raise ReportError(f"--out {out}: cannot write in the folder "
                          f"({error.strerror or error})") from None
    return path


# ============================================================ the report
def markdown(view: View, config, seconds: dict, missing_aa: str, figures=()) -> str:
    total = sum(seconds.values())
    head = ["# RasterLab: speed against error", "",
            f"{'Quick' if config.quick else 'Full'} report, {time.strftime('%Y-%m-%d %H:%M')}, "
            f"Python {platform.python_version()}, numpy {np.__version__}, "
            f"{os.cpu_count()} CPUs; measured in {total:.1f} s. Every number is in "
            "measurements.csv (and .json); inputs are seeded, so counts and errors repeat "
            "exactly, times do not.", "",
            "Operation counts come from the algorithms' own pseudo-code: each code line carries "
            "the operations one execution of it performs, and a run counts its executed lines "
            "(Note frames do nothing; a Span frame counts per pixel it fills). *ops/px* adds "
            "integer and float additions, multiplications, divisions, square roots, roundings "
            "and comparisons per pixel written; *tested* is pixels looked at per pixel written.",
            "", "## Headline findings", ""]
    head.append(table(["topic", "finding", "measured"], findings(view)))
    sections = [section_lines(view), section_circles(view),
                section_precision(view, "polygons", "Polygons"),
                section_precision(view, "triangles", "Triangles"),
                section_fill(view), section_interpolation(view),
                section_antialias(view, missing_aa), section_textures(view),
                section_visibility(view)]
    pictures = "## Figures\n\n" + "\n\n".join(f"![{figure_alt(f)}]({f}.png)" for f in FIGURE_ORDER
                                                 if f in figures)
    timing = "## Time per part\n\n" + table(["part", "seconds"],
                                             [[k, round(v, 1)] for k, v in seconds.items()])
    return "\n\n".join(["\n".join(head)] + [s for s in sections if s] + [pictures, timing]) + "\n"


FIGURE_ORDER = ("lines", "circles", "polygons", "fill", "triangles", "interpolation",
                "antialiasing", "textures")


def figure_alt(family: str) -> str:
    """A figure's alt text: in report.md, and as its PNG's Title; the
    figures' numbers are in the report's tables."""
    return f"Cost against error of the {family} algorithms (its numbers are in the tables above)"


def csv_text(rows: list[dict]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=measure.COLUMNS, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({**row, "value": repr(row["value"])})
    return buffer.getvalue()


def write_report(out=DEFAULT_OUT, quick: bool = False, progress=None) -> dict:
    """Measure and write the report into ``out``; returns what was written."""
    folder = check_folder(out)
    config = measure.settings(quick)
    started = time.perf_counter()
    rows, seconds = measure.run(config, progress)
    return write_files(folder, config, rows.rows, seconds, started)


def outputs(out) -> list[Output]:
    """Every file a report may write into ``out``, for the output policy's
    check before the measuring (app.model.files.check_outputs)."""
    names = DOCUMENTS + tuple(f"{family}.png" for family in FIGURE_ORDER)
    return [Output("--out", out, folder=True)] + [
        Output("--out", Path(out) / name, foreign=listed(MANIFEST)) for name in names]


def write_files(out, config, rows: list, seconds: dict, started: float | None = None) -> dict:
    """Write the files of a report from measurements already made."""
    folder = check_folder(out)
    started = time.perf_counter() if started is None else started
    missing_aa = measure.antialias_available()
    view = View(rows)
    from .report_figures import charts  # Pillow loads only when figures are drawn
    images = charts(view)
    documents = {
        "report.md": markdown(view, config, seconds, missing_aa, images).encode("utf-8"),
        "measurements.csv": csv_text(rows).encode("utf-8"),
        "measurements.json": (json.dumps({
            "quick": config.quick, "seed": measure.SEED, "columns": list(measure.COLUMNS),
            "settings": {k: v for k, v in vars(config).items()},
            "seconds": seconds, "antialiasing": missing_aa or "measured",
            "findings": [{"topic": t, "finding": f, "measured": m} for t, f, m in findings(view)],
            "rows": rows}, indent=1, allow_nan=False) + "\n").encode("utf-8"),
    }
    for family, image in images.items():
        buffer = io.BytesIO()
        text = PngImagePlugin.PngInfo()
        text.add_text("Title", figure_alt(family))
        image.save(buffer, format="PNG", optimize=True, pnginfo=text)
        documents[f"{family}.png"] = buffer.getvalue()
    names = sorted(documents)
    documents[MANIFEST] = manifest_bytes(names)
    replace_together(folder, documents)
    return {"folder": str(folder), "files": names, "rows": len(rows),
            "seconds": time.perf_counter() - started}


def replace_together(folder: Path, documents: dict) -> None:
    """Write ``documents`` (file name -> bytes) into ``folder`` so that
    they replace its report files together: a full disk or a kill leaves
    the old report whole, never new files beside old ones."""
    staged = StagedFolder(folder, "report", ReportError)
    stage = staged.open()
    try:
        for name, data in documents.items():
            try:
                write_atomically(stage / name, data, ReportError)
            except ReportError as error:
                # Name the file where the person will look for it.
                raise ReportError(str(error).replace(str(stage), str(folder))) from None
        staged.commit(sorted(documents))
    except BaseException:
        staged.discard()
        raise


class ProgressBar(TerminalBar):
    """The report's progress: measurements done so far."""

    def __call__(self, done: int, total: int, label: str) -> None:
        self.draw("measuring", done, total, f"{label[:30]:<30}")
