"""The colours with a meaning (app/model/colours.py) stay apart for people
with protanopia, deuteranopia or tritanopia, and stand out from their
ground.

Each pair of colours that stand for different things in one picture is
simulated with daltonlens (Machado et al. 2009, full severity) and its
distance measured in CIEDE2000; each colour's contrast against its ground
is WCAG 2.1's contrast ratio, worked out here from WCAG's definition of
relative luminance. ``python tests/app/render/test_palette_vision.py``
prints the smallest distances per deficiency and theme.
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from daltonlens import simulate
from skimage.color import deltaE_ciede2000, rgb2lab

from app.analysis import charts
from app.model import colours

DEFICIENCIES = {"protanopia": simulate.Deficiency.PROTAN,
                "deuteranopia": simulate.Deficiency.DEUTAN,
                "tritanopia": simulate.Deficiency.TRITAN}
# CIEDE2000 of about 2 is a just noticeable difference; 10 is a difference
# seen at a glance, between small marks as well as large areas.
MIN_DISTANCE = 10.0
# WCAG 2.1 success criterion 1.4.11: graphical objects against adjacent colours.
MIN_CONTRAST = 3.0
SIMULATOR = simulate.Simulator_Machado2009()


def rgb(colour: str) -> tuple[int, int, int]:
    value = int(colour.lstrip("#"), 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def relative_luminance(colour: str) -> float:
    """WCAG 2.1's relative luminance of an sRGB colour."""
    def linear(channel: int) -> float:
        c = channel / 255
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (linear(c) for c in rgb(colour))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: str, b: str) -> float:
    """WCAG 2.1's contrast ratio (L1 + 0.05) / (L2 + 0.05), L1 the lighter."""
    high, low = sorted((relative_luminance(a), relative_luminance(b)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def seen(colours_, deficiency: str | None) -> np.ndarray:
    """The colours as CIELAB, as a person with ``deficiency`` (None: none) sees them."""
    image = np.array([[rgb(c) for c in colours_]], np.uint8)
    if deficiency is not None:
        image = SIMULATOR.simulate_cvd(image, DEFICIENCIES[deficiency], severity=1.0)
    return rgb2lab(image.astype(np.float64) / 255)[0]


def smallest_distance(colours_, deficiency: str | None) -> tuple[float, tuple[str, str]]:
    """The closest pair of ``colours_`` as seen with ``deficiency``, and its distance."""
    lab = seen(colours_, deficiency)
    pairs = itertools.combinations(range(len(colours_)), 2)
    return min((float(deltaE_ciede2000(lab[i], lab[j])), (colours_[i], colours_[j]))
               for i, j in pairs)


def ground_of(meanings: colours.Meanings, group: str) -> str:
    return colours.ERROR_GROUND if group == "error" else meanings.ground


CASES = [(theme, group, deficiency) for theme, meanings in colours.THEMES.items()
         for group in meanings.groups() for deficiency in DEFICIENCIES]


@pytest.mark.parametrize("theme,group,deficiency", CASES)
def test_colours_of_different_meanings_stay_apart(theme, group, deficiency):
    distance, pair = smallest_distance(colours.THEMES[theme].groups()[group], deficiency)
    assert distance >= MIN_DISTANCE, (theme, group, deficiency, pair, round(distance, 1))


@pytest.mark.parametrize("theme", colours.THEMES)
def test_every_meaningful_colour_has_3_to_1_contrast_on_its_ground(theme):
    meanings = colours.THEMES[theme]
    for group, members in meanings.groups().items():
        ground = ground_of(meanings, group)
        for colour in members:
            assert contrast(colour, ground) >= MIN_CONTRAST, (theme, group, colour, ground)


def test_contrast_follows_wcag_reference_values():
    # Black on white is 21:1; WCAG's own example grey #767676 on white is 4.54:1.
    assert contrast("#000000", "#ffffff") == pytest.approx(21.0)
    assert contrast("#767676", "#ffffff") == pytest.approx(4.54, abs=0.01)


def test_the_simulation_merges_what_the_old_red_green_signs_relied_on():
    # The signs before: green positive, red negative, brown zero. A
    # deuteranope sees two of them nearly alike; the test above would
    # notice a palette that relied on them.
    old_signs = ("#1f7a3d", "#c92a2a", "#b35900")
    normal, _ = smallest_distance(old_signs, None)
    deutan, _ = smallest_distance(old_signs, "deuteranopia")
    assert deutan < MIN_DISTANCE < normal


def test_report_chart_series_differ_in_colour_or_in_marker():
    palette = charts.PALETTE
    for i, j in itertools.combinations(range(len(palette)), 2):
        if charts.MARKERS[i % len(charts.MARKERS)] != charts.MARKERS[j % len(charts.MARKERS)]:
            continue
        for deficiency in (None, *DEFICIENCIES):
            distance, _ = smallest_distance((palette[i], palette[j]), deficiency)
            assert distance >= MIN_DISTANCE, (palette[i], palette[j], deficiency)
        assert contrast(palette[i], charts.BACKGROUND) >= MIN_CONTRAST


def distance_table(themes) -> list[str]:
    """Per theme and group: the smallest CIEDE2000 distance with normal
    vision and each deficiency, and the lowest contrast on the ground."""
    lines = [f"{'theme':6} {'group':11} {'normal':>7} " + " ".join(f"{d:>12}" for d in DEFICIENCIES)
             + "  contrast"]
    for theme, meanings in themes.items():
        for group, members in meanings.groups().items():
            distances = [smallest_distance(members, d)[0] for d in (None, *DEFICIENCIES)]
            low = min(contrast(c, ground_of(meanings, group)) for c in members)
            lines.append(f"{theme:6} {group:11} {distances[0]:7.1f} "
                         + " ".join(f"{d:12.1f}" for d in distances[1:]) + f"  {low:8.2f}")
    return lines


if __name__ == "__main__":
    print("\n".join(distance_table(colours.THEMES)))
