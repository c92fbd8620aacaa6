"""Algorithm specs by name: family, inputs, options, pseudo-code, generator."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Callable

from algorithms.core.errors import InputError
from algorithms.core.steps import CodeLine
from algorithms.core.trace import DEFAULT_STEP_CAP, Trace, checkpoint, watching

FAMILIES = ("lines", "circles", "polygons", "fill", "triangles", "visibility", "antialias",
            "textures", "pipeline")
# Each family is the package algorithms.<family>; importing it registers its
# algorithms, in the order its __init__ imports its modules.


@dataclass(frozen=True)
class Option:
    """A typed option with a default and, where it applies, a range."""

    name: str
    kind: str  # "int", "float", "bool", "choice", "colors", "point", "numbers" or "text"
    default: object
    help: str = ""
    minimum: float | None = None
    maximum: float | None = None
    choices: tuple[str, ...] = ()  # names a "choice" takes, or a number may be instead of

    def parse(self, text: str):
        """Turn command-line text into a checked value."""
        text = text.strip()
        if text in self.choices:
            return text
        if self.kind == "bool":
            if text.lower() in ("true", "yes", "on", "1"):
                return True
            if text.lower() in ("false", "no", "off", "0"):
                return False
            raise InputError(f"option {self.name}: expected true or false, got {text!r}")
        if self.kind == "choice":
            raise InputError(f"option {self.name}: expected one of {', '.join(self.choices)}, got {text!r}")
        if self.kind == "colors":
            return self.check([part for part in text.split(",") if part.strip()])
        if self.kind == "text":
            return self.check(text)
        if self.kind == "numbers":
            parts = [part for part in text.split(",") if part.strip()]
            return self.check(tuple(parse_number(part, f"option {self.name}") for part in parts))
        if self.kind == "point":
            parts = text.split(",")
            if len(parts) != 2:
                raise InputError(f"option {self.name}: expected X,Y, got {text!r}")
            return self.check(tuple(parse_number(part, f"option {self.name}") for part in parts))
        return self.check(parse_number(text, f"option {self.name}", integer=self.kind == "int"))

    def check(self, value):
        """Check a typed value (from the command line or a widget)."""
        if isinstance(value, str) and value in self.choices:
            return value
        checker = _CHECKERS.get(self.kind)
        if checker is None:
            raise InputError(f"option {self.name}: unknown kind {self.kind!r}")
        return checker(self, value)

    def describe(self) -> dict:
        info = {"name": self.name, "type": self.kind, "default": self.default, "help": self.help}
        if self.minimum is not None:
            info["min"] = self.minimum
        if self.maximum is not None:
            info["max"] = self.maximum
        if self.choices:
            info["choices"] = list(self.choices)
        return info


def _check_number(option: Option, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"option {option.name}: expected a number, got {value!r}")
    if not math.isfinite(value):
        raise InputError(f"option {option.name}: {value} is not a finite number")
    if option.kind == "int" and not float(value).is_integer():
        raise InputError(f"option {option.name}: expected a whole number, got {value}")
    if option.minimum is not None and value < option.minimum:
        raise InputError(f"option {option.name}: {value} is below the minimum {option.minimum}")
    if option.maximum is not None and value > option.maximum:
        raise InputError(f"option {option.name}: {value} is above the maximum {option.maximum}")
    return int(value) if option.kind == "int" else float(value)


def _check_bool(option: Option, value):
    if not isinstance(value, bool):
        raise InputError(f"option {option.name}: expected true or false, got {value!r}")
    return value


def _check_choice(option: Option, value):
    raise InputError(f"option {option.name}: expected one of {', '.join(option.choices)}, got {value!r}")


_COLOR = re.compile(r"#[0-9a-fA-F]{6}")


def _check_colors(option: Option, value):
    if not isinstance(value, (list, tuple)):
        raise InputError(f"option {option.name}: expected a list of #rrggbb colours")
    colors = []
    for item in value:
        if not isinstance(item, str) or not _COLOR.fullmatch(item.strip()):
            raise InputError(f"option {option.name}: {item!r} is not a #rrggbb colour")
        colors.append(item.strip().lower())
    return tuple(colors)


def _check_point(option: Option, value):
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise InputError(f"option {option.name}: expected a point X,Y, got {value!r}")
    for item in value:
        if isinstance(item, bool) or not isinstance(item, (int, float)) or not math.isfinite(item):
            raise InputError(f"option {option.name}: {item!r} is not a finite number")
        if not float(item).is_integer():
            raise InputError(f"option {option.name}: {item} is not a whole pixel coordinate")
        if option.minimum is not None and item < option.minimum:
            raise InputError(f"option {option.name}: {item:,.0f} is below {option.minimum:,.0f}")
        if option.maximum is not None and item > option.maximum:
            raise InputError(f"option {option.name}: {item:,.0f} is above {option.maximum:,.0f}")
    return (int(value[0]), int(value[1]))


def _check_numbers(option: Option, value):
    if not isinstance(value, (list, tuple)):
        raise InputError(f"option {option.name}: expected a list of numbers such as 1,2,3")
    for item in value:
        if isinstance(item, bool) or not isinstance(item, (int, float)) or not math.isfinite(item):
            raise InputError(f"option {option.name}: {item!r} is not a finite number")
    return tuple(float(item) for item in value)


def _check_text(option: Option, value):
    # What the text names (a file, say) is checked by the algorithm that reads it.
    if not isinstance(value, str) or not value.strip():
        raise InputError(f"option {option.name}: expected a name, got {value!r}")
    return value.strip()


_CHECKERS = {"int": _check_number, "float": _check_number, "bool": _check_bool,
             "choice": _check_choice, "colors": _check_colors, "point": _check_point,
             "numbers": _check_numbers, "text": _check_text}


def parse_number(text: str, what: str, integer: bool = False):
    """Parse a finite number; whole numbers only when ``integer``.

    One syntax everywhere: ASCII digits with an optional sign, point and
    exponent (``-3``, ``2.5``, ``1e3``). float() alone would also take
    Arabic-Indic or full-width digits and ``1_0``.
    """
    if not _NUMBER.fullmatch(text.strip(" \t\n\r\f\v")):
        raise InputError(f"{what}: {text!r} is not a number")
    value = float(text)
    if not math.isfinite(value):
        raise InputError(f"{what}: {text!r} is not a finite number")
    if integer:
        if not value.is_integer():
            raise InputError(f"{what}: {text!r} is not a whole number")
        return int(value)
    return value


# inf and nan pass, to be refused as "not a finite number".
_NUMBER = re.compile(r"[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
                     r"|inf|infinity|nan)", re.IGNORECASE | re.ASCII)


# Whole-number points (lines, circles, outlines) stay within +-2^30 px, so
# that every pixel an algorithm reaches from them fits a frame's 32-bit x, y.
MAX_INTEGER_COORDINATE = 1 << 30


def _finite(value) -> bool:
    try:
        return math.isfinite(value)
    except OverflowError:  # an int beyond any float
        return False


def _brief(value) -> str:
    """A value for a one-line message, however long its digits."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 64:
        return f"a whole number of {value.bit_length()} bits"
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


@dataclass(frozen=True)
class Inputs:
    """What points an algorithm takes.

    Most algorithms take one list of exactly ``count`` points. With
    ``multiple`` they take k * count points (k triangles of 3 points). With
    ``contours`` the input is a list of contours (polygons with holes), each
    of at least ``count`` points.
    """

    count: int
    integer: bool = True
    names: tuple[str, ...] = ()  # e.g. ("P", "Q")
    contours: bool = False
    multiple: bool = False

    def check(self, points) -> tuple:
        if not self.contours:
            return self._check_list(points, exact=True)
        if len(points) == 0:
            raise InputError("expected at least one contour")
        return tuple(self._check_list(contour, exact=False, label=f"contour {n + 1}: ")
                     for n, contour in enumerate(points))

    def _check_list(self, points, exact: bool, label: str = "") -> tuple:
        if self.multiple and (len(points) == 0 or len(points) % self.count):
            raise InputError(f"{label}expected a multiple of {self.count} points, got {len(points)}")
        if exact and not self.multiple and len(points) != self.count:
            raise InputError(f"{label}expected {self.count} points, got {len(points)}")
        if not exact and len(points) < self.count:
            raise InputError(f"{label}expected at least {self.count} points, got {len(points)}")
        checked = []
        for n, point in enumerate(points):
            if not n & 4095:
                checkpoint()  # 100,000 points take about a second
            checked.append(self._check_point(point, f"{label}point {n + 1}"))
        return tuple(checked)

    def _check_point(self, point, label: str) -> tuple:
        if len(point) != 2:
            raise InputError(f"{label} must have two coordinates")
        for value in point:
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not _finite(value):
                raise InputError(f"{label}: {_brief(value)} is not a finite number")
            if self.integer and not float(value).is_integer():
                raise InputError(f"{label}: {value} is not a whole pixel coordinate")
        return tuple(int(v) if self.integer else float(v) for v in point)

    def check_range(self, points) -> None:
        """Whole-number points must lie within +-MAX_INTEGER_COORDINATE: frames keep
        pixel coordinates as 32-bit integers. (Checked when a run starts, so the
        command line's own grid check speaks first.)"""
        if not self.integer:
            return
        for n, (x, y) in enumerate(self.flat(points)):
            for value in (x, y):
                if abs(value) > MAX_INTEGER_COORDINATE:
                    raise InputError(f"point {n + 1}: {_brief(value)} is beyond "
                                     f"+-{MAX_INTEGER_COORDINATE:,} px")

    def text(self) -> str:
        """How many points, in words: "2 points", "3k points", ..."""
        if self.contours:
            return f"contours of >= {self.count} points"
        if self.multiple:
            return f"{self.count}k points"
        return f"{self.count} point" + ("s" if self.count != 1 else "")

    def flat(self, points) -> list:
        """Every point, whatever the nesting."""
        return [p for contour in points for p in contour] if self.contours else list(points)


ORACLE_KINDS = ("exact", "reference", "none")


@dataclass(frozen=True)
class Oracle:
    """What the tests hold an algorithm's results to.

    ``kind``: "exact" (integer or rational arithmetic written apart from the
    algorithm: algorithms/exact/ or tests/support/), "reference" (a plain
    definition or a well-kept library, with a stated tolerance where
    floats differ), or "none" (``about`` says why, "No independent oracle
    ...", and what is checked; a smoke test still runs it). ``about`` says
    what the algorithm is held to; ``tests`` names the test modules that do
    it (paths under tests/). ``check`` names the check
    tests/algorithms/test_stability.py runs on each of its hard cases
    (empty: only the checks every algorithm gets there).
    """

    kind: str
    about: str
    tests: tuple[str, ...] = ()
    check: str = ""

    def __post_init__(self):
        if self.kind not in ORACLE_KINDS:
            raise ValueError(f"oracle kind {self.kind!r} is not one of {ORACLE_KINDS}")


@dataclass(frozen=True)
class AlgorithmSpec:
    """Everything the program knows about one algorithm."""

    name: str
    title: str
    family: str
    summary: str
    inputs: Inputs
    options: tuple[Option, ...]
    # The pseudo-code, which may depend on the points and options (the
    # tie rule Bresenham uses depends on both, say).
    code: Callable[[tuple, dict], tuple[CodeLine, ...]]
    generator: Callable[[tuple, dict], object]
    kernel: Callable[[tuple, dict], object] | None = None
    notes: tuple[str, ...] = field(default=())  # shown under the pseudo-code
    # Extra panel rows (name, text) for a step, beyond the named variables:
    # the decision and its update, say. Called for the visible step only.
    explain: Callable[[Trace, int], list[tuple[str, str]]] | None = None
    # The generator also takes the grid (width, height) as a third argument:
    # a flood fill is bounded by the grid's edges.
    uses_grid: bool = False
    # What a run's steps walk over, for the budget (app/model/budget.py):
    # the primitive's own pixels ("path"), every pixel of its bounding box
    # ("box") or of the grid ("grid").
    visits: str = "path"
    # Seconds a recorded step takes, where that is well above its family's
    # figure in the budget (benchmarks/bench_budget.py --steps measures it).
    step_seconds: float | None = None
    # `run --json`'s "fragments": (key, value column) pairs reported per written pixel.
    fragments: tuple[tuple[str, str], ...] = ()
    # What the tests hold the results to (every shipped algorithm declares
    # one; a spec loaded at run time, a student's file, has none).
    oracle: Oracle | None = None

    def option(self, name: str) -> Option:
        for option in self.options:
            if option.name == name:
                return option
        known = ", ".join(o.name for o in self.options) or "none"
        raise InputError(f"{self.name} has no option {name!r} (options: {known})")

    def resolve(self, given: dict | None = None) -> dict:
        """Defaults overlaid with the given options, each checked."""
        options = {option.name: option.default for option in self.options}
        for name, value in (given or {}).items():
            options[name] = self.option(name).check(value)
        return options

    def frames(self, points, options: dict | None = None, grid=(32, 24)):
        """Check the inputs and start the generator."""
        options = self.resolve(options)
        points = self.inputs.check(points)
        self.inputs.check_range(points)
        return self._start(points, options, grid)

    def record(self, points, options: dict | None = None, grid=(32, 24),
               step_cap: int = DEFAULT_STEP_CAP, monitor=None) -> Trace:
        """Record a run; ``monitor`` (trace.RecordMonitor) hears progress and may cancel."""
        with watching(monitor, step_cap):  # the work before the first frame: cancel and cap
            options = self.resolve(options)
            points = self.inputs.check(points)
            self.inputs.check_range(points)
            frames = self._start(points, options, grid)
            code = self.code(points, options)
        return Trace.record(frames, code, grid[0], grid[1], step_cap, monitor)

    def _start(self, points, options, grid):
        if self.uses_grid:
            return self.generator(points, options, (int(grid[0]), int(grid[1])))
        return self.generator(points, options)

    def panel_rows(self, trace: Trace, i: int) -> list[tuple[str, str]]:
        """Rows for the variables panel at step i: named values, then extras."""
        rows = [(name, format_value(value)) for name, value in trace.variables_at(i).items()]
        if self.explain is not None:
            rows += self.explain(trace, i)
        return rows

    def describe(self) -> dict:
        return {"name": self.name, "title": self.title, "family": self.family,
                "summary": self.summary,
                "inputs": {"points": self.inputs.count, "integer": self.inputs.integer,
                           "contours": self.inputs.contours, "multiple": self.inputs.multiple},
                "options": [option.describe() for option in self.options],
                "fast_kernel": self.kernel is not None}


def format_value(value) -> str:
    """Short text for a panel: whole numbers without a decimal point."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, float) and value.is_integer() and abs(value) < 2 ** 53:
        return str(int(value))
    if isinstance(value, float):
        return repr(value)  # shortest exact text: float drift must stay visible
    return str(value)


_REGISTRY: dict[str, AlgorithmSpec] = {}
_ORDER: dict[str, tuple] = {}  # name -> (family, added at run time, registration) for listing


def register(spec: AlgorithmSpec, replace: bool = False) -> AlgorithmSpec:
    """Add a spec loaded at run time (a student's file), listed after its
    family's own. ``replace``: a student's file opened again takes the place
    of the spec of its name."""
    _load()
    return _add(spec, replace, at_run_time=True)


def _add(spec: AlgorithmSpec, replace: bool, at_run_time: bool) -> AlgorithmSpec:
    if spec.name in _REGISTRY and not replace:
        raise ValueError(f"algorithm {spec.name!r} registered twice")
    if spec.family not in FAMILIES:
        raise ValueError(f"unknown family {spec.family!r}")
    _REGISTRY[spec.name] = spec
    _ORDER[spec.name] = (FAMILIES.index(spec.family), at_run_time, len(_ORDER))
    return spec


def unregister(name: str) -> None:
    """Forget a spec registered at run time (a student's file); no-op for others."""
    _REGISTRY.pop(name, None)


_loaded = False  # every family's specs added (asked on every step: keep it cheap)


def _load() -> None:
    """Add the specs each family package declares (algorithms.<family>.SPECS)."""
    global _loaded
    if _loaded:
        return
    import importlib
    packages = [importlib.import_module(f"algorithms.{family}") for family in FAMILIES]
    _loaded = True
    for package in packages:
        for spec in package.SPECS:
            _add(spec, replace=False, at_run_time=False)


def all_specs() -> list[AlgorithmSpec]:
    """Every spec, family by family in FAMILIES order, and within a family in
    the order the family declares them (specs registered at run time last)."""
    _load()
    return sorted(_REGISTRY.values(), key=lambda spec: _ORDER[spec.name])


def get(name: str) -> AlgorithmSpec:
    _load()
    try:
        return _REGISTRY[name]
    except KeyError:
        raise InputError(f"unknown algorithm {name!r}; `rasterlab list` shows them") from None
