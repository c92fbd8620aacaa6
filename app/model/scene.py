"""Scene files: what a person set up, saved as JSON and read back checked.

A scene file is data only: it is parsed as JSON and every field is checked
against the registry; nothing in it is ever evaluated. Saving writes a
temporary file beside the target and renames it over the target, so a save
that fails leaves the old file as it was.
"""
from __future__ import annotations

import dataclasses
import json
import math
import numbers
import os
import reprlib
import stat
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path, PurePosixPath, PureWindowsPath

from algorithms.core import registry
from algorithms.core.raster import MAX_GRID
from algorithms.core.registry import InputError
from algorithms.textures import texels

from app.model import shipped as shipped_data
from app.model.files import write_atomically
from app.model.inputs import complete, flatten, runnable_input, split_contours

VERSION = 1
ORIGINS = ("bottom-left", "top-left")
MAX_FILE_BYTES = 8 * 2 ** 20
MAX_POINTS = 100_000
RESOURCES = shipped_data.ROOT
SHIPPED = shipped_data.SCENES
TEXTURES = shipped_data.TEXTURES
MAX_MESSAGE = 300  # characters; a message quoting a huge value is cut here
# Whole numbers in a scene file have at most this many digits: every field
# is far smaller, and longer ones cannot even become a float to be checked.
MAX_DIGITS = 15


def one_line(text: str, limit: int = MAX_MESSAGE) -> str:
    """The text as one short printable line: line breaks and other control
    characters escaped as in Python strings. Past ``limit`` the middle of
    its longest words (paths, huge values) is cut, then the middle of the
    line: the end, which says what went wrong, always stays."""
    text = "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)
    words = text.split(" ")
    while len(" ".join(words)) > limit:
        longest = max(range(len(words)), key=lambda k: len(words[k]))
        if len(words[longest]) <= MAX_WORD:
            break
        words[longest] = _cut_middle(words[longest], MAX_WORD)
    return _cut_middle(" ".join(words), limit)


MAX_WORD = 60  # characters a path or value keeps when a message is too long


def _cut_middle(text: str, limit: int) -> str:
    if len(text) <= limit:
        return text
    head = (limit - 3) // 2
    return text[:head] + "..." + text[len(text) - (limit - 3 - head):]


_short = reprlib.Repr()
_short.maxstring = _short.maxother = _short.maxlong = 40


def show(value) -> str:
    """A value as a message quotes it: short, even for a huge or deep one."""
    return _short.repr(value)


class SceneError(ValueError):
    """A scene file that cannot be used; the message names the field.

    The message is always one line, whatever the file held.
    """

    def __init__(self, message: str):
        super().__init__(one_line(message))


class Frozen(dict):
    """A dict that cannot change after it is made: the options, the view
    and each bookmark of a frozen Scene. It reads, compares and writes to
    JSON as a dict does."""

    def _refuse(self, *args, **kwargs):
        raise TypeError("a scene's mappings cannot change; make a new scene with replace()")

    __setitem__ = __delitem__ = __ior__ = _refuse
    clear = pop = popitem = setdefault = update = _refuse

    def __hash__(self):
        return hash(tuple(sorted(self.items(), key=repr)))


@dataclass(frozen=True)
class Scene:
    """What a person set up: the algorithm, its points and options, the grid
    and its origin, and what a scene file adds (title, description, view,
    bookmarks). Frozen and checked when made; ``replace`` makes a changed
    copy, checked again.

    ``points`` are as the algorithm takes them: a tuple of (x, y), or for
    contour inputs a tuple of contours. A scene being drawn may hold fewer
    points than its algorithm runs on (a contour still open, one end of a
    line): ``complete`` says whether it can run.
    """

    algorithm: str = "line-bresenham"
    points: tuple = ((3, 4), (27, 15))
    options: Frozen = field(default_factory=Frozen)
    width: int = 32
    height: int = 24
    origin: str = "bottom-left"
    title: str = ""
    description: str = ""
    view: Frozen = field(default_factory=Frozen)
    bookmarks: tuple = ()  # ({"name": str, "step": int}, ...)

    def __post_init__(self):
        spec = _spec(self.algorithm)
        _grid_size(self.width, "width")
        _grid_size(self.height, "height")
        if self.origin not in ORIGINS:
            raise SceneError(f"origin: expected one of {', '.join(ORIGINS)}, "
                             f"got {show(self.origin)}")
        set_field = object.__setattr__
        set_field(self, "points", _frozen_points(spec, self.points))
        set_field(self, "options", Frozen(_options(spec, self.options)))
        set_field(self, "view", Frozen(self.view))
        set_field(self, "bookmarks", tuple(Frozen(b) for b in self.bookmarks))

    @classmethod
    def of_flat(cls, algorithm: str, points, breaks=(), **fields) -> "Scene":
        """A scene from flat points and the indices where contours 2, 3, ...
        start (as the grid and the points editor keep them)."""
        spec = _spec(algorithm)
        points = [tuple(p) for p in points]
        if spec.inputs.contours:
            points = split_contours(points, breaks) if points else []
        return cls(algorithm=algorithm, points=points, **fields)

    def replace(self, **changes) -> "Scene":
        """A copy with ``changes``, checked as a new scene is."""
        return dataclasses.replace(self, **changes)

    @property
    def spec(self):
        return registry.get(self.algorithm)

    @property
    def grid(self) -> tuple[int, int]:
        return (self.width, self.height)

    @property
    def y_down(self) -> bool:
        return self.origin == "top-left"

    @cached_property
    def flat(self) -> tuple:
        """Every point in one tuple, whatever the nesting."""
        return tuple(self.spec.inputs.flat(self.points))

    @cached_property
    def breaks(self) -> tuple[int, ...]:
        """Where contours 2, 3, ... start in ``flat`` (none but for contour inputs)."""
        return flatten(self.spec, self.points)[1]

    @property
    def complete(self) -> bool:
        """Is there enough to run (see ``inputs.complete``)?"""
        return complete(self.spec, self.flat, self.breaks, self.options)

    def runnable(self):
        """The points as the algorithm takes them, without anything still
        being drawn (see ``inputs.runnable_input``)."""
        return runnable_input(self.spec, self.flat, self.breaks, self.options)

    def to_json(self) -> dict:
        return {
            "version": VERSION,
            "title": self.title,
            "description": self.description,
            "grid": {"width": self.width, "height": self.height},
            "origin": self.origin,
            "algorithm": self.algorithm,
            "options": _json_options(self.options),
            "primitives": _primitives(self.spec.inputs, self.points),
            "view": dict(self.view),
            "bookmarks": [dict(b) for b in self.bookmarks],
        }


def _spec(algorithm):
    try:
        return registry.get(algorithm)
    except InputError as error:
        raise SceneError(f"algorithm: {error}") from None


def _frozen_points(spec, points) -> tuple:
    """The points as tuples, each two finite numbers, nested as ``spec`` takes them."""
    try:
        if spec.inputs.contours:
            return tuple(tuple(_pair(p) for p in contour) for contour in points)
        return tuple(_pair(p) for p in points)
    except (TypeError, ValueError):
        raise SceneError(f"primitives: expected {spec.inputs.text()} "
                         "of two finite numbers each") from None


def _pair(point) -> tuple:
    x, y = point
    if not all(isinstance(v, numbers.Real) and not isinstance(v, bool) and _finite(v)
               for v in (x, y)):
        raise ValueError("not two finite numbers")
    return (x, y)


def _json_options(options: dict) -> dict:
    return {k: list(v) if isinstance(v, tuple) else v for k, v in options.items()}


def _primitives(inputs, points) -> list:
    """Group the points into primitives: contours, triangles or one primitive."""
    if inputs.contours:
        return [{"points": [list(p) for p in contour]} for contour in points]
    # max(1, ...): no points at all make one empty primitive, not a zero step.
    size = max(1, inputs.count if inputs.multiple else len(points))
    groups = [points[k:k + size] for k in range(0, len(points), size)] or [[]]
    return [{"points": [list(p) for p in group]} for group in groups]


# ------------------------------------------------------------------ reading
def load(path: str | os.PathLike, *, confine: bool = True) -> Scene:
    """Read and check a scene file; SceneError names what is wrong.

    A texture file the scene names is found relative to the scene file's
    folder, else among the shipped textures, and must lie inside the one it
    is found in (links resolved): a scene cannot pull in any other picture.
    ``confine=False`` is for files this program wrote itself (the window's
    recovery copies), whose textures the person chose anywhere."""
    path = Path(path)
    name = path.name or str(path)
    data = _read_regular_file(path, name)
    try:
        # A BOM is no part of the scene: editors on some systems add one.
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise SceneError(f"{name}: not a text file (not UTF-8)") from None
    scene = parse(text, name)
    texture = _texture_file(scene)
    if texture is None:
        return scene
    try:
        found = texture_path(texture, path.parent, confine)
    except SceneError as error:
        raise SceneError(f"{name}: options.texture: {error}") from None
    return scene.replace(options={**scene.options, "texture": found})


def _texture_file(scene: Scene) -> str | None:
    """The texture file the scene's options name; None for none or a built-in texture."""
    text = scene.options.get("texture")
    return text.strip() if isinstance(text, str) and texels.is_file_name(text) else None


def texture_path(text: str, folder: Path, confine: bool = True) -> str:
    """Where a scene in ``folder`` finds the texture file ``text`` (see ``load``)."""
    if _absolute(text):
        if confine:
            raise SceneError(f"{show(text)} is an absolute path; name a texture file by its "
                             "path from the scene's folder")
        return text
    for base in (folder, TEXTURES):
        found = os.path.realpath(os.path.join(base, text))
        if _within(found, base) and os.path.exists(found):
            return found
    if confine and not _within(os.path.realpath(os.path.join(folder, text)), folder):
        raise SceneError(f"{show(text)} lies outside the scene's folder; put the texture "
                         "beside the scene")
    return os.path.join(os.path.realpath(folder), text)  # missing: reading it says so


def _absolute(text: str) -> bool:
    # Either system's form, whichever runs: C:\x and \\server\x are paths on Windows.
    windows = PureWindowsPath(text)
    return PurePosixPath(text).is_absolute() or bool(windows.drive or windows.root)


def _within(path: str, folder: Path) -> bool:
    folder = os.path.normcase(os.path.realpath(folder))
    try:
        return os.path.commonpath([os.path.normcase(path), folder]) == folder
    except ValueError:  # on another drive (Windows)
        return False


def _read_regular_file(path: Path, name: str) -> bytes:
    """The bytes of a regular file of at most MAX_FILE_BYTES.

    A FIFO, a device or a folder is refused before a byte is read: opening
    without blocking keeps a FIFO with no writer from hanging, and a pipe or
    /dev/zero never ends. A file whose size stat() cannot tell (/proc)
    is refused when it yields more than its size says.
    """
    try:
        handle = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as error:
        raise SceneError(f"{name}: cannot read the file ({error.strerror or error})") from None
    try:
        status = os.fstat(handle)
        size, kind = status.st_size, status.st_mode
        if not stat.S_ISREG(kind):
            what = "a folder" if stat.S_ISDIR(kind) else "not a regular file"
            raise SceneError(f"{name}: {what}, not a scene file")
        if size > MAX_FILE_BYTES:
            raise SceneError(f"{name}: the file is larger than {MAX_FILE_BYTES:,} bytes, "
                             "the most a scene may be")
        data = os.read(handle, size + 1)
    except OSError as error:
        raise SceneError(f"{name}: cannot read the file ({error.strerror or error})") from None
    finally:
        os.close(handle)
    if len(data) != size:
        raise SceneError(f"{name}: not a regular file (it changed size as it was read)")
    return data


def parse(text: str, name: str = "scene") -> Scene:
    try:
        data = json.loads(text, parse_constant=_reject_constant, parse_int=_whole_number,
                          parse_float=_finite_number)
    except json.JSONDecodeError as error:
        raise SceneError(f"{name}: not valid JSON ({error.msg} at line {error.lineno})") from None
    except ValueError as error:
        raise SceneError(f"{name}: {error}") from None
    except RecursionError:
        # The decoder recurses once per level of [ or {.
        raise SceneError(f"{name}: the JSON nests too deeply to be a scene") from None
    try:
        return from_json(data)
    except SceneError as error:
        raise SceneError(f"{name}: {error}") from None


def _reject_constant(constant: str):
    raise ValueError(f"{constant} is not a finite number")


def _whole_number(text: str) -> int:
    if len(text.lstrip("-")) > MAX_DIGITS:
        raise ValueError(f"the number {show(text)} is too large")
    return int(text)


def _finite_number(text: str) -> float:
    # 1e400 is valid JSON but no float: json would make it infinity.
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"the number {show(text)} is too large")
    return value


def from_json(data) -> Scene:
    if not isinstance(data, dict):
        raise SceneError("the file must hold a JSON object")
    version = _field(data, "version", int)
    if version != VERSION:
        raise SceneError(f"version: this RasterLab reads version {VERSION}, not {show(version)}")
    grid = _field(data, "grid", dict)
    width = _grid_size(grid.get("width"), "width")
    height = _grid_size(grid.get("height"), "height")
    origin = data.get("origin", "bottom-left")
    if origin not in ORIGINS:
        raise SceneError(f"origin: expected one of {', '.join(ORIGINS)}, got {show(origin)}")
    algorithm = _field(data, "algorithm", str)
    try:
        spec = registry.get(algorithm)
    except InputError as error:
        raise SceneError(f"algorithm: {error}") from None
    options = _options(spec, data.get("options", {}))
    points = _points(spec, _field(data, "primitives", list), width, height)
    return Scene(algorithm=algorithm, points=points, options=options, width=width,
                 height=height, origin=origin, title=_text(data, "title"),
                 description=_text(data, "description"), view=_view(data.get("view", {})),
                 bookmarks=_bookmarks(data.get("bookmarks", [])))


def _field(data: dict, name: str, kind: type):
    if name not in data:
        raise SceneError(f"{name}: missing")
    value = data[name]
    if kind is int and (isinstance(value, bool) or not isinstance(value, int)):
        raise SceneError(f"{name}: expected a whole number, got {show(value)}")
    if not isinstance(value, kind):
        raise SceneError(f"{name}: expected {_kind_name(kind)}, got {type(value).__name__}")
    return value


def _kind_name(kind: type) -> str:
    return {dict: "an object", list: "a list", str: "text", int: "a whole number"}[kind]


def _text(data: dict, name: str) -> str:
    value = data.get(name, "")
    if not isinstance(value, str):
        raise SceneError(f"{name}: expected text, got {type(value).__name__}")
    return value


def _grid_size(value, name: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_GRID:
        raise SceneError(f"grid.{name}: expected a whole number 1..{MAX_GRID}, got {show(value)}")
    return value


def _options(spec, options) -> dict:
    if not isinstance(options, dict):
        raise SceneError("options: expected an object")
    checked = {}
    for name, value in options.items():
        try:
            checked[name] = spec.option(name).check(value)
        except InputError as error:
            raise SceneError(f"options.{name}: {error}") from None
        except (OverflowError, RecursionError):
            # from_json also takes data that never was JSON text: an int
            # too large for a float, a list nested past repr's depth.
            raise SceneError(f"options.{name}: {show(value)} is not a usable value") from None
    return checked


def _points(spec, primitives: list, width: int, height: int) -> list:
    groups = []
    for n, primitive in enumerate(primitives):
        if not isinstance(primitive, dict) or not isinstance(primitive.get("points"), list):
            raise SceneError(f"primitives[{n}]: expected an object with a list of points")
        groups.append(primitive["points"])
    if sum(len(g) for g in groups) > MAX_POINTS:
        raise SceneError(f"primitives: more than {MAX_POINTS:,} points")
    points = groups if spec.inputs.contours else [p for group in groups for p in group]
    try:
        checked = spec.inputs.check(points)
    except (InputError, TypeError) as error:
        raise SceneError(f"primitives: {error}") from None
    except (OverflowError, RecursionError):
        # An int beyond any float, or a list nested past repr's depth.
        raise SceneError("primitives: a point is not two usable numbers") from None
    for x, y in spec.inputs.flat(checked):
        if not _inside(x, y, width, height, spec.inputs.integer):
            raise SceneError(f"primitives: point ({x}, {y}) lies outside the {width}x{height} grid")
    if spec.inputs.contours:
        return [[list(p) for p in contour] for contour in checked]
    return [list(p) for p in checked]


def _inside(x, y, width, height, integer) -> bool:
    if integer:
        return 0 <= x < width and 0 <= y < height
    return 0 <= x <= width and 0 <= y <= height


def _finite(value) -> bool:
    try:
        return math.isfinite(value)
    except OverflowError:  # an int beyond any float
        return False


# A step number or a speed beyond this is no real setting (and would not fit
# the integers the player and exporter use).
MAX_VIEW_NUMBER = 10 ** 12
_VIEW_FIELDS = {"step": int, "speed": (int, float), "show_grid": bool, "compare": bool}


def _view(view) -> dict:
    if not isinstance(view, dict):
        raise SceneError("view: expected an object")
    checked = {}
    for name, value in view.items():
        if name == "overlays":
            checked[name] = _overlay_names(value)
            continue
        kind = _VIEW_FIELDS.get(name)
        if kind is None:
            continue  # a newer program's view setting: harmless to drop
        if isinstance(value, bool) != (kind is bool) or not isinstance(value, kind):
            raise SceneError(f"view.{name}: wrong type {type(value).__name__}")
        if isinstance(value, (int, float)) and not isinstance(value, bool) and (
                not _finite(value) or not 0 <= value <= MAX_VIEW_NUMBER):
            raise SceneError(f"view.{name}: expected a number 0 .. {MAX_VIEW_NUMBER:,}, "
                             f"got {show(value)}")
        checked[name] = value
    return checked


def _overlay_names(value) -> tuple:
    """View > Overlays to switch on: names (the window and export skip one they
    do not know, as a newer program's)."""
    if not isinstance(value, list) or not all(isinstance(name, str) for name in value):
        raise SceneError("view.overlays: expected a list of overlay names")
    return tuple(value)


def _bookmarks(bookmarks) -> list:
    if not isinstance(bookmarks, list):
        raise SceneError("bookmarks: expected a list")
    checked = []
    for n, mark in enumerate(bookmarks):
        step = mark.get("step") if isinstance(mark, dict) else None
        name = mark.get("name") if isinstance(mark, dict) else None
        if not isinstance(name, str) or isinstance(step, bool) or not isinstance(step, int) or step < 0:
            raise SceneError(f"bookmarks[{n}]: expected {{\"name\": text, \"step\": whole number >= 0}}")
        checked.append({"name": name, "step": step})
    return checked


# ------------------------------------------------------------------ writing
def save(scene: Scene, path: str | os.PathLike) -> None:
    """Write the scene atomically: the old file survives any failure.

    Never a file ``load`` refuses: a scene whose indented text would be
    over MAX_FILE_BYTES is written without indentation, and one that is
    over even so is refused (SceneError) with the old file left as it was.
    A texture file inside the scene's folder or among the shipped textures
    is written as its path from there, which ``load`` finds again."""
    data = _relative_texture(scene, Path(path).parent).to_json()
    text = json.dumps(data, indent=2, allow_nan=False) + "\n"
    if len(text.encode("utf-8")) > MAX_FILE_BYTES:
        text = json.dumps(data, separators=(",", ":"), allow_nan=False) + "\n"
    encoded = text.encode("utf-8")
    if len(encoded) > MAX_FILE_BYTES:
        raise SceneError(f"{path}: the scene would take {len(encoded):,} bytes, more than the "
                         f"{MAX_FILE_BYTES:,} a scene file may hold: not saved (shorten its "
                         "description, bookmarks or points)")
    write_atomically(Path(path), encoded, SceneError)


def _relative_texture(scene: Scene, folder: Path) -> Scene:
    texture = _texture_file(scene)
    if texture is None or not os.path.isabs(texture):
        return scene
    found = os.path.realpath(texture)
    for base in (folder, TEXTURES):
        if _within(found, base):
            relative = Path(os.path.relpath(found, os.path.realpath(base))).as_posix()
            return scene.replace(options={**scene.options, "texture": relative})
    return scene  # elsewhere: opening the file again refuses it, naming the texture
