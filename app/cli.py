"""The `rasterlab` command line (see DESIGN.md for the contract).

Bad input of any kind ends with exit status 2 and one line on stderr.
"""
from __future__ import annotations

import argparse
import json
import math
import re
import sys

from algorithms import registry
from algorithms.raster import MAX_GRID
from algorithms.registry import InputError, parse_number
from algorithms.trace import DEFAULT_STEP_CAP, TraceError

DEFAULT_GRID = (32, 24)


class CommandError(Exception):
    """Bad command-line input; the message is the one line printed."""


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise CommandError(message)


def build_parser() -> Parser:
    parser = Parser(prog="rasterlab", description=(
        "Step through rasterization algorithms on a magnified pixel grid. "
        "With no command, the window opens."))
    commands = parser.add_subparsers(dest="command", parser_class=Parser)
    listing = commands.add_parser("list", help="list the algorithms")
    listing.add_argument("--json", action="store_true", help="print JSON")
    run = commands.add_parser("run", help="run an algorithm headless and print its pixels")
    run.add_argument("algorithm", nargs="?", help="algorithm name, as `rasterlab list` shows it")
    run.add_argument("--points", nargs="+", action="append", metavar="X,Y",
                     help="points in pixel coordinates (y up); repeat once per contour")
    run.add_argument("--scene", metavar="SCENE.json",
                     help="run a saved scene instead of ALGO --points (options and grid from the file)")
    run.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                     help="set an option (numbers, names, true/false, comma lists)")
    run.add_argument("--grid", metavar="W,H",
                     help=f"grid size, at most {MAX_GRID},{MAX_GRID} (default: fits the points, "
                          f"at least {DEFAULT_GRID[0]},{DEFAULT_GRID[1]})")
    run.add_argument("--step-cap", type=str, default=str(DEFAULT_STEP_CAP), metavar="N",
                     help="stop recording after N steps (default %(default)s)")
    output = run.add_mutually_exclusive_group()
    output.add_argument("--json", action="store_true", help="print one JSON object")
    output.add_argument("--ascii", action="store_true", help="print the grid as text")
    return parser


# ------------------------------------------------------------------ parsing
def parse_point(text: str) -> tuple[float, float]:
    parts = text.split(",")
    if len(parts) != 2:
        raise InputError(f"point {text!r} must be X,Y")
    return tuple(parse_number(part, f"point {text!r}") for part in parts)


def parse_grid(text: str) -> tuple[int, int]:
    parts = text.split(",")
    if len(parts) != 2:
        raise InputError(f"grid {text!r} must be W,H")
    width, height = (parse_number(part, f"grid {text!r}", integer=True) for part in parts)
    if not (1 <= width <= MAX_GRID and 1 <= height <= MAX_GRID):
        raise InputError(f"grid {width}x{height} is outside 1x1 .. {MAX_GRID}x{MAX_GRID}")
    return width, height


def parse_step_cap(text: str) -> int:
    step_cap = parse_number(text, "--step-cap", integer=True)
    if step_cap < 1:
        raise InputError("--step-cap must be at least 1")
    return step_cap


def parse_settings(spec, settings: list[str]) -> dict:
    options = {}
    for setting in settings:
        key, sep, value = setting.partition("=")
        if not sep or not key.strip():
            raise InputError(f"--set {setting!r} must be KEY=VALUE")
        options[key.strip()] = spec.option(key.strip()).parse(value)
    return options


def fit_grid(points, grid_text: str | None, integer: bool = True) -> tuple[int, int]:
    """The given grid, or the smallest default-or-larger grid holding the points.

    Integer points name pixels, so they lie in 0..W-1; real points are
    positions, which may lie anywhere in [0, W] x [0, H].
    """
    def extent(v):
        return math.floor(v) + 1 if integer else math.ceil(v)

    if grid_text is not None:
        width, height = parse_grid(grid_text)
    else:
        width = max([DEFAULT_GRID[0]] + [extent(x) for x, _ in points])
        height = max([DEFAULT_GRID[1]] + [extent(y) for _, y in points])
        if width > MAX_GRID or height > MAX_GRID:
            raise InputError(f"the points need a grid larger than {MAX_GRID}x{MAX_GRID}")
    for x, y in points:
        inside_x = 0 <= x < width if integer else 0 <= x <= width
        inside_y = 0 <= y < height if integer else 0 <= y <= height
        if not (inside_x and inside_y):
            raise InputError(f"point ({_plain(x)}, {_plain(y)}) lies outside the "
                             f"{width}x{height} grid")
    return width, height


def _plain(value: float):
    return int(value) if float(value).is_integer() else value


# ----------------------------------------------------------------- commands
def command_list(args) -> int:
    specs = registry.all_specs()
    if args.json:
        print(json.dumps([spec.describe() for spec in specs], indent=2))
        return 0
    for spec in specs:
        options = ", ".join(f"{o.name}={_default_text(o.default)}" for o in spec.options)
        print(f"{spec.name:<20} {spec.family:<8} {spec.inputs.count} points  "
              f"{spec.summary}" + (f"  [{options}]" if options else ""))
    return 0


def _default_text(value) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (tuple, list)):
        return ",".join(map(str, value)) or "none"
    return str(value)


def command_run(args) -> int:
    if args.scene is not None:
        return run_scene(args)
    if args.algorithm is None or args.points is None:
        raise CommandError("run needs ALGO and --points, or --scene SCENE.json")
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
    spec.inputs.check(points)
    grid = fit_grid(spec.inputs.flat(points), args.grid, spec.inputs.integer)
    trace = spec.record(points, options, grid=grid, step_cap=step_cap)
    return print_run(args, spec, trace, options)


def run_scene(args) -> int:
    from app import scene as scenes
    if args.algorithm is not None or args.points is not None or args.set or args.grid:
        raise CommandError("--scene takes its algorithm, points, options and grid from the file")
    step_cap = parse_step_cap(args.step_cap)
    try:
        scene = scenes.load(args.scene)
    except scenes.SceneError as error:
        raise InputError(str(error)) from None
    spec = scene.spec
    trace = spec.record(scene.points, scene.options, grid=(scene.width, scene.height),
                        step_cap=step_cap)
    return print_run(args, spec, trace, scene.options)


def print_run(args, spec, trace, options) -> int:
    if trace.truncated:
        print(f"rasterlab: {trace.message}", file=sys.stderr)
    if args.json:
        print(json.dumps(run_result(spec, trace, options)))
    elif args.ascii:
        print(ascii_grid(trace))
    else:
        print(summary(spec, trace))
    return 0


def run_result(spec, trace, options) -> dict:
    """The JSON object of `run --json`."""
    result = {
        "algorithm": spec.name,
        "grid": [trace.width, trace.height],
        "pixels": trace.written_pixels().tolist(),
        "steps": len(trace),
        "final": _jsonable(trace.final_variables()),
        "options": _jsonable(spec.resolve(options)),
    }
    values = trace.pixel_values()
    if values is not None:
        result["values"] = _pixel_values(trace.start.pixel_value, values)
    if trace.truncated:
        result["truncated"] = True
        result["message"] = trace.message
    return result


def _pixel_values(name: str, values) -> list:
    if name == "rgb":
        return [f"#{int(v):06x}" for v in values]
    return [float(v) for v in values]


def _jsonable(mapping: dict) -> dict:
    result = {}
    for key, value in mapping.items():
        if isinstance(value, tuple):
            value = list(value)
        elif hasattr(value, "item"):
            value = value.item()
        if isinstance(value, float) and not math.isfinite(value):
            value = None
        result[key] = value
    return result


def ascii_grid(trace) -> str:
    """The final raster as text, top row first: '#' written, '+' written again, '.' empty."""
    counts = trace.raster_at(len(trace) - 1).counts
    rows = []
    for y in range(trace.height - 1, -1, -1):
        rows.append("".join("." if c == 0 else ("#" if c == 1 else "+") for c in counts[y]))
    return "\n".join(rows)


def summary(spec, trace) -> str:
    pixels = trace.written_pixels().tolist()
    final = ", ".join(f"{k}={registry.format_value(v)}" for k, v in trace.final_variables().items())
    return "\n".join([
        f"{spec.title} ({spec.name}) on a {trace.width}x{trace.height} grid: "
        f"{len(pixels)} pixels written in {len(trace)} steps",
        "pixels: " + " ".join(f"{x},{y}" for x, y in pixels),
        f"final: {final}",
    ])


# --------------------------------------------------------------------- main
def _shield_negative_points(argv: list[str]) -> list[str]:
    # argparse takes "-3,4" for an option flag; a leading space stops that
    # and parse_number strips it again.
    return [" " + arg if _NEGATIVE_POINT.match(arg) else arg for arg in argv]


_NEGATIVE_POINT = re.compile(r"^-[0-9.]+.*,")


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        args = build_parser().parse_args(_shield_negative_points(argv))
        if args.command is None:
            from app.window import launch
            return launch()
        return {"list": command_list, "run": command_run}[args.command](args)
    except (CommandError, InputError) as error:
        print(f"rasterlab: {error}", file=sys.stderr)
        return 2
    except TraceError as error:
        print(f"rasterlab: the algorithm broke its step protocol: {error}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        sys.stderr.close()  # the reader went away (`| head`); nothing to report
        return 0
