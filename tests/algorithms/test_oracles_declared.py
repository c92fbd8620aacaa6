"""Every shipped algorithm declares what the tests hold it to, and the declaration stays true.

An AlgorithmSpec's oracle names its kind, what it is held to and the test
modules that hold it; the stability suite runs the check it declares. So
that a declaration cannot outlive the tests it names, each named module
must exist and name the algorithm (the stability suite, which runs every
algorithm from the registry, must have the declared check instead).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from algorithms.core import registry
from test_stability import CHECKS

TESTS = Path(__file__).resolve().parents[1]
STABILITY = "algorithms/test_stability.py"
SPECS = registry.all_specs()


@pytest.mark.parametrize("spec", SPECS, ids=lambda spec: spec.name)
def test_every_algorithm_declares_an_oracle(spec):
    oracle = spec.oracle
    assert isinstance(oracle, registry.Oracle), f"{spec.name} declares no oracle"
    assert oracle.kind in registry.ORACLE_KINDS
    assert oracle.about.strip() and oracle.tests, f"{spec.name}: what it is held to, and where"
    if oracle.kind == "none":
        assert oracle.about.lower().startswith("no independent oracle"), \
            f"{spec.name}: kind none says why there is none"


@pytest.mark.parametrize("spec", SPECS, ids=lambda spec: spec.name)
def test_the_named_test_modules_exist_and_name_the_algorithm(spec):
    for module in spec.oracle.tests:
        path = TESTS / module
        assert path.is_file(), f"{spec.name}: no test module {module}"
        if module != STABILITY:
            assert spec.name in path.read_text(encoding="utf-8"), \
                f"{spec.name}: {module} does not name it"


@pytest.mark.parametrize("spec", SPECS, ids=lambda spec: spec.name)
def test_the_stability_suite_has_the_declared_check(spec):
    check = spec.oracle.check
    assert (STABILITY in spec.oracle.tests) == bool(check), \
        f"{spec.name}: the stability suite is named exactly when a check is declared"
    assert not check or check in CHECKS, f"{spec.name}: no check {check!r} in {STABILITY}"


def test_an_oracle_kind_outside_the_three_is_refused():
    with pytest.raises(ValueError, match="oracle kind"):
        registry.Oracle("approximate", "close enough", ("algorithms/test_stability.py",))
