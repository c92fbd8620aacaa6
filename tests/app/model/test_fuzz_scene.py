"""Fuzzing scene files: loading anything, running it, and saving through failures.

Whatever a file holds, app.scene.load either returns a Scene whose JSON
round-trips through save and load, or raises SceneError with one line that
starts with the file's name; `rasterlab run --scene` ends with status 0 or 2;
and a save that fails part-way leaves the old file's bytes and no temporary
file behind.
"""
import contextlib
import errno
import io
import json
import os
import tempfile
from pathlib import Path
from unittest import mock

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from algorithms.core import registry
from app import cli
from app.model import scene as scenes
from app.model.scene import Scene, SceneError

SPECS = registry.all_specs()
SIZE = 40  # valid scenes use grids up to SIZE x SIZE
STEP_CAP = 2000


def fuzz_settings(examples: int):
    # Derandomized: the same examples every run, so a failure reproduces.
    return settings(max_examples=examples, derandomize=True, database=None,
                    suppress_health_check=list(HealthCheck))


class Counter:
    def __init__(self):
        self.counts = {}

    def add(self, outcome: str):
        self.counts[outcome] = self.counts.get(outcome, 0) + 1

    def report(self, target: str):
        total = sum(self.counts.values())
        detail = ", ".join(f"{k}: {v}" for k, v in sorted(self.counts.items()))
        print(f"\n{target}: {total} examples ({detail})")


# -------------------------------------------------------------- strategies
def colour():
    return st.integers(0, 0xFFFFFF).map(lambda v: f"#{v:06x}")


def option_value(option, width, height):
    """A typed value the option's check accepts, as a scene file holds it."""
    kind = option.kind
    if kind == "bool":
        values = st.booleans()
    elif kind == "choice":
        values = st.sampled_from(option.choices)
    elif kind in ("int", "float"):
        low = option.minimum if option.minimum is not None else -1e6
        high = option.maximum if option.maximum is not None else 1e6
        values = (st.integers(int(low), int(high)) if kind == "int" else st.floats(low, high))
    elif kind == "colors":
        values = st.lists(colour(), max_size=6)
    elif kind == "point":
        values = st.tuples(st.integers(0, width - 1), st.integers(0, height - 1)).map(list)
    elif kind == "numbers":
        values = st.lists(st.floats(allow_nan=False, allow_infinity=False), max_size=9)
    else:
        values = st.nothing()
    return st.one_of(values, st.sampled_from(option.choices)) if option.choices else values


@st.composite
def valid_scenes(draw):
    spec = draw(st.sampled_from(SPECS))
    width, height = draw(st.integers(1, SIZE)), draw(st.integers(1, SIZE))
    inputs = spec.inputs
    if inputs.integer:
        point = st.tuples(st.integers(0, width - 1), st.integers(0, height - 1))
    else:
        point = st.tuples(st.floats(0, width), st.floats(0, height))
    point = point.map(list)
    if inputs.contours:
        contour = st.lists(point, min_size=inputs.count, max_size=inputs.count + 3)
        points = draw(st.lists(contour, min_size=1, max_size=3))
    elif inputs.multiple:
        k = draw(st.integers(1, 3))
        points = draw(st.lists(point, min_size=k * inputs.count, max_size=k * inputs.count))
    else:
        points = draw(st.lists(point, min_size=inputs.count, max_size=inputs.count))
    options = {}
    for option in spec.options:
        if draw(st.booleans()):
            options[option.name] = option.check(draw(option_value(option, width, height)))
    view = draw(st.fixed_dictionaries({}, optional={
        "step": st.integers(0, 10 ** 6), "speed": st.floats(0, 1e6),
        "show_grid": st.booleans(), "compare": st.booleans()}))
    bookmarks = draw(st.lists(st.fixed_dictionaries(
        {"name": st.text(max_size=8), "step": st.integers(0, 10 ** 6)}), max_size=3))
    return Scene(algorithm=spec.name, points=points, options=options, width=width,
                 height=height, origin=draw(st.sampled_from(scenes.ORIGINS)),
                 title=draw(st.text(max_size=20)), description=draw(st.text(max_size=20)),
                 view=view, bookmarks=bookmarks)


# Values that stand in for a field: every JSON type, and the numbers that
# have broken loaders before. NaN and infinities come out of json.dumps as
# the NaN and Infinity literals.
ODD_SCALARS = st.one_of(
    st.none(), st.booleans(), st.integers(), st.floats(), st.text(max_size=10),
    st.sampled_from([10 ** 400, -(10 ** 400), 1e300, -1e300, -1, -5, 0, 4096, 4097, 1.5,
                     -0.0, float("nan"), float("inf"), float("-inf"), "", "1", "#ff0000",
                     "line-dda", "top-left"]))
ODD_VALUES = st.recursive(
    ODD_SCALARS, lambda inner: st.one_of(st.lists(inner, max_size=4),
                                         st.dictionaries(st.text(max_size=6), inner, max_size=4)),
    max_leaves=12)


def locations(tree, parent=None, key=None):
    """Every (container, key) in the tree, the root's as (None, None)."""
    found = [(parent, key)]
    if isinstance(tree, dict):
        for k, v in tree.items():
            found += locations(v, tree, k)
    elif isinstance(tree, list):
        for k, v in enumerate(tree):
            found += locations(v, tree, k)
    return found


@st.composite
def mutated_scene_data(draw):
    """A valid scene's JSON data, changed by a few random edits."""
    data = draw(valid_scenes()).to_json()
    for _ in range(draw(st.integers(0, 3))):
        places = locations(data)
        parent, key = places[draw(st.integers(0, len(places) - 1))]
        edit = draw(st.sampled_from(["delete", "replace", "add", "wrap", "number"]))
        if parent is None:
            data = draw(ODD_VALUES) if edit == "replace" else data
        elif edit == "delete":
            del parent[key]
        elif edit == "replace":
            parent[key] = draw(ODD_VALUES)
        elif edit == "add" and isinstance(parent, dict):
            parent[draw(st.text(max_size=8))] = draw(ODD_VALUES)
        elif edit == "add":
            parent.insert(key, draw(ODD_VALUES))
        elif edit == "wrap":
            parent[key] = [parent[key]]
        else:
            parent[key] = draw(st.sampled_from([float("nan"), float("inf"), 1e300, -1e300,
                                                10 ** 400, -3, 0, 0.5, 2 ** 63]))
    return data


@st.composite
def mutated_scene_texts(draw):
    """Mutated scene data as JSON text (NaN and Infinity literals included),
    sometimes cut short."""
    data = draw(mutated_scene_data())
    text = json.dumps(data, allow_nan=True, indent=draw(st.sampled_from([None, 2])))
    cut = draw(st.one_of(st.none(), st.integers(0, len(text))))
    if cut is not None:
        text = text[:cut]
    return text


ODD_TEXTS = st.one_of(
    st.text(max_size=200),
    st.sampled_from(["", "{", "}", "[]", "null", "1", '"x"', "NaN", "-Infinity", "1e400",
                     "[" * 5000 + "]" * 5000, '{"a":' * 3000 + "1" + "}" * 3000,
                     "1" * 5000, '{"version": ' + "9" * 20 + "}", "\ufeff{}", '{"version": 1}']),
    mutated_scene_texts(),
)

FILE_NAMES = st.one_of(
    st.just("scene.json"),
    st.text(st.characters(blacklist_characters="/\x00", blacklist_categories=("Cs",)),
            min_size=1, max_size=16).filter(lambda n: n not in (".", "..")),
)


# ------------------------------------------------------------------ checks
def check_loaded(directory: Path, path: Path):
    """load(path): a Scene that round-trips, or one clean SceneError line."""
    try:
        scene = scenes.load(path)
    except SceneError as error:
        message = str(error)
        assert message.startswith(scenes.one_line(path.name) + ": "), message
        assert len(message.splitlines()) == 1 and message.isprintable(), message
        return "rejected"
    copy = directory / "round-trip.json"
    scenes.save(scene, copy)
    assert scenes.load(copy).to_json() == scene.to_json()
    return "loaded"


def write(directory: Path, name: str, content) -> Path:
    path = directory / name
    if isinstance(content, str):
        content = content.encode("utf-8", "surrogatepass")
    path.write_bytes(content)
    return path


def run_scene(path: Path, extra: list[str]):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = cli.main(["run", "--scene", str(path), "--step-cap", str(STEP_CAP)] + extra)
    return status, out.getvalue(), err.getvalue()


def _reject(constant):
    raise ValueError(f"{constant} in the JSON output")


# ------------------------------------------------------------------- tests
def test_fuzz_load_arbitrary_bytes(tmp_path):
    counter = Counter()

    @fuzz_settings(400)
    @given(st.binary(max_size=300), FILE_NAMES)
    def fuzz(content, name):
        counter.add(check_loaded(tmp_path, write(tmp_path, name, content)))

    fuzz()
    counter.report("scene load, arbitrary bytes")


def test_fuzz_parse_text(tmp_path):
    counter = Counter()

    @fuzz_settings(500)
    @given(ODD_TEXTS, FILE_NAMES)
    def fuzz(text, name):
        try:
            scene = scenes.parse(text, name)
        except SceneError as error:
            message = str(error)
            assert message.startswith(scenes.one_line(name) + ": "), message
            assert len(message.splitlines()) == 1 and message.isprintable(), message
            counter.add("rejected")
            return
        # What parse takes, load takes from a file too.
        path = write(tmp_path, "parsed.json", text)
        assert scenes.load(path).to_json() == scene.to_json()
        counter.add(check_loaded(tmp_path, path))

    fuzz()
    counter.report("scene parse, text")
    assert counter.counts.get("loaded", 0) > 0


def test_fuzz_load_mutated_scenes(tmp_path):
    counter = Counter()

    @fuzz_settings(1000)
    @given(mutated_scene_texts())
    def fuzz(text):
        counter.add(check_loaded(tmp_path, write(tmp_path, "mutated.json", text)))

    fuzz()
    counter.report("scene load, mutated scenes")
    assert counter.counts.get("loaded", 0) > 0 and counter.counts.get("rejected", 0) > 0


def test_fuzz_from_json_data(tmp_path):
    """from_json takes data that never was JSON text too (the window builds
    it): ints beyond any float, NaN, deep lists."""
    counter = Counter()

    @fuzz_settings(500)
    @given(st.one_of(mutated_scene_data(), ODD_VALUES))
    def fuzz(data):
        try:
            scene = scenes.from_json(data)
        except SceneError as error:
            assert len(str(error).splitlines()) == 1 and str(error).isprintable(), str(error)
            counter.add("rejected")
            return
        copy = tmp_path / "from-data.json"
        scenes.save(scene, copy)
        assert scenes.load(copy).to_json() == scene.to_json()
        counter.add("loaded")

    fuzz()
    counter.report("scene from_json, data")
    assert counter.counts.get("loaded", 0) > 0


def test_fuzz_run_scene(tmp_path):
    counter = Counter()

    @fuzz_settings(500)
    @given(st.one_of(mutated_scene_texts(), valid_scenes().map(lambda s: json.dumps(s.to_json())),
                     st.binary(max_size=50)),
           st.sampled_from([[], ["--json"], ["--ascii"], ["--set", "radius=3"], ["--grid", "4,4"],
                            ["--json", "--ascii"], ["line-dda"]]))
    def fuzz(content, extra):
        path = write(tmp_path, "run.json", content)
        status, out, err = run_scene(path, extra)
        assert status in (0, 2), (content, extra, status, err)
        if status == 2:
            assert out == "" and err.startswith("rasterlab: "), (out, err)
            assert err.endswith("\n") and len(err.splitlines()) == 1, err
        elif "--json" in extra:
            result = json.loads(out, parse_constant=_reject)
            assert set(result) >= {"algorithm", "grid", "pixels", "steps", "final", "options"}
        counter.add(f"status {status}")

    fuzz()
    counter.report("cli run --scene")
    assert counter.counts.get("status 0", 0) > 0


# Inputs the fuzzing found, kept so they run whatever the generator draws.
def _scene_with(change):
    data = Scene(algorithm="triangle-scan", points=[[0, 0], [5, 0], [0, 5]]).to_json()
    change(data)
    return data


@pytest.mark.parametrize("text, words", [
    # json recursed past the interpreter's limit: RecursionError.
    ("[" * 100_000, "nests too deeply"),
    ('{"a":' * 5000, "nests too deeply"),
    # 10**400 reached math.isfinite: OverflowError.
    (json.dumps(_scene_with(lambda d: d["options"].update(z=[10 ** 400, 1, 2]))), "too large"),
    (json.dumps(_scene_with(lambda d: d.update(view={"speed": 10 ** 400}))), "too large"),
    (json.dumps(_scene_with(lambda d: d["primitives"][0]["points"][0].__setitem__(0, 10 ** 400))),
     "too large"),
    ("1e400", "too large"),
    # A line break in an option's name split the message.
    (json.dumps(_scene_with(lambda d: d["options"].update({"a\nb": 1}))), "options.a\\nb"),
])
def test_found_texts_are_rejected_in_one_line(text, words):
    with pytest.raises(SceneError) as error:
        scenes.parse(text, "found.json")
    message = str(error.value)
    assert message.startswith("found.json: ") and len(message.splitlines()) == 1, message
    assert words in message


@pytest.mark.parametrize("data", [
    _scene_with(lambda d: d["options"].update(z=[10 ** 400, 1, 2])),
    _scene_with(lambda d: d["primitives"][0]["points"][0].__setitem__(0, 10 ** 400)),
    _scene_with(lambda d: d.update(view={"speed": 10 ** 400})),
])
def test_found_data_is_rejected(data):
    with pytest.raises(SceneError):
        scenes.from_json(data)


def test_a_file_name_with_a_line_break_stays_on_one_line(tmp_path):
    path = write(tmp_path, "a\nb.json", "{")
    with pytest.raises(SceneError) as error:
        scenes.load(path)
    assert str(error.value).startswith("a\\nb.json: not valid JSON")


def test_loading_a_device_is_refused_before_reading():
    # stat() says 0 bytes; reading on would never end.
    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero here")
    with pytest.raises(SceneError, match="not a regular file"):
        scenes.load("/dev/zero")


# ------------------------------------------------------------------ saving
class Disk:
    """Stand-ins for the calls a save makes; one of them fails."""

    def __init__(self, failing: str, error: OSError, written: int):
        self.failing, self.error, self.written = failing, error, written
        self.real_fdopen = os.fdopen

    def patches(self):
        return [mock.patch.object(tempfile, "mkstemp", self.mkstemp),
                mock.patch.object(os, "fdopen", self.fdopen),
                mock.patch.object(os, "fsync", self.fsync),
                mock.patch.object(os, "replace", self.replace)]

    def fail(self, step: str):
        if step == self.failing:
            raise self.error

    def mkstemp(self, *args, **kwargs):
        self.fail("mkstemp")
        return _real_mkstemp(*args, **kwargs)

    def fdopen(self, handle, *args, **kwargs):
        self.fail("fdopen")
        return FailingStream(_real_fdopen(handle, *args, **kwargs), self)

    def fsync(self, handle):
        self.fail("fsync")
        return _real_fsync(handle)

    def replace(self, source, target):
        self.fail("replace")
        return _real_replace(source, target)


class FailingStream:
    """A file object whose write stops part-way, as on a full disk."""

    def __init__(self, stream, disk: Disk):
        self.stream, self.disk = stream, disk

    def write(self, data):
        if self.disk.failing == "write":
            self.stream.write(data[:self.disk.written])
            raise self.disk.error
        return self.stream.write(data)

    def flush(self):
        self.disk.fail("flush")
        return self.stream.flush()

    def fileno(self):
        return self.stream.fileno()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stream.close()
        self.disk.fail("close")
        return False


_real_mkstemp, _real_fdopen = tempfile.mkstemp, os.fdopen
_real_fsync, _real_replace = os.fsync, os.replace

FAILURES = st.builds(
    lambda code, text: OSError(code, text) if text is not None else OSError(f"disk gone {code}"),
    st.sampled_from([errno.ENOSPC, errno.EIO, errno.EACCES, errno.EROFS, errno.EDQUOT]),
    st.one_of(st.none(), st.sampled_from(["No space left on device", "Input/output error"])))


def open_in(folder: Path) -> list[str]:
    """Files in the folder this process still holds open (a leaked descriptor
    of a temporary file shows here even after the file is deleted)."""
    if not os.path.isdir("/proc/self/fd"):
        return []
    held = []
    for fd in os.listdir("/proc/self/fd"):
        with contextlib.suppress(OSError):
            target = os.readlink(f"/proc/self/fd/{fd}")
            if target.startswith(str(folder) + os.sep):
                held.append(target)
    return held


def test_fuzz_failed_saves_keep_the_old_file(tmp_path):
    counter = Counter()

    @fuzz_settings(300)
    @given(valid_scenes(), valid_scenes(),
           st.sampled_from(["replace", "write", "fsync", "flush", "close", "fdopen", "mkstemp",
                            "none"]),
           FAILURES, st.integers(0, 200))
    def fuzz(old, new, failing, error, written):
        folder = Path(tempfile.mkdtemp(dir=tmp_path))
        path = folder / "keep.json"
        scenes.save(old, path)
        before = path.read_bytes()
        disk = Disk(failing, error, written)
        with contextlib.ExitStack() as stack:
            for patch in disk.patches():
                stack.enter_context(patch)
            if failing == "none":
                scenes.save(new, path)
            else:
                with pytest.raises(SceneError) as raised:
                    scenes.save(new, path)
        if failing == "none":
            assert scenes.load(path).to_json() == new.to_json()
        else:
            message = str(raised.value)
            assert message.startswith(str(path)) or message.startswith(str(folder)), message
            assert (error.strerror or str(error)) in message, message
            assert len(message.splitlines()) == 1
            assert path.read_bytes() == before
        assert [p.name for p in folder.iterdir()] == ["keep.json"]
        assert open_in(folder) == []
        counter.add(failing)

    fuzz()
    counter.report("scene save with injected failures")


@pytest.mark.parametrize("failing, error", [
    # An OSError made in code has no strerror: the message said "(None)".
    ("replace", OSError("disk gone")),
    # A failing fdopen left mkstemp's descriptor open.
    ("fdopen", OSError(errno.EMFILE, "Too many open files")),
])
def test_found_save_failures(tmp_path, failing, error):
    path = tmp_path / "keep.json"
    scenes.save(Scene(), path)
    before = path.read_bytes()
    disk = Disk(failing, error, 0)
    with contextlib.ExitStack() as stack:
        for patch in disk.patches():
            stack.enter_context(patch)
        with pytest.raises(SceneError, match=error.strerror or str(error)):
            scenes.save(Scene(title="new"), path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["keep.json"]
    assert open_in(tmp_path) == []


@pytest.mark.slow
def test_fuzz_ten_thousand_scene_files(tmp_path, capsys):
    """10,000 scene files (mutated, valid, odd text, bytes) through `run
    --scene`: every one ends with exit status 0 or 2 and none with a
    traceback. Prints the figures."""
    counts: dict = {}
    tracebacks = []

    @fuzz_settings(10_000)
    @given(st.one_of(mutated_scene_texts(), valid_scenes().map(lambda s: json.dumps(s.to_json())),
                     ODD_TEXTS, st.binary(max_size=200)),
           st.sampled_from([[], ["--json"], ["--ascii"], ["--set", "radius=3"]]))
    def fuzz(content, extra):
        path = write(tmp_path, "run.json", content)
        try:
            status, out, err = run_scene(path, extra)
        except Exception as error:  # noqa: BLE001 - counted, and the test fails on it
            tracebacks.append(repr(error))
            return
        if "Traceback" in err or status not in (0, 2) or (
                status == 2 and len(err.splitlines()) != 1):
            tracebacks.append(err[-300:])
        counts[status] = counts.get(status, 0) + 1

    fuzz()
    tried = sum(counts.values()) + len(tracebacks)
    with capsys.disabled():
        codes = ", ".join(f"exit {code}: {n}" for code, n in sorted(counts.items()))
        print(f"\nscene file fuzz: {tried} inputs tried ({codes}); "
              f"tracebacks or bad endings: {len(tracebacks)}")
    assert tried >= 10_000
    assert not tracebacks, tracebacks[:3]
    assert set(counts) <= {0, 2}, counts
