"""The `rasterlab` command line (see DESIGN.md for the contract).

Bad input of any kind ends with exit status 2 and one line on stderr.
"""
from __future__ import annotations

import argparse
import dataclasses
import codecs
import json
import os
import re
import sys

from algorithms.core import registry
from algorithms.core.raster import MAX_GRID
from algorithms.core.registry import InputError, parse_number
from algorithms.core.trace import DEFAULT_STEP_CAP, MAX_STEP_CAP, TraceError
from app import cli_describe, cli_questions, cli_teaching
from app.model import budget, runs
from app.model.files import Output, OutputRefused, check_outputs
from app.model.runs import DEFAULT_GRID, Rows, check_grid, fit_grid, run_result, save_new
from app.progress import TerminalBar, drawn, recording_bar
from app.model.scene import one_line
from app.model.version import app_version
from app.cli_parser import CommandError, Parser, add_numbers_option


def build_parser() -> Parser:
    parser = Parser(prog="rasterlab", description=(
        "Step through rasterization algorithms on a magnified pixel grid. "
        "With no command, the window opens."))
    parser.add_argument("--version", action="version", version=f"rasterlab {app_version()}")
    commands = parser.add_subparsers(dest="command", parser_class=Parser)
    listing = parser.add_command(commands, "list",
                                 help="list the algorithms, or the shipped scenes")
    listing.add_argument("--json", action="store_true", help="print JSON")
    listing.add_argument("--scenes", action="store_true",
                         help="list the scenes RasterLab ships, by the name run and export take")
    run = parser.add_command(commands, "run", help="run an algorithm headless and print its "
                                                   "pixels, or save its scene")
    run.add_argument("algorithm", nargs="?", help="algorithm name, as `rasterlab list` shows it")
    run.add_argument("--points", nargs="+", action="append", metavar="X,Y",
                     help="points in pixel coordinates (y up); repeat once per contour")
    run.add_argument("--scene", metavar="SCENE",
                     help="run a scene file, or a shipped scene by name (`rasterlab list --scenes`), "
                          "instead of ALGO --points (options and grid from the scene)")
    run.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                     help="set an option (numbers, names, true/false, comma lists)")
    run.add_argument("--grid", metavar="W,H",
                     help=f"grid size, at most {MAX_GRID},{MAX_GRID} (default: fits the points, "
                          f"at least {DEFAULT_GRID[0]},{DEFAULT_GRID[1]})")
    run.add_argument("--memory-limit", default=None, metavar="SIZE",
                     help="refuse a run whose estimated memory exceeds this (e.g. 512M, 4G; "
                          "default 2G)")
    add_time_limit(run)
    run.add_argument("--step-cap", type=str, default=str(DEFAULT_STEP_CAP), metavar="N",
                     help=f"stop recording after N steps, 1 .. {MAX_STEP_CAP:,}: the cap bounds the "
                          "memory a run takes (default %(default)s)")
    run.add_argument("--steps", action="store_true",
                     help="print every step: line, pixel, choice, variables, tables (as an "
                          "aligned table, or with --json or --csv)")
    output = run.add_mutually_exclusive_group()
    output.add_argument("--json", action="store_true", help="print one JSON object")
    output.add_argument("--ascii", action="store_true", help="print the grid as text")
    output.add_argument("--csv", action="store_true", help="with --steps: print the steps as CSV")
    add_numbers_option(run, "--steps tables, --describe (and --json's extra *_exact fields)")
    cli_describe.add_describe_option(run)
    run.add_argument("--save", metavar="SCENE.json",
                     help="also write the run's scene to a file the window, export and run "
                          "--scene open; prints one line instead of the pixels unless --json, "
                          "--ascii or --steps asks for an output")
    run.add_argument("--force", action="store_true",
                     help="with --save: replace a file that exists")
    add_export_command(parser, commands)
    add_report_command(parser, commands)
    cli_teaching.add_template_command(parser, commands)
    cli_teaching.add_check_command(parser, commands)
    cli_teaching.add_grader_command(parser, commands)
    cli_teaching.add_worksheet_command(parser, commands)
    cli_questions.add_questions_command(parser, commands)
    return parser


# ------------------------------------------------------------------ parsing
def parse_point(text: str) -> tuple[float, float]:
    text = text.strip()  # messages quote the point without main's shielding space
    parts = text.split(",")
    if len(parts) != 2:
        raise InputError(f"point {text!r} must be X,Y")
    return tuple(parse_number(part, f"point {text!r}") for part in parts)


def parse_grid(text: str) -> tuple[int, int]:
    text = text.strip()
    parts = text.split(",")
    if len(parts) != 2:
        raise InputError(f"grid {text!r} must be W,H")
    return check_grid(*(parse_number(part, f"grid {text!r}", integer=True) for part in parts))


def parse_step_cap(text: str) -> int:
    step_cap = parse_number(text, "--step-cap", integer=True)
    if not 1 <= step_cap <= MAX_STEP_CAP:
        raise InputError(f"--step-cap must be 1 .. {MAX_STEP_CAP:,}, got {text.strip()!r}")
    return step_cap


def parse_settings(spec, settings: list[str]) -> dict:
    options = {}
    for setting in settings:
        key, sep, value = setting.partition("=")
        if not sep or not key.strip():
            raise InputError(f"--set {setting!r} must be KEY=VALUE")
        options[key.strip()] = spec.option(key.strip()).parse(value)
    return options


# ----------------------------------------------------------------- commands
def command_list(args) -> int:
    if args.scenes:
        return list_scenes(args)
    specs = registry.all_specs()
    if args.json:
        print(json.dumps([spec.describe() for spec in specs], indent=2))
        return 0
    name_width = max(len(spec.name) for spec in specs)
    family_width = max(len(spec.family) for spec in specs)
    for spec in specs:
        options = ", ".join(_option_text(o) for o in spec.options)
        print(f"{spec.name:<{name_width}}  {spec.family:<{family_width}}  "
              f"{spec.inputs.text():<24}  {spec.summary}" + (f"  [{options}]" if options else ""))
    return 0


def list_scenes(args) -> int:
    """The catalogue of shipped scenes, family by family (app/model/catalogue.py)."""
    from app.model import catalogue
    rows = catalogue.examples()
    if args.json:
        print(json.dumps([{"name": e.name, "family": e.family, "algorithm": e.scene.algorithm,
                           "title": e.scene.title, "description": e.scene.description}
                          for e in rows], indent=2))
        return 0
    width = max(len(e.name) for e in rows)
    family_width = max(len(e.family) for e in rows)
    for e in rows:
        print(f"{e.name:<{width}}  {e.family:<{family_width}}  {e.title}")
    return 0


def _option_text(option) -> str:
    """name=default, with the choices when there are a few: "order=stack (stack|queue|span)"."""
    text = f"{option.name}={_default_text(option.default)}"
    if option.kind == "choice" and len(option.choices) > 1:
        text += f" ({'|'.join(map(str, option.choices))})"
    return text


def _default_text(value) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (tuple, list)):
        return ",".join(map(str, value)) or "none"
    return str(value)


def command_run(args) -> int:
    if args.csv and not args.steps:
        raise CommandError("--csv prints the table of steps: add --steps")
    if args.steps and args.ascii:
        raise CommandError("--steps prints a table: use it alone, with --json or with --csv")
    if args.force and args.save is None:
        raise CommandError("--force replaces the file of --save: give --save SCENE.json too")
    cli_describe.check_describe(args)
    if args.numbers != "decimal" and not (args.steps or args.describe):
        raise CommandError("--numbers sets how the table of steps shows fractions: add --steps")
    if args.scene is not None:
        return run_scene(args)
    if args.algorithm is None or args.points is None:
        raise CommandError(_missing_algorithm(args.points))
    spec = registry.get(args.algorithm)
    groups = [[parse_point(text) for text in group] for group in args.points]
    if spec.inputs.contours:
        points = groups
    elif len(groups) > 1:
        raise InputError(f"{spec.name} takes one --points list, not one per contour")
    else:
        points = groups[0]
    options = parse_settings(spec, args.set)
    step_cap = parse_step_cap(args.step_cap)
    points = spec.inputs.check(points)
    _check_save(args, options)
    grid = parse_grid(args.grid) if args.grid is not None else None
    grid = fit_grid(spec.inputs.flat(points), grid, spec.inputs.integer)
    trace = _record(spec, points, options, grid, step_cap, args)
    if args.save is not None:
        from app.model.scene import Scene
        scene = Scene(algorithm=spec.name, points=points, options=options,
                      width=grid[0], height=grid[1])
        return save_run(args, scene, trace)
    return print_run(args, spec, trace, options)


def _memory_limit(args) -> int:
    if getattr(args, "memory_limit", None) is None:
        return budget.DEFAULT_MEMORY_LIMIT
    return budget.parse_size(args.memory_limit)


def add_time_limit(command) -> None:
    command.add_argument("--time-limit", default=None, metavar="SECONDS",
                         help="refuse a run estimated to take longer than this, before it "
                              f"starts (default {budget.DEFAULT_TIME_LIMIT:g})")


def _time_limit(args) -> float:
    if args.time_limit is None:
        return budget.DEFAULT_TIME_LIMIT
    return budget.parse_seconds(args.time_limit)


def _missing_algorithm(points) -> str:
    # `--points` takes every word up to the next option, so a name after the
    # points lands among them: say so instead of "needs ALGO".
    names = {spec.name for spec in registry.all_specs()}
    misplaced = [word for group in points or [] for word in group if word.strip() in names]
    if misplaced:
        return f"put ALGO before --points: {misplaced[0].strip()!r} was read as a point"
    return "run needs ALGO and --points, or --scene SCENE.json"


def run_scene(args) -> int:
    from app.model import scene as scenes
    from app.model import shipped
    if args.algorithm is not None or args.points is not None or args.set or args.grid:
        raise CommandError("--scene takes its algorithm, points, options and grid from the file")
    step_cap = parse_step_cap(args.step_cap)
    scene_path = shipped.scene_path(args.scene)
    try:
        scene = scenes.load(scene_path)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    _check_save(args, scene.options, scene_path)
    trace = _record(scene.spec, scene.points, scene.options, scene.grid, step_cap, args)
    if args.save is not None:
        return save_run(args, scene, trace)
    return print_run(args, scene.spec, trace, scene.options)


def _record(spec, points, options, grid, step_cap: int, args):
    """The run recorded within the command's budgets, its progress on a terminal."""
    with drawn(recording_bar(spec, points, options, grid, step_cap)) as progress:
        return runs.record(spec, points, options, grid, step_cap, _memory_limit(args),
                           _time_limit(args), progress)


def _check_save(args, options, scene_path=None) -> None:
    """The output policy for --save, before the run: never the scene file
    read, a texture, a folder or a device (``check_outputs``)."""
    if args.save is None:
        return
    texture = options.get("texture")
    texture = texture if isinstance(texture, str) and os.path.isfile(texture) else None
    check_outputs([Output("--save", args.save)], [scene_path, texture])


def save_run(args, scene, trace) -> int:
    """`run ... --save SCENE.json`: the scene is written once its run has
    worked; then the output asked for (--json, --ascii, --steps), or else
    one line saying what was saved in place of the pixels."""
    save_new(scene, args.save, args.force, "give --force to replace it")
    if args.json or args.ascii or args.steps or args.describe:
        return print_run(args, scene.spec, trace, scene.options)
    if trace.truncated:
        print(f"rasterlab: {trace.message}", file=sys.stderr)
    print(f"{args.save}: a scene of {scene.algorithm} on a {scene.width}x{scene.height} grid "
          f"({len(trace.written_pixels())} pixels written in {len(trace)} steps)")
    return 0


def print_run(args, spec, trace, options) -> int:
    if trace.truncated:
        print(f"rasterlab: {trace.message}", file=sys.stderr)
    if args.steps:
        return print_steps(args, spec, trace, options)
    if args.describe:
        return cli_describe.print_descriptions(args, trace)
    if args.json:
        write_json(sys.stdout, run_result(spec, trace, options))
    elif args.ascii:
        print(ascii_grid(trace))
    else:
        write_summary(sys.stdout, spec, trace)
    return 0


def print_steps(args, spec, trace, options) -> int:
    """`run --steps`: the step table, in the output form asked for."""
    from app.model import step_output, steptable
    table = steptable.StepTable(trace, args.numbers)
    if args.json:
        result = run_result(spec, trace, options)
        result["columns"] = step_output.json_columns(table)
        result["rows"] = Rows(range(len(table)),
                              lambda part: [step_output.json_row(table, i) for i in part])
        write_json(sys.stdout, result)
    elif args.csv:
        steptable.write_csv(table, sys.stdout)
    else:
        step_output.write_aligned(table, sys.stdout)
    return 0


def write_json(stream, result: dict) -> None:
    """``print(json.dumps(result))``, byte for byte, with each Rows written
    in parts instead of being made one list."""
    rows = {key: value for key, value in result.items() if isinstance(value, Rows)}
    text = json.dumps({key: (f"@@{key}@@" if key in rows else value)
                       for key, value in result.items()}, allow_nan=False)
    for key, value in rows.items():
        head, _, text = text.partition(f'"@@{key}@@"')
        stream.write(head + "[")
        for n, part in enumerate(value.parts()):
            stream.write((", " if n else "") + json.dumps(part, allow_nan=False)[1:-1])
        stream.write("]")
    stream.write(text + "\n")


def ascii_grid(trace) -> str:
    """The final raster as text, top row first: '#' written, '+' written again, '.' empty."""
    counts = trace.raster_at(len(trace) - 1).counts
    rows = []
    for y in range(trace.height - 1, -1, -1):
        rows.append("".join("." if c == 0 else ("#" if c == 1 else "+") for c in counts[y]))
    return "\n".join(rows)


def write_summary(stream, spec, trace) -> None:
    pixels = trace.written_pixels()
    final = ", ".join(f"{k}={registry.format_value(v)}" for k, v in trace.final_variables().items())
    stream.write(f"{spec.title} ({spec.name}) on a {trace.width}x{trace.height} grid: "
                 f"{len(pixels)} pixels written in {len(trace)} steps\npixels:"
                 + ("" if len(pixels) else " "))
    for start in range(0, len(pixels), Rows.PART):  # in parts, as write_json
        stream.write("".join(f" {x},{y}" for x, y in pixels[start:start + Rows.PART].tolist()))
    stream.write(f"\nfinal: {final}\n")


# ------------------------------------------------------------------- export
def add_export_command(parser, commands) -> None:
    """`rasterlab export SCENE.json --gif OUT.gif ...` (see app/render/export.py)."""
    export = parser.add_command(
        commands, "export", help="export a scene's run: GIF, PNG or SVG frames, MP4, WebM, PDF or an "
                       "interactive HTML page",
        description="Draw every step of a scene's run as the window shows it, with an optional "
                    "caption and side panel: an animated GIF, numbered PNG or SVG frames, an MP4 "
                    "or WebM video, a PDF (with a Beamer include) or an interactive HTML page.")
    export.add_argument("scene", metavar="SCENE", help="a scene file saved by RasterLab, or a "
                        "shipped scene by name (`rasterlab list --scenes`)")
    export.add_argument("--gif", metavar="OUT.gif", help="write an animated GIF")
    export.add_argument("--frames-dir", metavar="DIR",
                        help="write frame_0000.png, frame_0001.png, ... into DIR")
    export.add_argument("--mp4", metavar="OUT.mp4",
                        help="write an H.264 video (plays in PowerPoint, Keynote and browsers)")
    export.add_argument("--webm", metavar="OUT.webm", help="write a VP9 WebM video")
    export.add_argument("--svg-dir", metavar="DIR",
                        help="write frame_0000.svg, ... (vector frames) into DIR")
    export.add_argument("--pdf", metavar="OUT.pdf", help="write a PDF with a page per frame")
    export.add_argument("--pages", choices=("frames", "bookmarks"), default="frames",
                        help="SVG and PDF: a page per exported frame, or only the frames of the "
                             "scene's bookmarks (default %(default)s)")
    export.add_argument("--beamer", metavar="OUT.tex",
                        help="with --pdf: write a Beamer frame showing the PDF's pages as "
                             "overlays")
    export.add_argument("--html", metavar="OUT.html",
                        help="write an interactive page: one self-contained file that replays "
                             "the run in a browser")
    export.add_argument("--force", action="store_true",
                        help="write what is otherwise refused as possibly unwanted: replace a "
                             "file that is not of the format written (a GIF by --gif, ...) or a "
                             "frame file a folder's earlier export did not write, and write a "
                             "page over its size budget. An output that is an input or another "
                             "output, a folder, device or FIFO, is refused all the same")
    export.add_argument("--fps", default="4", metavar="N",
                        help="frames per second, 0.1 .. 50 (default %(default)s)")
    export.add_argument("--scale", default=None, metavar="N",
                        help="pixels per grid cell, 1 .. 64 (default: as large as fits the grid's "
                             "longer side in 640 pixels, at most 32)")
    export.add_argument("--from", dest="first", metavar="I",
                        help="first step: a number or a bookmark name (default 0)")
    export.add_argument("--to", dest="last", metavar="J",
                        help="last step, included: a number or a bookmark name (default: the last)")
    export.add_argument("--hold", default="2", metavar="SECONDS",
                        help="extra time on the last frame (default %(default)s)")
    export.add_argument("--transcript", action=argparse.BooleanOptionalAction, default=True,
                        help="write the steps in words beside a GIF (NAME.txt) and a video "
                             "(NAME.vtt captions) (default: on)")
    export.add_argument("--caption", action=argparse.BooleanOptionalAction, default=True,
                        help="the caption under the grid: step, pseudo-code line, values "
                             "(default: on)")
    export.add_argument("--panel", choices=("auto", "code", "variables", "both", "tables", "none"),
                        default="auto",
                        help="side panel: the pseudo-code with the current line marked, the "
                             "variables, both, the run's tables (the scan line's ET and AET), "
                             "or none; auto: the pseudo-code where it fits (default)")
    export.add_argument("--unit", choices=("auto", "step", "decision", "pixel", "scanline",
                                           "primitive"), default="auto",
                        help="one frame per step, decision, pixel written, scan line or "
                             "primitive; auto: per step for short runs, else the finest unit "
                             "that keeps the export within 240 frames (default)")
    export.add_argument("--text-size", metavar="PX",
                        help="text size of the caption and panel in pixels, 8 .. 96 (default: "
                             "a thirtieth of the grid's longer side, 16 .. 48)")
    export.add_argument("--no-reasoning", action="store_true",
                        help="no scan line, midpoint or sample marks on the grid")
    export.add_argument("--axes", action="store_true",
                        help="coordinates beside the grid, ticks at the cell boundaries")
    export.add_argument("--vertex-labels", action="store_true",
                        help="name the scene's points (P1, P2, ...) on the grid")
    export.add_argument("--theme", choices=("light", "dark"), default="light",
                        help="colours (default %(default)s)")
    export.add_argument("--once", action="store_true", help="play once instead of looping")
    export.add_argument("--per", choices=("auto", "step", "animation"), default="auto",
                        help="one frame per step, or per animation frame of a run that has "
                             "them (aa-temporal); auto: animation frames where there are "
                             "some (default)")
    export.add_argument("--no-grid", action="store_true", help="no grid lines")
    export.add_argument("--no-primitive", action="store_true", help="no ideal primitive")
    export.add_argument("--no-highlight", action="store_true",
                        help="no outlines on the step's pixel and the candidates")
    export.add_argument("--overlays", metavar="LIST",
                        help="geometry drawn over the grid, a comma list of half-planes, "
                             "sub-triangles, distances, basis (triangle runs), octants (line "
                             "runs), all or none (default: the scene's view.overlays)")
    export.add_argument("--memory-limit", metavar="SIZE",
                        help="memory the run may need, e.g. 512M or 4G (default 2G); a larger "
                             "request is refused before it starts")
    add_time_limit(export)
    export.add_argument("--frames-limit", metavar="SIZE",
                        help="disk space the PNG frames may take (default 1G)")
    add_numbers_option(export, "the caption and the panels")


def _overlays(text: str | None, scene) -> tuple:
    from app.render.overlays import parse_overlays, scene_overlays
    if text is None:
        return scene_overlays(scene)
    try:
        return parse_overlays(text)
    except ValueError as error:
        raise InputError(f"--overlays: {error}") from None


def command_export(args) -> int:
    if args.beamer is not None and args.pdf is None:
        raise CommandError("--beamer includes the pages of the PDF: give --pdf OUT.pdf too")
    if args.beamer is not None:
        from app.render.formats import beamer_reference
        try:
            beamer_reference(args.pdf, args.beamer)
        except ValueError as error:
            raise InputError(str(error)) from None
    outputs = (args.gif, args.frames_dir, args.mp4, args.webm, args.svg_dir, args.pdf, args.html)
    if all(output is None for output in outputs):
        raise CommandError("export needs an output: --gif, --frames-dir, --mp4, --webm, "
                           "--svg-dir, --pdf or --html")
    fps = parse_number(args.fps, "--fps")
    hold = parse_number(args.hold, "--hold")
    scale = None if args.scale is None else parse_number(args.scale, "--scale", integer=True)
    text_size = (None if args.text_size is None
                 else parse_number(args.text_size, "--text-size", integer=True))
    from app.render import export as exporting
    from app.model import scene as scenes
    from app.model import shipped
    if not exporting.MIN_FPS <= fps <= exporting.MAX_FPS:
        raise InputError(f"--fps must be {exporting.MIN_FPS:g} .. {exporting.MAX_FPS:g}, "
                         f"got {args.fps.strip()}")
    if not 0 <= hold <= exporting.MAX_HOLD:
        raise InputError(f"--hold must be 0 .. {exporting.MAX_HOLD:g} seconds, "
                         f"got {args.hold.strip()}")
    if scale is not None and not 1 <= scale <= exporting.MAX_SCALE:
        raise InputError(f"--scale must be 1 .. {exporting.MAX_SCALE}, got {args.scale.strip()}")
    if text_size is not None and not exporting.MIN_TEXT <= text_size <= exporting.MAX_TEXT:
        raise InputError(f"--text-size must be {exporting.MIN_TEXT} .. {exporting.MAX_TEXT} "
                         f"pixels, got {args.text_size.strip()}")
    scene_path = shipped.scene_path(args.scene)
    try:
        scene = scenes.load(scene_path)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    from app.render import formats
    formats.check(args, scene, scene_path)
    settings = exporting.ExportSettings(
        first=args.first, last=args.last, fps=fps, hold=hold, scale=scale,
        grid_lines=not args.no_grid, primitive=not args.no_primitive,
        highlight=not args.no_highlight, caption=args.caption, panel=args.panel,
        theme=args.theme, loop=not args.once, per=args.per, memory_limit=_memory_limit(args),
        time_limit=_time_limit(args),
        unit=args.unit, reasoning=not args.no_reasoning, text_size=text_size, axes=args.axes,
        vertex_labels=args.vertex_labels, overlays=_overlays(args.overlays, scene),
        numbers=args.numbers)
    frames_limit = (exporting.MAX_FRAMES_BYTES if args.frames_limit is None
                    else budget.parse_size(args.frames_limit, "--frames-limit"))
    bar = _ProgressBar(sys.stderr)
    with drawn(recording_bar(scene.spec, scene.points, scene.options, scene.grid)) as recording:
        settings = dataclasses.replace(settings, recording=recording)
        done = _with_progress(bar, lambda: formats.export_all(
            args, scene, settings, frames_limit, bar.show if bar.active else None),
            exporting.ExportError, "export interrupted; nothing was written")
    if done is None:
        return 130
    for line in formats.summary(args, *done):
        print(line)
    return 0


def _with_progress(bar, work, error_type, interrupted: str):
    """``work()`` under a terminal progress bar: its ``error_type`` becomes a
    one-line refusal; Ctrl+C says ``interrupted`` and gives None."""
    try:
        return work()
    except error_type as error:
        raise InputError(str(error)) from None
    except KeyboardInterrupt:
        bar.clear()  # the message goes on a clean line
        print(f"rasterlab: {interrupted}", file=sys.stderr)
        return None
    finally:
        bar.clear()


class _ProgressBar(TerminalBar):
    """The export's progress: frames drawn so far."""

    def show(self, done: int, total: int) -> None:
        tail = ", writing" if done == total else ""
        self.draw("exporting", done, total, f"frames{tail} ")


# ------------------------------------------------------------------- report
def add_report_command(parser, commands) -> None:
    """`rasterlab report [--quick] [--out DIR]` (see app/analysis/report.py)."""
    report = parser.add_command(
        commands, "report", help="measure speed against error and write a report",
        description="Measure every algorithm family (operation counts, errors against the "
                    "exact oracles, times) and write report.md, measurements.csv/.json and "
                    "one PNG of cost against error per family into DIR.")
    report.add_argument("--quick", action="store_true",
                        help="smaller sweeps: about a tenth of the full report's work, "
                             "seconds where the full report takes minutes")
    report.add_argument("--out", default="rasterlab-report", metavar="DIR",
                        help="the folder to write into, made if needed (default %(default)s)")
    report.add_argument("--memory-limit", metavar="SIZE",
                        help="memory the report may need, e.g. 512M (default 2G); a report "
                             "estimated to need more is refused before it starts")
    report.add_argument("--force", action="store_true",
                        help="replace files in DIR that an earlier report did not write")


def command_report(args) -> int:
    from app.analysis import measure, report, report_budget

    check_outputs(report.outputs(args.out), force=args.force)
    report_budget.check_report(measure.settings(args.quick), _memory_limit(args))
    bar = report.ProgressBar(sys.stderr)
    result = _with_progress(bar, lambda: report.write_report(args.out, quick=args.quick,
                                                             progress=bar),
                            report.ReportError, "report interrupted")
    if result is None:
        return 130
    print(f"{result['folder']}: {', '.join(result['files'])} ({result['rows']} measurements, "
          f"{result['seconds']:.0f} s)")
    return 0


# --------------------------------------------------------------------- main
def _shield_negative_points(argv: list[str]) -> list[str]:
    # argparse takes "-3,4" for an option flag; a leading space stops that
    # and parse_number strips it again. No flag holds a comma, so "-inf,0"
    # and "-x,1" are points too, and get a message about the number.
    return [" " + arg if _NEGATIVE_POINT.match(arg) else arg for arg in argv]


_NEGATIVE_POINT = re.compile(r"^-(?!-).*,", re.DOTALL)


def utf8_streams(streams=None) -> None:
    """Make stdout and stderr write UTF-8 where they do not: Windows gives
    redirected output its code page (cp1252, ...), a C locale gives ASCII,
    and neither can write ≤, ≈ or dᵢ₊₁. A strict error handler becomes
    backslashreplace: a file name with a byte that is not UTF-8 (a lone
    surrogate, as os.fsdecode gives it) prints as \\udcff instead of
    raising; a lenient handler (surrogateescape, ...) stays."""
    for stream in (sys.stdout, sys.stderr) if streams is None else streams:
        if not hasattr(stream, "reconfigure"):
            continue  # not a text stream Python made (None under pythonw)
        errors = "backslashreplace" if stream.errors == "strict" else stream.errors
        if not _is_utf8(getattr(stream, "encoding", None)):
            stream.reconfigure(encoding="utf-8", errors=errors)
        elif errors != stream.errors:
            stream.reconfigure(errors=errors)


def _is_utf8(encoding: str | None) -> bool:
    try:
        return codecs.lookup(encoding or "").name == "utf-8"
    except LookupError:
        return False


def main(argv: list[str] | None = None) -> int:
    """The command line; ``argv`` None: the program's own (sys.argv), when
    the process is the command's alone and also gets the address-space
    backstop of the memory budget (see ``_backstop``)."""
    own = argv is None
    argv = sys.argv[1:] if own else list(argv)
    utf8_streams()
    args = argparse.Namespace(command=None)
    try:
        args = build_parser().parse_args(_shield_negative_points(argv))
        if own and args.command in BUDGETED:
            _backstop(args)
        if args.command is None:
            _check_display()
            from app.gui import launch
            return launch()
        return {"list": command_list, "run": command_run,
                "export": command_export, "report": command_report,
                "template": cli_teaching.command_template, "check": cli_teaching.command_check,
                "grader": cli_teaching.command_grader,
                "worksheet": cli_teaching.command_worksheet,
                "questions": cli_questions.command_questions}[args.command](args)
    except (CommandError, InputError, OutputRefused) as error:
        print(f"rasterlab: {one_line(str(error))}", file=sys.stderr)
        return 2
    except TraceError as error:
        print(f"rasterlab: the algorithm broke its step protocol: {one_line(str(error))}",
              file=sys.stderr)
        return 1
    except MemoryError:
        # the address-space backstop (or the system) refused an allocation
        # the estimate did not foresee
        print(f"rasterlab: the run needed more memory than its budget (--memory-limit "
              f"{budget.size_text(_memory_limit(args))}); give a smaller scene or a lower "
              "--step-cap", file=sys.stderr)
        return 2
    except BrokenPipeError:
        sys.stderr.close()  # the reader went away (`| head`); nothing to report
        return 0
    except OSError as error:
        # A file or folder the system refused (a name too long, no
        # permission, a full disk) that no command turned into its own line.
        print(f"rasterlab: {one_line(_os_reason(error))}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        # As export and report: Ctrl+C ends with one line and status 130.
        what = f"{args.command} interrupted" if args.command else "interrupted"
        print(f"rasterlab: {what}", file=sys.stderr)
        return 130


# The commands that run scenes, held to the address-space backstop.
BUDGETED = ("run", "export", "report", "worksheet", "check")


def _backstop(args) -> None:
    """Limit the address space a little above the memory budget (app/model/
    budget.py, limit_address_space). check's own --memory-limit is per case
    of the student's code, which runs in processes with their own limits."""
    memory = budget.DEFAULT_MEMORY_LIMIT if args.command == "check" else _memory_limit(args)
    budget.limit_address_space(memory)


def _check_display() -> None:
    """Refuse in one line, before Qt aborts with its own, when no display can show the window."""
    platform = os.environ.get("QT_QPA_PLATFORM", "")
    if not sys.platform.startswith("linux") or platform not in ("", "xcb", "wayland"):
        return
    if os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return
    raise CommandError("the window needs a display and none was found (DISPLAY is not set); "
                       "without one, use `rasterlab list`, `run`, `export` or `report`, or "
                       "start a virtual one: `Xvfb :99 & DISPLAY=:99 rasterlab`")


def _os_reason(error: OSError) -> str:
    """An OSError as "NAME: reason", the way the commands' own refusals read."""
    reason = error.strerror or str(error)
    return f"{error.filename}: {reason}" if error.filename is not None else reason
