"""Fuzzing the command line: whatever the argv, status 0 or 2 and never a traceback.

Every example calls app.cli.main in-process. On status 2 stderr is exactly one
line starting with 'rasterlab: ' and stdout is empty; on status 0 with --json
stdout is one strict JSON object (no NaN or Infinity) with the fields
DESIGN.md names. Points, grids and step caps are kept small where they are
valid, so no example records more than a few thousand steps.
"""
import contextlib
import io
import json
import sys
import types
from unittest import mock

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from algorithms.core import registry
from app import cli

SPECS = {spec.name: spec for spec in registry.all_specs()}
GRID = 24  # valid coordinates and grids stay below this
STEP_CAP = 2000  # valid step caps stay at or below this
FIELDS = {"algorithm", "grid", "pixels", "steps", "final", "options"}


def fuzz_settings(examples: int):
    # Derandomized: the same examples every run, so a failure reproduces.
    return settings(max_examples=examples, derandomize=True, database=None,
                    suppress_health_check=list(HealthCheck))


# Number texts that have broken number parsers somewhere before.
ODD_NUMBERS = [
    "", " ", "-0", "+0", "-0.0", "0.5", ".5", "5.", "1e300", "-1e300", "1e-320",
    "1" + "0" * 400, "-" + "9" * 400, "nan", "NaN", "-nan", "inf", "-inf", "Infinity",
    "0x10", "1_0", "\u0661\u0662", "\uff13", "\u00bd", "1e", "--1", "4096", "4097",
    "5000", "-1", "2147483648", "9223372036854775808", "1e20", "\u2028", "1\n",
]


def odd_number():
    return st.one_of(st.sampled_from(ODD_NUMBERS),
                     st.floats(allow_nan=True, allow_infinity=True).map(repr),
                     st.integers().map(str), st.text(max_size=5))


def odd_point():
    return st.one_of(
        st.tuples(odd_number(), odd_number()).map(",".join),
        st.lists(odd_number(), max_size=4).map(",".join),
        st.sampled_from(["1,2,3", "1,,2", ",1", "1,", ",", "-inf,0", "-x,1", "0,0,"]),
        st.text(max_size=8),
    )


def coordinate(integer: bool):
    whole = st.integers(0, GRID - 1)
    if integer:
        # The same whole numbers, written the ways a person may write them.
        return st.one_of(whole.map(str), whole.map(lambda v: f"{v}.0"),
                         whole.map(lambda v: f" {v}"), st.just("-0"))
    return st.one_of(whole.map(str), st.floats(0, GRID - 1).map(repr))


def valid_points(spec):
    """--points groups a spec accepts (before its own geometry checks)."""
    inputs = spec.inputs
    point = st.tuples(coordinate(inputs.integer), coordinate(inputs.integer)).map(",".join)
    if inputs.contours:
        contour = st.lists(point, min_size=inputs.count, max_size=inputs.count + 3)
        return st.lists(contour, min_size=1, max_size=2)
    if inputs.multiple:
        return st.integers(1, 3).flatmap(
            lambda k: st.lists(point, min_size=k * inputs.count, max_size=k * inputs.count)
        ).map(lambda group: [group])
    return st.lists(point, min_size=inputs.count, max_size=inputs.count).map(lambda g: [g])


def odd_points():
    return st.lists(st.lists(odd_point(), min_size=0, max_size=5), min_size=1, max_size=2)


def colour():
    return st.integers(0, 0xFFFFFF).map(lambda v: f"#{v:06x}")


def valid_value(option) -> st.SearchStrategy:
    """Text for --set that the option's kind accepts."""
    choices = list(option.choices)
    kind = option.kind
    if kind == "bool":
        values = st.sampled_from(["true", "false", "yes", "no", "on", "off", "1", "0", "TRUE"])
    elif kind == "choice":
        values = st.sampled_from(choices)
    elif kind in ("int", "float"):
        low = option.minimum if option.minimum is not None else -100
        high = option.maximum if option.maximum is not None else 100
        if kind == "int":
            # Mostly small, sometimes up to the maximum (a radius of 4096).
            values = st.one_of(st.integers(int(low), int(min(high, 64))),
                               st.integers(int(low), int(high))).map(str)
        else:
            # Small steps make long runs; the step cap bounds them anyway.
            values = st.floats(low, high).map(repr)
    elif kind == "colors":
        # One per point or per endpoint is what algorithms take: 2, 3 or 6.
        values = st.sampled_from([0, 1, 2, 3, 6]).flatmap(
            lambda n: st.lists(colour(), min_size=n, max_size=n)).map(",".join)
    elif kind == "point":
        values = st.tuples(st.integers(0, GRID - 1), st.integers(0, GRID - 1)).map(
            lambda p: f"{p[0]},{p[1]}")
    elif kind == "numbers":
        # Per-vertex values: one per point (3 or 3k) is what algorithms take.
        number = st.one_of(st.floats(-10, 10), st.floats(0.001, 10),
                           st.floats(allow_nan=False, allow_infinity=False))
        values = st.sampled_from([0, 1, 3, 6, 9]).flatmap(
            lambda n: st.lists(number.map(repr), min_size=n, max_size=n)).map(",".join)
    else:
        values = st.text(max_size=8)
    return st.one_of(values, st.sampled_from(choices)) if choices else values


def odd_value():
    return st.one_of(odd_number(), odd_point(), st.text(max_size=10),
                     st.lists(odd_number(), max_size=6).map(",".join),
                     st.sampled_from(["#zzzzzz", "#12345", "#1234567", "red", "auto",
                                      "true,false", "1,nan", "0,1e300"]))


def valid_settings(spec):
    """--set KEY=VALUE words the option kinds accept, for some of the spec's options."""
    per_option = [st.one_of(st.none(), valid_value(o).map(lambda v, o=o: f"{o.name}={v}"))
                  for o in spec.options]
    return st.tuples(*per_option).map(lambda words: [w for w in words if w is not None])


def odd_settings(spec):
    """--set words with a value of the wrong kind, or no such key, or no '='."""
    names = [o.name for o in spec.options] or ["radius"]
    return st.lists(st.one_of(
        st.tuples(st.sampled_from(names), odd_value()).map("=".join),
        st.tuples(st.text(max_size=6), odd_value()).map("=".join),
        st.text(max_size=8),
        st.sampled_from(["=", "=1", " =1", "radius", "radius=", "seed=auto", "colors"]),
    ), min_size=1, max_size=3)


def valid_grid():
    size = st.integers(GRID, GRID + 8)  # holds every valid point
    return st.one_of(st.none(), st.tuples(size, size).map(lambda g: f"{g[0]},{g[1]}"))


def odd_grid():
    # Too small for the points, outside 1..4096, or not W,H at all.
    return st.one_of(st.sampled_from(["0,5", "5,0", "4097,1", "4096,1", "1,4096", "1e300,1",
                                      "a,b", "3", "3,4,5", "", ",", "-3,4", "2.5,3", "nan,3",
                                      "1,1", "5,3"]),
                     st.tuples(odd_number(), odd_number()).map(",".join))


def odd_step_cap():
    return st.one_of(st.sampled_from(["0", "-1", "1e300", "1e20", "2.5", "abc", "", "nan",
                                      "1" + "0" * 400, "9223372036854775808"]),
                     odd_number())


def odd_name():
    names = st.sampled_from(sorted(SPECS))
    return st.one_of(st.text(max_size=12), names.map(str.upper), names.map(lambda n: n + " "),
                     names.map(lambda n: n[:-1]))


# Built once: building strategies inside every example is slow. Each part of
# a run argv has a valid and an odd strategy; an example breaks a few parts.
PARTS = {
    "name": (st.sampled_from(sorted(SPECS)), odd_name()),
    "grid": (valid_grid(), odd_grid()),
    "step-cap": (st.integers(1, STEP_CAP).map(str), odd_step_cap()),
    "output": (st.sampled_from([[], ["--json"], ["--ascii"]]),
               st.sampled_from([["--json", "--ascii"], ["--json", "--json"], ["--jso"]])),
}
POINTS = {name: (valid_points(spec), odd_points()) for name, spec in SPECS.items()}
SETTINGS = {name: (valid_settings(spec), odd_settings(spec)) for name, spec in SPECS.items()}
# About half the examples break nothing, so many runs reach the algorithm.
BROKEN = st.one_of(st.just([]), st.lists(st.sampled_from(sorted(PARTS) + ["points", "set"]),
                                         min_size=1, max_size=3))


@st.composite
def run_argv(draw):
    """A `run ALGO --points ...` argv: every part valid except the broken ones."""
    broken = set(draw(BROKEN))

    def part(strategies, name):
        return draw(strategies[name in broken])

    name = part(PARTS["name"], "name")
    # A garbage name still gets the points and options of some real spec.
    spec_name = name if name in SPECS else draw(st.sampled_from(sorted(SPECS)))
    words = [["run"], [name]]
    for group in part(POINTS[spec_name], "points"):
        words.append(["--points"] + group)
    for setting in part(SETTINGS[spec_name], "set"):
        words.append(["--set", setting])
    grid = part(PARTS["grid"], "grid")
    if grid is not None:
        words.append(["--grid", grid])
    words.append(["--step-cap", part(PARTS["step-cap"], "step-cap")])
    words += [[flag] for flag in part(PARTS["output"], "output")]
    # Options may come in any order after ALGO (before it, --points would
    # swallow the name, which the raw argv test tries).
    rest = draw(st.permutations(words[2:]))
    return [word for group in words[:2] + list(rest) for word in group]


# Words the unstructured argv is made of: every flag, some names, garbage.
VOCABULARY = ["run", "list", "--json", "--ascii", "--points", "--set", "--grid", "--scene",
              "--step-cap", "--help", "-h", "--", "-", "--po", "--s", "--json=1", "--grid=3,4",
              "line-dda", "circle-midpoint", "flood-fill", "triangle-scan", "polygon-scanline",
              "0,0", "3,4", "10,2", "5,9", "-1,2", "radius=3", "seed=5,5", "missing.json", "2000"]


def raw_argv():
    word = st.one_of(st.sampled_from(VOCABULARY), st.sampled_from(VOCABULARY),
                     odd_point(), st.text(max_size=10))
    # The cap goes last, so every run this argv may start stays short.
    return st.lists(word, max_size=12).map(lambda argv: argv + ["--step-cap", str(STEP_CAP)])


# ------------------------------------------------------------------ checks
def call(argv):
    """main(argv) in-process: (status, stdout, stderr); --help's exit counts as 0."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = cli.main(argv)
        except SystemExit as exit_:
            assert exit_.code in (0, None), (argv, exit_.code)
            assert "--help" in argv or "-h" in argv or any(a.startswith("--h") for a in argv)
            status = 0
    return status, out.getvalue(), err.getvalue()


def _reject(constant):
    raise ValueError(f"{constant} in the JSON output")


def check_run(argv):
    status, out, err = call(argv)
    assert status in (0, 2), (argv, status, err)
    assert "Traceback" not in err
    if status == 2:
        assert out == "", (argv, out)
        assert err.endswith("\n") and len(err.splitlines()) == 1, (argv, err)
        assert err.startswith("rasterlab: "), (argv, err)
        return status
    # A truncated run says so on stderr, in one line, and still succeeds.
    assert err == "" or (err.startswith("rasterlab: ") and len(err.splitlines()) == 1), err
    if "--json" in argv and "run" in argv[:1] and "--help" not in argv and "-h" not in argv:
        result = json.loads(out, parse_constant=_reject)
        assert isinstance(result, dict) and set(result) >= FIELDS, result
        assert result["algorithm"] in SPECS
        width, height = result["grid"]
        assert 1 <= width and 1 <= height
        assert result["steps"] >= 1
        assert all(len(p) == 2 and all(isinstance(c, int) for c in p) for p in result["pixels"])
        if "values" in result:
            assert len(result["values"]) == len(result["pixels"])
    return status


class Counter:
    def __init__(self):
        self.examples = 0
        self.by_status = {0: 0, 2: 0}

    def add(self, status):
        self.examples += 1
        self.by_status[status] += 1

    def report(self, target):
        print(f"\n{target}: {self.examples} examples "
              f"(status 0: {self.by_status[0]}, status 2: {self.by_status[2]})")


def no_window():
    # With no command main opens the window; the fuzz must not.
    module = types.ModuleType("app.gui")
    module.launch = lambda: 0
    return mock.patch.dict(sys.modules, {"app.gui": module})


# ------------------------------------------------------------------- tests
def test_fuzz_run_argv():
    counter = Counter()

    @fuzz_settings(1000)
    @given(run_argv())
    def fuzz(argv):
        counter.add(check_run(argv))

    with no_window():
        fuzz()
    counter.report("cli run argv")
    assert counter.by_status[0] > 0 and counter.by_status[2] > 0


def test_fuzz_raw_argv():
    counter = Counter()

    @fuzz_settings(800)
    @given(raw_argv())
    def fuzz(argv):
        counter.add(check_run(argv))

    with no_window():
        fuzz()
    counter.report("cli raw argv")


def test_fuzz_list():
    counter = Counter()

    @fuzz_settings(100)
    @given(st.lists(st.one_of(st.sampled_from(["--json", "--ascii", "-j", "x"]),
                              st.text(max_size=4)), max_size=3))
    def fuzz(extra):
        argv = ["list"] + extra
        status = check_run(argv)
        if status == 0 and "--json" in extra:
            out = call(argv)[1]
            specs = json.loads(out, parse_constant=_reject)
            assert [spec["name"] for spec in specs] == list(SPECS)
        counter.add(status)

    fuzz()
    counter.report("cli list")


# Inputs the fuzzing found, kept so they run whatever the generator draws.
@pytest.mark.parametrize("argv, words", [
    # A cap beyond sys.maxsize reached itertools.islice: ValueError traceback.
    (["run", "line-dda", "--points", "0,0", "1,1", "--step-cap", "1e300"], "--step-cap"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--step-cap", "9223372036854775808"],
     "--step-cap"),
    # argparse quotes unrecognized words raw: a line break split the message.
    (["list", "\x1e"], "unrecognized"),
    (["run", "run", "\x0c", "--step-cap", "1"], "unrecognized"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--", "a\nb"], "unrecognized"),
    # Clearer messages: "-inf,0" and "-x,1" were taken for unknown flags
    # ("unrecognized arguments"); a name after --points was read as a point
    # ("run needs ALGO and --points").
    (["run", "line-dda", "--points", "-inf,0", "1,1"], "finite"),
    (["run", "line-dda", "--points", "-x,1", "1,1"], "not a number"),
    (["run", "line-dda", "--points", "0,0", "1,1", "--grid", "-3,4"], "outside"),
    (["run", "--points", "0,0", "1,1", "line-dda"], "before --points"),
])
def test_found_inputs_end_with_one_line(argv, words):
    status, out, err = call(argv)
    assert status == 2 and out == ""
    assert err.startswith("rasterlab: ") and len(err.splitlines()) == 1, err
    assert words in err


# ------------------------------------------------------------ the long run
def tally(argv, counts: dict) -> None:
    """Run one argv and count how it ended: by exit status, or as a
    traceback (an exception out of main, or "Traceback" on stderr)."""
    try:
        status, _out, err = call(argv)
    except Exception as error:  # noqa: BLE001 - counted, and the test fails on it
        counts.setdefault("tracebacks", []).append((argv, repr(error)))
        return
    if "Traceback" in err:
        counts.setdefault("tracebacks", []).append((argv, err[-300:]))
    counts[status] = counts.get(status, 0) + 1


@pytest.mark.slow
def test_fuzz_ten_thousand_command_lines(capsys):
    """10,000 command lines, structured and raw: every one ends with exit
    status 0 or 2 and none with a traceback. Prints the figures."""
    counts: dict = {}

    @fuzz_settings(10_000)
    @given(st.one_of(run_argv(), run_argv(), raw_argv()))
    def fuzz(argv):
        tally(argv, counts)

    with no_window():
        fuzz()
    tracebacks = counts.pop("tracebacks", [])
    tried = sum(counts.values()) + len(tracebacks)
    with capsys.disabled():
        codes = ", ".join(f"exit {code}: {n}" for code, n in sorted(counts.items()))
        print(f"\ncli fuzz: {tried} inputs tried ({codes}); tracebacks: {len(tracebacks)}")
    assert tried >= 10_000
    assert not tracebacks, tracebacks[:3]
    assert set(counts) <= {0, 2}, counts
