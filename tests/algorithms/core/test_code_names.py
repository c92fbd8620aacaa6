"""Pseudo-code names are held to the convention as a generator runs.

Each test writes a small family module into a temporary folder, imports it
and records an algorithm from it: a line name no line has, or a name and a
kind that disagree (plot... and only plot... is of kind PLOT), is refused.
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


def _spec(tmp_path, monkeypatch, name, source):
    (tmp_path / f"{name}.py").write_text(textwrap.dedent(source))
    monkeypatch.syspath_prepend(str(tmp_path))
    module = importlib.import_module(name)
    spec = AlgorithmSpec(name=name.replace("_", "-"), title="Fake", family="lines", summary="",
                         inputs=Inputs(1), options=(), code=code.listing(module.fake_listing),
                         generator=module.fake)
    registry.all_specs()  # the shipped specs first, so the copy below holds them
    monkeypatch.setattr(registry, "_REGISTRY", dict(registry._REGISTRY))
    return spec


def test_a_family_that_follows_the_convention_records(tmp_path, monkeypatch):
    spec = _spec(tmp_path, monkeypatch, "fake_good", GOOD)
    registry.register(spec)
    trace = spec.record([(0, 0)])
    assert [trace.code[int(line)].kind for line in trace.line[1:7]] == ["visit", "plot"] * 3


@pytest.mark.parametrize("name, change, message", [
    ("fake_unknown_key", ('at["test"]', 'at["tset"]'), "no pseudo-code line is named 'tset'"),
    ("fake_plot_not_plot", ("kind=PLOT", "kind=VISIT"), "line 'plot' is of kind visit"),
    ("fake_plot_unnamed", ('code.add("plot"', 'code.add("write"'), "line 'write' is of kind plot"),
])
def test_a_wrong_name_is_refused_when_the_generator_runs(tmp_path, monkeypatch, name, change,
                                                         message):
    assert change[0] in GOOD
    spec = _spec(tmp_path, monkeypatch, name, GOOD.replace(*change))
    with pytest.raises(ValueError, match=message):
        spec.record([(0, 0)])


def test_a_name_computed_at_run_time_is_checked_too(tmp_path, monkeypatch):
    # A key held in a variable or built from a string is what no reading of
    # the source could check.
    source = GOOD.replace('yield (at["test"], x, 0, x)', 'yield (at["te" + "st" * x], x, 0, x)')
    spec = _spec(tmp_path, monkeypatch, "fake_computed", source)
    with pytest.raises(ValueError, match="no pseudo-code line is named 'te'"):
        spec.record([(0, 0)])


def test_a_line_defined_twice_is_refused():
    listing = code.Code()
    listing.add("setup", "x = 0")
    with pytest.raises(ValueError, match="'setup' is defined twice"):
        listing.add("setup", "y = 0")


def test_every_shipped_family_declares_its_specs_in_listing_order():
    specs = registry.all_specs()
    families = [spec.family for spec in specs]
    assert families == sorted(families, key=registry.FAMILIES.index)
    # A package may declare a spec of another family (line-two-triangles
    # is a line drawn by the triangle package's fill): the listing takes the
    # packages in family order and each package's specs in its own order.
    declared = [spec for family in registry.FAMILIES
                for spec in importlib.import_module(f"algorithms.{family}").SPECS]
    assert sorted(s.name for s in declared) == sorted(s.name for s in specs)
    for family in registry.FAMILIES:
        assert [s.name for s in specs if s.family == family] == \
            [s.name for s in declared if s.family == family]
