"""RasterLab from Python: run an algorithm, look at its steps as plain data,
show the interactive player in a notebook, export, and check a student's
file. ``import rasterlab`` gives these names (rasterlab/__init__.py loads
this module on first use, so the command's start-up never does).

Each function does what a command does, through the same code: ``run`` and
``open_scene`` as `rasterlab run` (app/model/runs.py), ``Run.export`` and
``export`` as `rasterlab export` (app/render/formats.py), ``check`` as
`rasterlab check` (app/teaching/check_run.py), ``question`` as one variant
of `rasterlab questions` (app/teaching/questions/). Bad input raises ValueError
with the one line the command would print; nothing here imports Qt.
"""
from __future__ import annotations

import os
import warnings
from dataclasses import fields
from functools import cached_property
from pathlib import Path

from algorithms.core import registry
from algorithms.core.registry import InputError
from algorithms.core.trace import DEFAULT_STEP_CAP, MAX_STEP_CAP
from app.model import budget, runs
from app.model import scene as scenes
from app.model import shipped
from app.model.escape import html_text

__all__ = ["run", "open_scene", "export", "check", "question", "Run", "CheckResult"]

FORMATS = ("gif", "mp4", "webm", "pdf", "html", "png", "svg")
FOLDERS = ("png", "svg")  # a folder of frames: named by format=, never by a suffix
PLAYER_HEIGHT = 640  # pixels the player takes in a notebook: grid, code, transport and steps


def run(algorithm: str, points, *, grid=None, step_cap: int = DEFAULT_STEP_CAP,
        **options) -> "Run":
    """Run an algorithm on points, as `rasterlab run` does.

    algorithm: its name as `rasterlab list` shows it, e.g. "line-bresenham".
    points: a list of (x, y) in pixel coordinates, y up; for the algorithms
        that take contours (polygon-scanline, flood-fill, ...) a list of
        contours, each a list of (x, y).
    grid: (width, height) of the grid, at most 4096 each; None fits the
        points, at least 32x24.
    step_cap: the most steps recorded, 1 .. 50,000,000; a longer run stops
        there with a RuntimeWarning and ``Run.truncated`` set.
    options: the algorithm's options by name (`rasterlab list` shows them
        with their defaults), as Python values (True, 3, "queue",
        ["#ff0000"]) or as the text `--set` takes ("true", "3").

    Raises ValueError with one line when anything is wrong.
    """
    spec = registry.get(algorithm)
    checked = _options(spec, options)
    cap = _step_cap(step_cap)
    points = _points(spec, points)
    size = runs.fit_grid(spec.inputs.flat(points), _grid(grid), spec.inputs.integer)
    trace = runs.record(spec, points, checked, size, cap)
    scene = scenes.Scene(algorithm=spec.name, points=points, options=checked,
                         width=size[0], height=size[1])
    return Run(scene, trace)


def open_scene(name_or_path, *, step_cap: int = DEFAULT_STEP_CAP) -> "Run":
    """Run a scene: a shipped one by name (`rasterlab list --scenes`, e.g.
    "demo-bresenham") or a scene file saved by RasterLab.

    name_or_path: the name, or the path of a .json scene file.
    step_cap: as for ``run``.
    """
    scene = _load(name_or_path)
    trace = runs.record(scene.spec, scene.points, scene.options, scene.grid, _step_cap(step_cap))
    return Run(scene, trace)


def export(run_or_scene, path, **settings) -> str:
    """Export a run as `rasterlab export` does; the line it prints.

    run_or_scene: a Run, or a shipped scene's name or a scene file (run
        afresh within the export's own memory limit).
    path, settings: as for ``Run.export``.
    """
    if isinstance(run_or_scene, Run):
        return run_or_scene.export(path, **settings)
    return _export(_load(run_or_scene), None, path, settings)


class Run:
    """One recorded run: its input, pixels, values, variables and steps as
    plain Python data (ints, floats, strings, lists, tuples and dicts, as
    `rasterlab run --json` prints them), and the ways to save, export and
    show it. Made by ``run`` and ``open_scene``.

    algorithm: the algorithm's name.
    points: the points, as tuples (a list of contours for contour algorithms).
    options: every option of the algorithm, the defaults filled in.
    grid: (width, height).
    pixels: the pixels written, (x, y) in drawing order, as often as written.
    values: per written pixel, its value (coverage 0..1, or "#rrggbb") for
        the algorithms that give one; else None.
    variables: the variables at the end of the run, by name.
    steps: one dict per step (see ``steps``).
    truncated: whether the step cap cut the run short.
    """

    def __init__(self, scene, trace):
        self._scene, self._trace = scene, trace
        if trace.truncated:
            warnings.warn(trace.message, RuntimeWarning, stacklevel=3)

    @cached_property
    def _result(self) -> dict:
        result = runs.run_result(self._scene.spec, self._trace, self._scene.options)
        return {key: value.tolist() if isinstance(value, runs.Rows) else value
                for key, value in result.items()}

    @property
    def algorithm(self) -> str:
        return self._scene.algorithm

    @property
    def points(self) -> list:
        if self._scene.spec.inputs.contours:
            return [list(contour) for contour in self._scene.points]
        return list(self._scene.points)

    @property
    def options(self) -> dict:
        return dict(self._result["options"])

    @property
    def grid(self) -> tuple[int, int]:
        return self._scene.grid

    @property
    def pixels(self) -> list[tuple[int, int]]:
        return [tuple(pixel) for pixel in self._result["pixels"]]

    @property
    def values(self) -> list | None:
        values = self._result.get("values")
        return None if values is None else list(values)

    @property
    def variables(self) -> dict:
        return dict(self._result["final"])

    @property
    def truncated(self) -> bool:
        return bool(self._trace.truncated)

    @cached_property
    def steps(self) -> list[dict]:
        """Per step, the cells of `rasterlab run --steps --json`: "step"
        (0, 1, ...), "line" (the pseudo-code line, from 1), "code" (its
        text), "pixel" (the step's pixel as (x, y), or None), "choice" (the
        branch taken, or None), "variables" (the values shown at that step)
        and "tables" (the latest edge tables and such, as lists of rows)."""
        from app.model import step_output, steptable
        table = steptable.StepTable(self._trace)
        steps = [step_output.json_step(table, i) for i in range(len(table))]
        for step in steps:
            if isinstance(step["pixel"], list):
                step["pixel"] = tuple(step["pixel"])
        return steps

    def to_scene(self) -> dict:
        """The run's scene as the JSON data of a scene file."""
        return self._scene.to_json()

    def save(self, path, *, force: bool = False) -> Path:
        """Write the run's scene file (atomically) and return its path; the
        window, `rasterlab run --scene` and `rasterlab export` open it.

        path: the file to write, e.g. "line.json".
        force: replace a file that exists (else ValueError).
        """
        runs.save_new(self._scene, path, force, "give force=True to replace it")
        return Path(path)

    def export(self, path, **settings) -> str:
        """Export the run as `rasterlab export` does; the line it prints.

        path: the file to write; its suffix picks the format: .gif, .mp4,
            .webm, .pdf or .html. A folder of numbered frames takes
            format="png" or format="svg". A file is written whole or not at
            all; an existing one of the format written is replaced (another
            only with force=True), a link's target is written.
        settings: format (one of gif, mp4, webm, pdf, html, png, svg), force
            (replace a file RasterLab did not write; write a page over its
            size budget), transcript (default True: the steps in words
            beside a GIF as NAME.txt, beside a video as NAME.vtt captions),
            and those of `rasterlab
            export`, by their Python names: first, last (steps or bookmark
            names), fps, hold, scale, caption, panel, unit, text_size,
            theme, loop, per, axes, vertex_labels, overlays ("all" or a
            list), reasoning, grid_lines, primitive, highlight, grid_text,
            memory_limit (bytes, or a size such as "4G").
        """
        return _export(self._scene, self._trace, path, settings)

    def _repr_html_(self) -> str:
        """The interactive player, inline in Jupyter and VS Code notebooks:
        the self-contained page of `export --html` in an iframe's srcdoc,
        sandboxed to run scripts only. A notebook that does not show it
        (not trusted) shows the line under it instead."""
        from app.render import html as page
        from app.render.settings import ExportError, ExportSettings
        settings = ExportSettings().for_grid(*self.grid)
        try:
            text = page.page_bytes(self._scene, self._trace, settings).decode("utf-8")
        except ExportError as error:
            return f"<p>{html_text(str(error))}</p>"
        return (f'<div style="position:relative;height:{PLAYER_HEIGHT}px">'
                '<p style="position:absolute;margin:8px">RasterLab\'s player shows here when '
                'the notebook is trusted.</p>'
                f'<iframe srcdoc="{html_text(text)}" sandbox="allow-scripts" '
                f'title="RasterLab: {html_text(self.algorithm)}" style="position:absolute;'
                'width:100%;height:100%;border:1px solid #d5dbe3"></iframe></div>')

    def __repr__(self) -> str:
        width, height = self.grid
        return (f"<Run {self.algorithm} on a {width}x{height} grid: {len(self._result['pixels'])} "
                f"pixels written in {len(self._trace)} steps>")


def check(student_file, *, algorithm: str, cases="hard", seed: int = 0,
          time_limit: float = 2, memory_limit="256M",
          require_sandbox: bool = False) -> "CheckResult":
    """Check a student's algorithm as `rasterlab check` does: the file's
    generator draw(...) runs in a separate process on each case, with the
    same limits, and its pixels are compared with the reference's and the
    exact result.

    student_file: the student's .py file (see the templates RasterLab ships).
    algorithm: the reference, as `rasterlab list` names it, e.g. "line-bresenham".
    cases: "hard" (the hard-case catalogue), "random N", a scene file, or a
        list of these words, e.g. ["hard", "random", 5, "my-scene.json"].
    seed: the seed of the random cases.
    time_limit: CPU seconds per case, 0.1 .. 60.
    memory_limit: memory per case, 64M .. 8G: bytes or a size such as "512M".
    require_sandbox: refuse (ValueError) where the bubblewrap sandbox is not
        available; without it the text says which isolation was in force.
    """
    from app.teaching import check_report
    from app.teaching.check_run import run_check
    checked = run_check(student_file, algorithm, _case_words(cases), str(seed), str(time_limit),
                        str(memory_limit), require_sandbox=require_sandbox)
    return CheckResult(check_report.as_json(*checked),
                       "\n".join(check_report.text_lines(*checked)))


def question(template: str, seed: int, scene=None):
    """One variant of a question template, as `rasterlab questions` draws it:
    the same template and seed give the same question.

    template: its name, as `rasterlab questions --list` shows it.
    seed: a whole number; it picks the variant's inputs.
    scene: None, or a scene (a Scene, a path, a shipped scene's name, or a Run) of an
        algorithm the template asks about, whose inputs the question uses.
    Returns a Question (app/teaching/questions/model.py): text, answer,
    worked steps, scene and picture (PNG bytes).
    """
    from app.teaching.questions import registry as questions
    if isinstance(seed, bool) or not isinstance(seed, int):
        raise ValueError(f"seed: expected a whole number, got {seed!r}")
    if isinstance(scene, Run):
        scene = scene._scene
    elif scene is not None and not isinstance(scene, scenes.Scene):
        scene = _load(scene)
    try:
        return questions.get(template).make(seed, scene)
    except InputError as error:
        raise ValueError(str(error)) from None


class CheckResult:
    """What ``check`` found.

    passed: how many cases pass; total: how many ran; score: passed / total.
    cases: one dict per case, as `rasterlab check --json` gives them.
    text: the report `rasterlab check` prints (also what ``str()`` gives).
    """

    def __init__(self, report: dict, text: str):
        self.cases: list[dict] = report["cases"]
        self.passed: int = report["passed"]
        self.total: int = len(self.cases)
        self.text = text

    @property
    def score(self) -> float:
        return self.passed / self.total if self.total else 0.0

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"<CheckResult: {self.passed} of {self.total} cases pass>"


# ------------------------------------------------------------------ helpers
def _options(spec, given: dict) -> dict:
    return {name: spec.option(name).parse(value) if isinstance(value, str)
            else spec.option(name).check(_plain(value)) for name, value in given.items()}


def _plain(value):
    """numpy numbers and arrays as Python's, which the checks take."""
    return value.tolist() if hasattr(value, "tolist") else value


def _points(spec, points) -> tuple:
    try:
        return spec.inputs.check(_plain(points))
    except TypeError:
        raise InputError(f"points: expected {spec.inputs.text()}, each a pair (x, y)") from None


def _grid(grid) -> tuple[int, int] | None:
    if grid is None:
        return None
    try:
        width, height = _plain(grid)
    except (TypeError, ValueError):
        raise InputError(f"grid must be (width, height), got {grid!r}") from None
    if not all(isinstance(v, int) and not isinstance(v, bool) for v in (width, height)):
        raise InputError(f"grid must be two whole numbers, got {grid!r}")
    return runs.check_grid(width, height)


def _step_cap(step_cap) -> int:
    value = _plain(step_cap)
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_STEP_CAP:
        raise InputError(f"step_cap must be a whole number 1 .. {MAX_STEP_CAP:,}, "
                         f"got {step_cap!r}")
    return value


def _load(name_or_path) -> scenes.Scene:
    if not isinstance(name_or_path, (str, os.PathLike)):
        raise InputError(f"a scene is a shipped scene's name or a file, got {name_or_path!r}")
    return scenes.load(shipped.scene_path(os.fspath(name_or_path)))


def _case_words(cases) -> list[str]:
    if isinstance(cases, os.PathLike) or isinstance(cases, str) and cases.endswith(".json"):
        return [os.fspath(cases)]
    if isinstance(cases, str):
        return cases.split()
    return [os.fspath(case) if isinstance(case, os.PathLike) else str(case) for case in cases]


def _export(scene, trace, path, settings: dict) -> str:
    """The export of ``scene`` (its run ``trace``, or recorded here) to ``path``."""
    from app.render import export as exporting
    from app.render import formats
    settings = dict(settings)
    kind = _format(path, settings.pop("format", None))
    force = bool(settings.pop("force", False))
    transcript = bool(settings.pop("transcript", True))
    outputs = formats.Outputs(**{{"png": "frames_dir", "svg": "svg_dir"}.get(kind, kind):
                                 os.fspath(path)}, force=force, transcript=transcript)
    formats.check(outputs, scene)
    chosen = _settings(settings)
    done = formats.export_all(outputs, scene, chosen, exporting.MAX_FRAMES_BYTES, trace=trace,
                              names=("first", "last"))
    return "\n".join(formats.summary(outputs, *done))


def _format(path, given) -> str:
    if not isinstance(path, (str, os.PathLike)):
        raise InputError(f"export needs a path to write, got {path!r}")
    if given is not None and given not in FORMATS:
        raise InputError(f"format must be one of {', '.join(FORMATS)}, got {given!r}")
    kind = given if given is not None else Path(path).suffix.lower().lstrip(".")
    if kind not in FORMATS or given is None and kind in FOLDERS:
        raise InputError(f"{Path(path).name}: cannot tell the format; use a path ending in .gif, "
                         ".mp4, .webm, .pdf or .html, or format='png' or 'svg' for a folder "
                         "of frames")
    return kind


def _settings(given: dict):
    from app.render.overlays import parse_overlays
    from app.render.settings import ExportSettings
    names = [field.name for field in fields(ExportSettings)]
    for name in given:
        if name not in names:
            raise InputError(f"export has no setting {name!r} (settings: format, force, "
                             f"{', '.join(names)})")
    if isinstance(given.get("memory_limit"), str):
        given["memory_limit"] = budget.parse_size(given["memory_limit"], "memory_limit")
    if isinstance(given.get("overlays"), str):
        given["overlays"] = parse_overlays(given["overlays"])
    elif "overlays" in given:
        given["overlays"] = tuple(given["overlays"])
    return ExportSettings(**given)
