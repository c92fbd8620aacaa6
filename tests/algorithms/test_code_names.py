"""The registry holds every family that builds a Code to the naming convention.

Each test writes a small family module into a temporary folder, imports it
and registers an algorithm from it: a wrong name must be refused before the
algorithm is listed.
"""
import importlib
import textwrap

import pytest

from algorithms.core import code
from algorithms.core import registry
from algorithms.core.registry import AlgorithmSpec, Inputs

GOOD = '''
    from algorithms.core.code import Code, listing
    from algorithms.core.steps import NO_PIXEL, PLOT, VISIT, Start, Vars


    def fake_listing(points, options):
        code = Code()
        code.add("setup", "x = 0  (a comment's comma, and a bracket ( do not count)")
        code.add("test", f"    if {'inside'}(x): skip", VISIT,
                 ops={"compare": 1})
        code.add("plot", "    plot(x, 0)",
                 kind=PLOT)
        code.add("done", "done")
        return code


    def fake(points, options):
        at = fake_listing(points, options).at
        yield Start(line=at["setup"], values=("x",))
        plot = at["plot"]
        for x in range(3):
            yield (at["test"], x, 0, x)
            yield (plot, x, 0, x)
        yield Vars(line=at["done"], values={"x": 3})
'''


def _register(tmp_path, monkeypatch, name, source):
    (tmp_path / f"{name}.py").write_text(textwrap.dedent(source))
    monkeypatch.syspath_prepend(str(tmp_path))
    module = importlib.import_module(name)
    spec = AlgorithmSpec(name=name.replace("_", "-"), title="Fake", family="lines", summary="",
                         inputs=Inputs(1), options=(), code=code.listing(module.fake_listing),
                         generator=module.fake)
    monkeypatch.setattr(registry, "_REGISTRY", dict(registry._REGISTRY))
    return spec


def test_a_family_that_follows_the_convention_registers(tmp_path, monkeypatch):
    spec = _register(tmp_path, monkeypatch, "fake_good", GOOD)
    registry.register(spec)
    trace = spec.record([(0, 0)])
    assert [trace.code[int(line)].kind for line in trace.line[1:7]] == ["visit", "plot"] * 3


@pytest.mark.parametrize("name, change, message", [
    ("fake_unknown_key", ('at["test"]', 'at["tset"]'), "no pseudo-code line is named 'tset'"),
    ("fake_numbered", ("(plot, x, 0, x)", "(4, x, 0, x)"), "names its pseudo-code line by number"),
    ("fake_numbered_record", ('Vars(line=at["done"]', "Vars(line=3"), "by number"),
    ("fake_plot_not_plot", ("kind=PLOT", "kind=VISIT"), "line 'plot' is of kind visit"),
    ("fake_plot_unnamed", ('code.add("plot"', 'code.add("write"'), "line 'write' is of kind plot"),
])
def test_a_wrong_name_is_refused_before_the_algorithm_is_listed(tmp_path, monkeypatch, name,
                                                                change, message):
    assert change[0] in GOOD
    spec = _register(tmp_path, monkeypatch, name, GOOD.replace(*change))
    with pytest.raises(ValueError, match=message) as refused:
        registry.register(spec)
    assert f"{name}.py:" in str(refused.value)
    assert spec.name not in registry._REGISTRY


def test_a_family_without_code_is_not_held_to_it(tmp_path, monkeypatch):
    source = GOOD.replace("code = Code()", "code = Builder()").replace("(plot, x, 0, x)",
                                                                      "(4, x, 0, x)")
    source = source.replace("from algorithms.core.code import Code, listing",
                            "from algorithms.core.code import Code as Builder")
    spec = _register(tmp_path, monkeypatch, "fake_unconverted", source)
    registry.register(spec)
    assert registry._REGISTRY[spec.name] is spec


def test_a_package_may_name_lines_one_of_its_modules_adds():
    builder = 'code = Code()\ncode.add("plot_run", "fill the run", PLOT)\n'
    user = 'def frames(at):\n    yield Span(line=at["plot_run"], y=0, x_start=0, x_end=2)\n'
    code.check_sources({"build.py": builder, "frames.py": user})
    with pytest.raises(ValueError, match="frames.py:2: no pseudo-code line is named 'plot_runs'"):
        code.check_sources({"build.py": builder, "frames.py": user.replace("plot_run", "plot_runs")})


def test_every_shipped_family_keeps_the_naming_convention():
    """Shipped families are not read at registration (start-up): held here."""
    specs = registry.all_specs()
    assert len({spec.generator.__module__ for spec in specs}) > 10
    for spec in specs:
        code.check_family(spec.generator, set())
