"""Every fast kernel emits exactly the pixels its generator writes, in order."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core.registry import get
from tests.support.linecases import LINE_ALGORITHMS, NAMED_CASES, segments, trace_of

OPTIONS = {
    "line-bresenham": st.fixed_dictionaries({"symmetric": st.booleans()}),
    "line-dda": st.fixed_dictionaries({"dtype": st.sampled_from(["float64", "float32"])}),
    "line-incremental": st.fixed_dictionaries({"rounding": st.sampled_from(["floor", "round"])}),
    "line-explicit": st.just({}),
    "line-implicit": st.just({}),
    "line-parametric": st.fixed_dictionaries(
        {"dt": st.one_of(st.just("auto"), st.floats(0.002, 1.0), st.sampled_from([0.001, 0.1, 0.3]))}),
}
COLORS = st.one_of(st.just({}), st.just({"colors": ["#ff0000", "#00ff80"]}))


def assert_same(name, p, q, options):
    spec = get(name)
    kernel = spec.kernel((p, q), spec.resolve(options))
    written = trace_of(name, p, q, options).written_pixels()
    assert kernel.dtype == np.int64 and kernel.shape == written.shape
    assert np.array_equal(kernel, written)


def test_every_line_algorithm_has_a_kernel():
    assert all(get(name).kernel is not None for name in LINE_ALGORITHMS)


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@pytest.mark.parametrize("p, q", NAMED_CASES)
def test_named_cases(name, p, q):
    assert_same(name, p, q, {})


@pytest.mark.parametrize("p, q", NAMED_CASES + [((0, 0), (12, 6)), ((0, 0), (14, -7)), ((3, 1), (-9, 10))])
@pytest.mark.parametrize("dt", ["auto", 0.3, 1.0])
def test_parametric_named_cases(p, q, dt):
    # (0,0)-(12,6) at k = 7: t*dy is exactly 3.5 from 7/12 but 3.4999... from
    # 7 * (1/12), so a kernel that takes t another way shows here.
    assert_same("line-parametric", p, q, {"dt": dt})


@pytest.mark.parametrize("name", LINE_ALGORITHMS)
@settings(max_examples=60)
@given(data=st.data())
def test_random_segments_and_options(name, data):
    span = 25 if name == "line-implicit" else 400
    p, q = data.draw(segments(span))
    options = {**data.draw(OPTIONS[name]), **data.draw(COLORS)}
    assert_same(name, p, q, options)


@pytest.mark.parametrize("name", ["line-dda", "line-incremental", "line-explicit"])
@pytest.mark.parametrize("p, q", [((0, 0), (4000, 1234)), ((3, 4090), (1200, -7)), ((0, 0), (98, 2))])
def test_long_lines(name, p, q):
    for options in ({}, {"dtype": "float32"} if name == "line-dda" else {}):
        assert_same(name, p, q, options)
