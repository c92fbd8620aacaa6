"""The commands for teaching: `rasterlab template` hands out the starting
file of a student's own algorithm, `rasterlab check` grades it, `rasterlab
worksheet` writes a worksheet and its answer key.

check's exit status: 0 when every case passes, 1 when some fail, 2 for bad
input (raised as InputError, which app/cli.py turns into one line), 3 when
RasterLab itself failed (a bug, or a resource the grader lacked), which is
never the student's doing: whatever the student's code does ends as a
failed case (app/teaching/student.py).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from algorithms.core.registry import InputError
from app.cli_parser import add_numbers_option
from app.model import shipped
from app.model.scene import one_line
from app.teaching import worksheet
from app.model.files import (Output, OutputRefused, check_folders, check_outputs, listed, not_ours,
                              write_atomically)


def add_check_command(parser, commands) -> None:
    check = parser.add_command(
        commands, "check", help="check a student's own algorithm against a built-in one",
        description="Run the generator draw(...) of a student's Python file (see "
                    "`rasterlab template`) in a separate process on each case, compare its "
                    "pixels with the reference algorithm and the exact result, and print "
                    "PASS or FAIL per case with the first divergence. Given several files "
                    "or folders (one per student), or any of --format, --csv, --points, "
                    "--jobs, --give-up-after and --id-from, it grades a class: one line "
                    "per submission as it finishes, and the formats asked for. On Linux with "
                    "bubblewrap each case runs in a sandbox (no network, no files but its own "
                    "scratch folder); elsewhere the report says the code is not isolated. "
                    "Exit status 0 when all pass, 1 when some fail, 2 for bad input, 3 when "
                    "RasterLab itself failed.")
    check.add_argument("submissions", nargs="+", metavar="SUBMISSION",
                       help="a student's .py file, or a folder holding one (with --cmd, the "
                            "folder or file the command runs); the student's id is the "
                            "folder's name or the file's name (see --id-from)")
    check.add_argument("--cmd", metavar="COMMAND",
                       help="grade a program in any language: COMMAND runs in each submission "
                            "(a folder, copied whole, or a file; {} is the file's name), e.g. "
                            "./raster or \"node {}\", reading each case as a JSON line on "
                            "stdin and writing JSON lines of steps (`rasterlab template` "
                            "lists C, C++ and JavaScript starting files)")
    check.add_argument("--against", required=True, metavar="ALG",
                       help="the reference algorithm: a line, circle, triangle or polygon "
                            "algorithm of `rasterlab list` (e.g. line-bresenham, circle-midpoint, "
                            "triangle-bbox, polygon-scanline), or flood-fill, zbuffer, painter, "
                            "line-wu or line-area")
    check.add_argument("--cases", nargs="+", default=["hard"], metavar="CASE",
                       help="hard (the hard-case catalogue), random N (N seeded random "
                            "inputs) and SCENE.json files, in any mix (default: hard)")
    check.add_argument("--seed", default="0", metavar="N", help="seed of the random cases (default %(default)s)")
    check.add_argument("--time-limit", default="2", metavar="SECONDS",
                       help="CPU time per case, 0.1 .. 60 (default %(default)s); the process "
                            "is ended 1 s after it on the wall clock")
    check.add_argument("--memory-limit", default="256M", metavar="SIZE",
                       help="memory per case, 64M .. 8G (default %(default)s); the report "
                            "says which limits this system enforces")
    check.add_argument("--json", action="store_true", help="print one JSON object")
    check.add_argument("--junit", metavar="OUT.xml", help="also write JUnit XML for a grader "
                       "(for a class, one testsuite per student, named by the id); never "
                       "over a student's file or a case's scene")
    _add_batch_options(check)
    check.add_argument("--force", action="store_true",
                       help="replace an output file that RasterLab did not write")
    check.add_argument("--require-sandbox", action="store_true",
                       help="refuse to run (exit status 2) where the bubblewrap sandbox is not "
                            "available; RASTERLAB_BWRAP names the bwrap program to use")


def _add_batch_options(check) -> None:
    check.add_argument("--format", choices=("gradescope", "prairielearn", "coderunner"),
                       help="write each submission's results for a grader: Gradescope's or "
                            "PrairieLearn's results.json, or CodeRunner's combinator grader "
                            "JSON; to --out, else to stdout")
    check.add_argument("--out", metavar="PATH", help="the file --format writes; for several "
                       "submissions a folder, which gets ID.json per submission")
    check.add_argument("--csv", metavar="OUT.csv", help="also write one row per student: id, "
                       "cases passed and failed, score, most points, first failing case, seconds")
    check.add_argument("--points", metavar="KIND=N,...", help="points per case of each kind: "
                       "hard, random, scene (e.g. hard=2,random=1; default 1 each)")
    check.add_argument("--jobs", metavar="N", help="grade N submissions at a time (default 1)")
    check.add_argument("--give-up-after", metavar="K", help="after K cases of a submission "
                       "ran out of time, skip its other cases (default 2; 0: never)")
    check.add_argument("--id-from", metavar="REGEX", help="take each student's id from the "
                       "one group of REGEX, searched in the submission's path as given")


def command_check(args) -> int:
    # Loaded here: the window and the other commands import this module too.
    from app import cli_batch
    from app.teaching.check_run import isolation
    prepared = None
    if cli_batch.is_batch(args):
        prepared = cli_batch.prepare(args)
    elif args.junit:
        cases = [word for word in args.cases if Path(word).is_file()]
        junit = [Output("--junit", args.junit, foreign=not_ours("xml"))]
        check_outputs(junit, [args.submissions[0], *cases], args.force)
        check_folders(junit)
    where = isolation(args.require_sandbox)
    if not where.sandboxed:
        print(f"rasterlab: warning: the student's code is NOT isolated from your files and "
              f"network ({where.reason}); --require-sandbox refuses to run without a sandbox",
              file=sys.stderr)
    try:
        return cli_batch.run(args, prepared, where.line()) if prepared else _checked(args)
    except (InputError, OutputRefused, BrokenPipeError, KeyboardInterrupt):
        raise
    except Exception as error:  # MemoryError, OSError, SandboxFailure and bugs alike
        print(f"rasterlab: check failed in RasterLab itself, not in the student's code: "
              f"{type(error).__name__}: {one_line(str(error))}", file=sys.stderr)
        return 3


def _checked(args) -> int:
    from app.teaching import check_report
    from app.teaching.check_run import run_check
    from app.progress import CasesBar
    bar = CasesBar(sys.stderr)

    def echo(lines):  # each case as it ends, on a line of its own under the bar
        bar.clear()
        print("\n".join(lines), flush=True)
    try:
        checked = run_check(args.submissions[0], args.against, args.cases, args.seed, args.time_limit,
                            args.memory_limit, bar if bar.active else None,
                            args.require_sandbox, args.cmd, echo=None if args.json else echo)
    finally:
        bar.clear()
    if args.junit:
        write_atomically(Path(args.junit), check_report.junit_xml(*checked), error=OSError)
    if args.json:
        print(json.dumps(check_report.as_json(*checked), indent=2))
    else:
        print(check_report.tail_line(checked.results))
    sys.stdout.flush()
    return 0 if all(result.passed for result in checked.results) else 1


# ----------------------------------------------------------------- template
def add_template_command(parser, commands) -> None:
    template = parser.add_command(
        commands, "template", help="write the starting file of a student's own algorithm",
        description="With no NAME, list the templates. With NAME, print that template, or "
                    "write it to --out: a Python file with the generator draw(...) to fill in, "
                    "which `rasterlab check` then grades, or a C, C++ or JavaScript program "
                    "for `rasterlab check --cmd`.")
    template.add_argument("name", nargs="?", metavar="NAME", help="a template, as the list names it")
    template.add_argument("--out", metavar="FILE", help="write the template into FILE")
    template.add_argument("--force", action="store_true", help="replace FILE if it exists")


def command_template(args) -> int:
    found = {**shipped.templates(), **shipped.program_templates()}
    if args.name is None:
        if args.out:
            raise InputError("--out needs a template NAME")
        width = max(map(len, found))
        for name, path in found.items():
            print(f"{name:<{width}}  {shipped.template_title(path)}")
        return 0
    if args.name not in found:
        raise InputError(f"no template {args.name!r}; there are: {', '.join(found)}")
    text = found[args.name].read_text(encoding="utf-8")
    if args.out is None:
        sys.stdout.write(text)
        return 0
    out = Path(args.out)
    if out.exists() and not args.force:
        raise InputError(f"{out}: exists; add --force to replace it")
    write_atomically(out, text.encode("utf-8"), error=OSError)
    if out.suffix == ".py":
        print(f"{out}: the {args.name} template; check it with `rasterlab check {out.name} "
              f"--against ...` (the file says which algorithms)")
    else:
        print(f"{out}: the {args.name} template; check the program with `rasterlab check "
              f"--cmd ...` (the file says how, and against which algorithms)")
    return 0


# ---------------------------------------------------------------- worksheet
def add_worksheet_command(parser, commands) -> None:
    sheet = parser.add_command(
        commands, "worksheet", help="write a worksheet and its answer key for a scene",
        description="Write the step table of a scene's run (the steps that plot, branch or "
                    "fill a span) with chosen columns left blank, a grid with the ideal shape "
                    "to shade, and the answer key: worksheet.FORMAT and answers.FORMAT in DIR.")
    sheet.add_argument("scene", metavar="SCENE", help="a scene file saved by RasterLab, or a "
                       "shipped scene by name (`rasterlab list --scenes`)")
    sheet.add_argument("--out", required=True, metavar="DIR", help="the folder to write into")
    sheet.add_argument("--format", choices=worksheet.FORMATS, default="pdf",
                       help="pdf, md (with PNG grids), tex (a tabular) or csv (default %(default)s)")
    sheet.add_argument("--memory-limit", metavar="SIZE",
                       help="memory the scene's run may need, e.g. 512M (default 2G); a larger "
                            "request is refused before it starts")
    sheet.add_argument("--time-limit", default=None, metavar="SECONDS",
                       help="refuse a run estimated to take longer than this, before it "
                            "starts (default 120)")
    sheet.add_argument("--blank", default=None, metavar="COLUMNS",
                       help="columns the student fills in, comma-separated (default: every "
                            "column but step, since each of the others gives answers away); "
                            "columns empty on every row are left out")
    sheet.add_argument("--force", action="store_true",
                       help="replace files in DIR that an earlier worksheet did not write")
    add_numbers_option(sheet, "the sheet and its answer key")


def command_worksheet(args) -> int:
    from app.model import scene as scenes
    scene_path = shipped.scene_path(args.scene)
    try:
        scene = scenes.load(scene_path)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    out = Path(args.out)
    check_outputs([Output("--out", out, folder=True)]
                  + [Output("--out", out / name, foreign=listed(worksheet.MANIFEST))
                     for name in worksheet.file_names(args.format)],
                  [scene_path], force=args.force)
    blank = None if args.blank is None else [
        name.strip() for name in args.blank.split(",") if name.strip()]
    from app.model import budget
    memory = budget.DEFAULT_MEMORY_LIMIT if args.memory_limit is None \
        else budget.parse_size(args.memory_limit)
    seconds = budget.DEFAULT_TIME_LIMIT if args.time_limit is None \
        else budget.parse_seconds(args.time_limit)
    from app.progress import drawn, recording_bar
    with drawn(recording_bar(scene.spec, scene.points, scene.options, scene.grid)) as progress:
        sheet = worksheet.build(scene, blank, memory, seconds, progress, numbers=args.numbers)
    pdf_writer = None
    if args.format == "pdf":
        from app.gui.worksheet_pdf import write_pdf
        pdf_writer = write_pdf
    files = worksheet.write(sheet, args.out, args.format, pdf_writer)
    print(f"{args.out}: {', '.join(path.name for path in files)} ({len(sheet.rows)} steps)")
    return 0


# ------------------------------------------------------------------- grader
def add_grader_command(parser, commands) -> None:
    grader = parser.add_command(
        commands, "grader", help="write a grading platform's autograder for an algorithm",
        description="Write Gradescope's autograder zip: setup.sh installs RasterLab (from "
                    "--wheel, which the zip carries, else from pip) and bubblewrap; "
                    "run_autograder runs `rasterlab check /autograder/submission --against ALG "
                    "--format gradescope` on the cases given here. The cases, limits and "
                    "points are checked now, as check would.")
    grader.add_argument("platform", choices=("gradescope",), help="the grading platform")
    grader.add_argument("--against", required=True, metavar="ALG",
                        help="the reference algorithm, as for check")
    grader.add_argument("--cases", nargs="+", default=["hard"], metavar="CASE",
                        help="hard, random N and SCENE.json files, as for check (default: hard)")
    grader.add_argument("--seed", default="0", metavar="N", help="seed of the random cases")
    grader.add_argument("--time-limit", default="2", metavar="SECONDS", help="as for check")
    grader.add_argument("--memory-limit", default="256M", metavar="SIZE", help="as for check")
    grader.add_argument("--points", metavar="KIND=N,...", help="points per kind of case, as for check")
    grader.add_argument("--wheel", metavar="WHEEL.whl", help="the RasterLab wheel to install "
                        "(default: `pip install rasterlab` of this version)")
    grader.add_argument("--out", required=True, metavar="ZIP", help="the zip to write")
    grader.add_argument("--force", action="store_true", help="replace a file that is not a zip")


def command_grader(args) -> int:
    from importlib import metadata
    from app.teaching import autograder, batch
    batch.plan(args.against, args.cases, args.seed, args.time_limit, args.memory_limit,
               args.points)  # refused here, not on the platform
    wheel = Path(args.wheel) if args.wheel else None
    if wheel is not None and (wheel.suffix != ".whl" or not wheel.is_file()):
        raise InputError(f"--wheel {wheel}: not a .whl file")
    scenes = [word for word in args.cases if word.endswith(".json")]
    check_outputs([Output("--out", args.out, foreign=not_ours("zip"))],
                  [wheel, *scenes], args.force)
    try:
        version = metadata.version("rasterlab")
    except metadata.PackageNotFoundError:
        if wheel is None:
            raise InputError("RasterLab is not installed as a package here, so its version "
                             "for pip is unknown: give --wheel") from None
        version = ""
    words = autograder.check_words(args.against, args.cases, args.seed, args.time_limit,
                                   args.memory_limit, args.points)
    write_atomically(Path(args.out), autograder.zip_bytes(words, args.cases, wheel, version),
                     error=OSError)
    print(f"{args.out}: Gradescope autograder for {args.against} "
          f"(cases: {' '.join(args.cases)}); upload it as the assignment's autograder")
    return 0
