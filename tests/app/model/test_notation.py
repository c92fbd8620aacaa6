"""Numbers and names as a person reads them (app/model/notation.py)."""
from decimal import Decimal
from fractions import Fraction

import pytest

from app.model.notation import number, rich, shown, subscripts, tidy


@pytest.mark.parametrize("value", [8675.21484375, 0.798123456, -1545.318359375, 1.0e-7,
                                   0.1 + 0.2, 3.14159265])
def test_floats_keep_five_significant_figures(value):
    text = number(value)
    # Within half a unit of the fifth significant figure, and no longer.
    assert abs(Decimal(text) - Decimal(value)) <= abs(Decimal(value)) * Decimal("5e-5")
    assert len(text.replace("-", "").replace(".", "").lstrip("0").split("e")[0]) <= 5


def test_large_values_keep_their_whole_digits_and_a_decimal():
    assert number(1000000.53125) == "1000000.5"
    assert number(123456.789) == "123456.8"
    assert number(-98765.4321) == "-98765.4"


def test_a_near_tie_keeps_every_digit():
    # Float drift next to a rounding decision must stay visible.
    assert number(12.499999999) == "12.499999999"
    assert number(2.5) == "2.5" and number(3.0) == "3" and number(7) == "7"
    assert number(Fraction(1030, 53)) == "1030/53 (19.434)" and number(Fraction(4, 2)) == "2"


@pytest.mark.parametrize("raw, want", [
    ("d_i = 0 = 0, so E", "dᵢ = 0, so E"),
    ("d_i+1 = d_i + incrE = 0 + (22) = 22", "dᵢ₊₁ = dᵢ + incrE = 0 + 22 = 22"),
    ("d_i+1 = d_i + incrNE = 4 + (-14) = -10", "dᵢ₊₁ = dᵢ + incrNE = 4 \u2212 14 = -10"),
    ("x_left <= i + 1/2 < x_right", "x_left \u2264 i + 1/2 < x_right"),
    ("e0 = 8675.21484375", "e0 = 8675.2"),
])
def test_panel_texts_read_cleanly(raw, want):
    assert shown(raw) == want


def test_rich_text_sets_indices_as_subscripts_and_escapes():
    assert rich(tidy("d_i+1 = d_i + 2 < x_{left}")) == \
        "d<sub>i+1</sub> = d<sub>i</sub> + 2 &lt; x<sub>left</sub>"
    assert subscripts("x_left") == "x_left"  # no Unicode subscript f: left as it is


def test_names_with_words_after_the_underscore_are_left_alone():
    assert subscripts("fill_rule = top-left, s_affine, e_k, w_0, d_i-1") == \
        "fill_rule = top-left, s_affine, eₖ, w₀, dᵢ₋₁"
    assert rich("x_left") == "x_left" and rich("x_{left}") == "x<sub>left</sub>"
