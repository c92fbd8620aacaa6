"""The commands for teaching: `rasterlab check` grades a student's own
algorithm, `rasterlab worksheet` writes a worksheet and its answer key.

check's exit status: 0 when every case passes, 1 when some fail, 2 for bad
input (raised as InputError, which app/cli.py turns into one line).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from algorithms.core import registry
from algorithms.core.registry import InputError, parse_number
from app.model import budget
from app.teaching import worksheet
from app.model.files import write_atomically

if TYPE_CHECKING:
    from app.teaching import student


def add_check_command(commands) -> None:
    check = commands.add_parser(
        "check", help="check a student's own algorithm against a built-in one",
        description="Run the generator draw(...) of a student's Python file (see "
                    "resources/templates/) in a separate process on each case, compare its "
                    "pixels with the reference algorithm and the exact result, and print "
                    "PASS or FAIL per case with the first divergence. Exit status 0 when all "
                    "pass, 1 when some fail, 2 for bad input.")
    check.add_argument("file", metavar="FILE.py", help="the student's file")
    check.add_argument("--against", required=True, metavar="ALG",
                       help="the reference algorithm: a line, circle, triangle or polygon "
                            "algorithm of `rasterlab list` (e.g. line-bresenham, circle-midpoint, "
                            "triangle-bbox, polygon-scanline), or flood-fill, zbuffer, painter, "
                            "line-wu or line-area")
    check.add_argument("--cases", nargs="+", default=["hard"], metavar="CASE",
                       help="hard (the hard-case catalogue), random N (N seeded random "
                            "inputs) and SCENE.json files, in any mix (default: hard)")
    check.add_argument("--seed", default="0", metavar="N", help="seed of the random cases")
    check.add_argument("--time-limit", default="2", metavar="SECONDS",
                       help="CPU time per case, 0.1 .. 60 (default %(default)s); the process "
                            "is ended 1 s after it on the wall clock")
    check.add_argument("--memory-limit", default="256M", metavar="SIZE",
                       help="memory per case, 64M .. 8G (default %(default)s); the report "
                            "says which limits this system enforces")
    check.add_argument("--json", action="store_true", help="print one JSON object")
    check.add_argument("--junit", metavar="OUT.xml", help="also write JUnit XML for a grader")


def _limits(args) -> student.Limits:
    from app.teaching import student
    seconds = parse_number(args.time_limit, "--time-limit")
    if not 0.1 <= seconds <= 60:
        raise InputError(f"--time-limit must be 0.1 .. 60 seconds, got {args.time_limit!r}")
    memory = budget.parse_size(args.memory_limit)
    if not 64 << 20 <= memory <= 8 << 30:
        raise InputError(f"--memory-limit must be 64M .. 8G, got {args.memory_limit!r}")
    return student.Limits(seconds=seconds, memory=memory)


def command_check(args) -> int:
    # Loaded here: the window and the other commands import this module too.
    from app.teaching import check_report, checking, student
    path = student.check_file(args.file)
    spec = registry.get(args.against)
    checking.kind_of(spec)
    selectors = checking.parse_selectors(args.cases)
    seed = parse_number(args.seed, "--seed", integer=True)
    limits = _limits(args)
    cases = checking.make_cases(spec, selectors, seed)  # bad scenes are refused before any run
    results = checking.check(path, spec.name, cases, limits=limits)
    held = student.limits_record(limits, student.limits_in_force(limits))
    shown = Path(args.file).name
    if args.junit:
        write_atomically(Path(args.junit),
                         check_report.junit_xml(results, shown, spec.name, held), error=OSError)
    if args.json:
        print(json.dumps(check_report.as_json(results, shown, spec.name, held), indent=2))
    else:
        print("\n".join(check_report.text_lines(results, shown, spec.name, held)))
    sys.stdout.flush()
    return 0 if all(result.passed for result in results) else 1


# ---------------------------------------------------------------- worksheet
def add_worksheet_command(commands) -> None:
    sheet = commands.add_parser(
        "worksheet", help="write a worksheet and its answer key for a scene",
        description="Write the step table of a scene's run (the steps that plot, branch or "
                    "fill a span) with chosen columns left blank, a grid with the ideal shape "
                    "to shade, and the answer key: worksheet.FORMAT and answers.FORMAT in DIR.")
    sheet.add_argument("scene", metavar="SCENE.json", help="a scene file saved by RasterLab")
    sheet.add_argument("--out", required=True, metavar="DIR", help="the folder to write into")
    sheet.add_argument("--format", choices=worksheet.FORMATS, default="pdf",
                       help="pdf, md (with PNG grids), tex (a tabular) or csv (default %(default)s)")
    sheet.add_argument("--blank", default=",".join(worksheet.DEFAULT_BLANK), metavar="COLUMNS",
                       help="columns the student fills in, comma-separated (default %(default)s)")


def command_worksheet(args) -> int:
    from app.model import scene as scenes
    try:
        scene = scenes.load(args.scene)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    blank = [name.strip() for name in args.blank.split(",") if name.strip()]
    sheet = worksheet.build(scene, blank)
    pdf_writer = None
    if args.format == "pdf":
        from app.gui.worksheet_pdf import write_pdf
        pdf_writer = write_pdf
    files = worksheet.write(sheet, args.out, args.format, pdf_writer)
    print(f"{args.out}: {', '.join(path.name for path in files)} ({len(sheet.rows)} steps)")
    return 0
