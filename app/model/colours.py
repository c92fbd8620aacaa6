"""The colours that carry meaning, for every picture RasterLab draws: the
window, the exports, the HTML page and the report's charts.

They come from the Okabe-Ito set (Okabe and Ito, "Color Universal Design",
2008), chosen so that people with any of the common colour-vision
deficiencies can still tell them apart; where a colour of the set is too
light to reach a 3:1 contrast on the light theme's ground (orange, sky
blue, yellow) a darker shade of the same hue takes its place, and the dark
theme uses the lighter members. tests/app/render/test_palette_vision.py
simulates protanopia, deuteranopia and tritanopia on every pair of colours
of one meaning and checks their distance and contrast.

Colour is never the only cue: diff cells carry a pattern
(``DIFF_PATTERNS``), signed values a sign glyph (``SIGN_GLYPHS``), the
decision dots a marker shape per branch (``BRANCH_SYMBOLS``), the
coverage counts' overlaps a pattern (``COVERAGE_PATTERNS``) and the error
map's "too little" side a hatch.

This module lives in ``app.model`` because the widgets, the renderer and
the report all read it and may import nothing else they share.
"""
from __future__ import annotations

from dataclasses import dataclass

# The set as published: black, orange, sky blue, bluish green, yellow,
# blue, vermillion, reddish purple.
OKABE_ITO = {"black": "#000000", "orange": "#e69f00", "sky blue": "#56b4e9",
             "bluish green": "#009e73", "yellow": "#f0e442", "blue": "#0072b2",
             "vermillion": "#d55e00", "reddish purple": "#cc79a7"}

# The diff classes (app/model/compare.py DIFF_CLASSES order) and their patterns.
DIFF_PATTERNS = ("stripes /", "stripes \\", "plain", "cross")
# Coverage counts 0, 1, 2, 3 or more: the overlaps carry a pattern.
COVERAGE_PATTERNS = ("plain", "plain", "stripes /", "cross")
# A sign glyph set beside a signed value, so its tone is never the only cue.
SIGN_GLYPHS = {"positive": "+", "negative": "\u2212", "zero": "0"}
# pyqtgraph symbols of the decision dots: undecided, then one per branch.
UNDECIDED_SYMBOL = "o"
BRANCH_SYMBOLS = ("s", "t", "d", "x")
# The same shapes as text, for legends: square, triangle down, diamond, cross.
BRANCH_GLYPHS = ("\u25a0", "\u25bc", "\u25c6", "\u2715")


@dataclass(frozen=True)
class Meanings:
    """The colours (#rrggbb) of one theme, by what they mean."""

    ground: str                  # the background they are drawn on
    diff: tuple[str, str, str, str]  # only in A, only in B, both, different value
    positive: str                # signed values (edge values, weights)
    negative: str
    zero: str
    undecided: str               # a decision dot that chose no branch
    branches: tuple[str, ...]    # the decision dots, one per branch
    too_little: str              # the coverage-error map's ends
    too_much: str
    ink: str                     # a plotted cell
    current: str                 # the step's pixel
    candidate: str               # the pixels a decision chooses between
    difference: str              # a cell that differs from a compared run
    primitive: str               # the ideal primitive
    edges: tuple[str, str, str]  # the edge functions of a triangle (overlay)
    coverage: tuple[str, str, str]  # cells written once, twice, 3 or more times
    octants: tuple[str, str, str]  # octant diagram: the line's octant, the mirrors, its image

    def groups(self) -> dict[str, tuple[str, ...]]:
        """Colours that stand for different things side by side, by picture."""
        return {"diff": self.diff, "sign": (self.positive, self.negative, self.zero),
                "branches": (self.undecided, *self.branches),
                "error": (self.too_little, self.too_much),
                "highlights": (self.ink, self.current, self.candidate, self.difference,
                               self.primitive),
                "edges": self.edges, "coverage": self.coverage,
                "octants": self.octants}


LIGHT = Meanings(
    ground="#fbfcfd", diff=("#d55e00", "#0072b2", "#8c8c8c", "#000000"),
    positive="#0072b2", negative="#d55e00", zero="#5c5c5c",
    undecided="#8c8c8c", branches=("#0072b2", "#d55e00", "#000000", "#4999c6"),
    too_little="#0072b2", too_much="#d55e00",
    ink="#2563a8", current="#d55e00", candidate="#009e73", difference="#995a7d",
    primitive="#000000", edges=("#d55e00", "#009e73", "#7a4a9a"),
    coverage=("#4999c6", "#b35900", "#3d1f5c"),
    octants=("#009e73", "#7a4a9a", "#d55e00"))

DARK = Meanings(
    ground="#1b2027", diff=("#e69f00", "#56b4e9", "#8c8c8c", "#ffffff"),
    positive="#56b4e9", negative="#e69f00", zero="#bdbdbd",
    undecided="#8c8c8c", branches=("#56b4e9", "#e69f00", "#b54f00", "#0072b2"),
    too_little="#0072b2", too_much="#d55e00",
    ink="#5fa8f5", current="#e69f00", candidate="#009e73", difference="#cc79a7",
    primitive="#f0e442", edges=("#e69f00", "#009e73", "#cc79a7"),
    coverage=("#2f80c0", "#e69f00", "#ffffff"),
    octants=("#009e73", "#cc79a7", "#e69f00"))

THEMES = {"light": LIGHT, "dark": DARK}
# The coverage-error map is drawn on white in either theme (white is "no error").
ERROR_GROUND = "#ffffff"


def rgb(colour: str) -> tuple[int, int, int]:
    """'#rrggbb' as (r, g, b) integers."""
    value = int(colour.lstrip("#"), 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255
