"""How numbers and names read on screen and on exported frames: one helper
for the window's panels and captions and for the exporter.

The algorithms' own texts stay as they are (plain ASCII, full precision:
``run --json`` and the recorded traces keep them); what a person reads
(the panels, the steps table, exports, worksheets and ``run --steps`` as
text or CSV) goes through here:

* ``number``: a sensible number of significant figures (all the whole
  digits of a large value, and one decimal at least). A float that
  rounds onto a tie (an integer or a half) it does not equal keeps more
  digits, so that float drift at a rounding decision stays visible
  (12.4999998 is not shown as 12.5).
* ``tidy``: a text's long decimals shortened the same way, ``<=`` as ≤,
  ``>=`` as ≥, ``!=`` as ≠, and two clumsy forms of the panels' sums
  fixed: "d_i = 0 = 0" becomes "d_i = 0", "+ (-14)" becomes "− 14".
* ``colour``: a packed 0xRRGGBB value as #rrggbb, for the values a run
  declares as colours (``colour_names``: its Start record's
  ``color_value`` or ``pixel_value`` and ``colour_values``).
* ``subscripts`` (for Pillow frames: Unicode) and ``rich`` (for Qt rich
  text: <sub>) set an index written with an underscore, d_i+1 or
  x_{left}, as a subscript.

One setting, ``numbers``, is shared by the window's panels, the steps
table, exports and worksheets: "decimal" (the default) shows values as
they have always read; "exact" shows every value the algorithm holds as
an exact fraction (an ET's 1/m, Bresenham's m, the barycentric weights of
a triangle with lattice vertices: app/model/exact.py) as p/q, the way the
lecture notes print them. A float is never turned into a fraction.
"""
from __future__ import annotations

import html
import re
from fractions import Fraction
from functools import lru_cache

DIGITS = 5  # significant figures of a shown float
NUMBERS = ("decimal", "exact")  # the display setting's values, default first

_SUB = str.maketrans("0123456789+-=()aehijklmnoprstuvx",
                     "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_SUBSCRIPTABLE = set("0123456789+-=()aehijklmnoprstuvx")
# An index: one letter or digit, perhaps with + or - a number (d_i, d_i+1,
# e_k, w_0), or anything in braces (x_{left}). Longer words after an
# underscore are names, not indices: fill_rule and s_affine stay as they are.
_INDEX = re.compile(r"(?<=[A-Za-z0-9])_(\{[^}]*\}|[A-Za-z0-9](?:[+\-]\d+)?)(?![A-Za-z0-9_])")
_LONG_DECIMAL = re.compile(r"(?<![\w.])-?\d+\.\d{6,}(?:e[+-]?\d+)?(?![\w.])")
_REPEAT = re.compile(r"= (-?[\w.]+) = \1(?=$|[,;)\s])")
_PLUS_BRACKET = re.compile(r"([+\-]) \((-?)(\d[\d.]*)\)")


def checked_numbers(numbers: str) -> str:
    """``numbers`` if it is a value of the setting, else ValueError with one line."""
    if numbers not in NUMBERS:
        raise ValueError(f"numbers must be {' or '.join(NUMBERS)}, got {numbers!r}")
    return numbers


def fraction(value: Fraction) -> str:
    """An exact value as the notes print it: -5/2, 3 (no decimal)."""
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"


def number(value, digits: int = DIGITS, numbers: str = "decimal") -> str:
    """Short text for a number: whole numbers plain, floats to ``digits``
    significant figures (every digit where that would hide a near miss
    of a tie), fractions as p/q with their decimal value (``numbers``
    "exact": as p/q alone)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, Fraction)):
        return str(value)
    if isinstance(value, Fraction):
        if value.denominator == 1 or numbers == "exact":
            return fraction(value)
        return f"{value} ({number(float(value), digits)})"
    if isinstance(value, int):
        return str(value)
    if value != value or value in (float("inf"), float("-inf")):
        return str(value)
    if value.is_integer() and abs(value) < 2 ** 53:
        return str(int(value))
    whole = len(str(int(abs(value)))) if abs(value) >= 1 else 0
    # Every whole digit stays (a coordinate near 1,000,000 must not read
    # 1e+06), then decimals up to ``digits`` figures, at least one.
    text = f"{value:.{max(1, digits - whole)}f}" if whole else f"{value:.{digits}g}"
    if whole and "." in text:
        text = text.rstrip("0").rstrip(".")
    shown = float(text)
    # A near miss of a tie (a float's drift, not a value that merely rounds
    # to a half): keep it visible.
    last_digit = 10.0 ** -max(1, digits - whole) if whole else 1e-5
    if shown != value and (2 * shown).is_integer() and abs(shown - value) < 1e-4 * last_digit:
        text = repr(value)  # the shortest text that is exactly this float
    return text


def colour(value) -> str | None:
    """A packed 0xRRGGBB value (int, float or its text) as #rrggbb; None
    for anything else (nan, a fraction of a level, out of range)."""
    try:
        value = float(value)
    except (TypeError, ValueError):
        return None
    if not value.is_integer() or not 0 <= value <= 0xFFFFFF:
        return None
    return f"#{int(value):06x}"


def colour_names(start) -> frozenset[str]:
    """The names of a run's values that hold packed colours: the colour it
    writes (``color_value``, else ``pixel_value``: an antialiasing run's
    pixel value is a coverage, never a colour) and those it declares in
    ``colour_values``."""
    written = getattr(start, "color_value", None) or getattr(start, "pixel_value", None)
    names = set(getattr(start, "colour_values", ()) or ())
    return frozenset(names | ({written} if written else set()))


def tidy(text: str) -> str:
    """A panel's or caption's text as a person should read it (see above)."""
    text = _LONG_DECIMAL.sub(lambda m: number(float(m.group(0))), text)
    text = _REPEAT.sub(r"= \1", text)
    text = _PLUS_BRACKET.sub(lambda m: _signed(m.group(1), m.group(2), m.group(3)), text)
    return text.replace("<=", "\u2264").replace(">=", "\u2265").replace("!=", "\u2260")


def _signed(operator: str, minus: str, digits: str) -> str:
    negative = (operator == "-") != (minus == "-")
    return ("\u2212 " if negative else "+ ") + digits


def subscripts(text: str) -> str:
    """Indices as Unicode subscripts where every character of the index has
    one (d_i+1 -> dᵢ₊₁); other indices keep their underscore."""
    def sub(match):
        index = match.group(1).strip("{}")
        if index and set(index) <= _SUBSCRIPTABLE:
            return index.translate(_SUB)
        return match.group(0)
    return _INDEX.sub(sub, text)


def rich(text: str) -> str:
    """Qt rich text: escaped, with every index as <sub>...</sub>."""
    parts, last = [], 0
    for match in _INDEX.finditer(text):
        parts.append(html.escape(text[last:match.start()]))
        parts.append(f"<sub>{html.escape(match.group(1).strip('{}'))}</sub>")
        last = match.end()
    parts.append(html.escape(text[last:]))
    return "".join(parts)


@lru_cache(maxsize=4096)  # the window asks again for every row at every step
def shown(text: str) -> str:
    """``tidy`` then ``subscripts``: what an exported frame writes."""
    return subscripts(tidy(text))
