"""What the quiz-tool writers (moodle.py, qti.py, gift.py, prairielearn.py)
share: how a numerical key is typed into a tool that reads decimals only,
and the question and its worked steps as HTML.

A quiz tool compares a typed decimal with the key. An exact answer whose
decimal ends (3/4 = 0.75) is asked for exactly; one whose decimal does not
(1/3) is given with DIGITS decimals and accepted within READ_TOLERANCE, and
the question says how to write it. A real answer keeps its own tolerance.
"""
from __future__ import annotations

from fractions import Fraction

from app.model import escape
from app.teaching.questions.model import NUMERICAL, Answer, Question, Worked

DIGITS = 6               # decimals given for a value whose decimal does not end
READ_TOLERANCE = 0.0005  # what three correct decimals of such a value are within
PICTURE = "picture.png"  # the picture's file name beside each question


def finite_decimal(value) -> bool:
    """Whether ``value`` (an int or Fraction) has a decimal that ends."""
    denominator = Fraction(value).denominator
    for prime in (2, 5):
        while denominator % prime == 0:
            denominator //= prime
    return denominator == 1


def tolerance(answer: Answer) -> float:
    """The absolute error a decimal-only tool accepts for a NUMERICAL answer."""
    if answer.tolerance > 0:
        return answer.tolerance
    return 0.0 if finite_decimal(answer.value) else READ_TOLERANCE


def decimal_text(answer: Answer) -> str:
    """The key of a NUMERICAL answer as a decimal: exact when it ends, else
    rounded to DIGITS decimals (more when the tolerance is finer)."""
    value = Fraction(answer.value)
    if finite_decimal(value):
        return _exact_decimal(value)
    digits = DIGITS
    while answer.tolerance and 10 ** -digits > answer.tolerance / 100:
        digits += 1
    return _exact_decimal(round(value, digits))  # a Fraction over 10**digits


def _exact_decimal(value: Fraction) -> str:
    sign, value = ("-" if value < 0 else ""), abs(value)
    whole, rest = divmod(value.numerator, value.denominator)
    digits = ""
    while rest:
        whole_digit, rest = divmod(rest * 10, value.denominator)
        digits += str(whole_digit)
    return f"{sign}{whole}" + (f".{digits}" if digits else "")


def how_to_write(answer: Answer) -> str:
    """The sentence a decimal-only tool adds to a NUMERICAL question ("" if
    none is needed): how to type a fraction, and the tolerance accepted."""
    if answer.kind != NUMERICAL:
        return ""
    if answer.tolerance > 0:
        return f"Give a decimal number; answers within {answer.tolerance:g} are accepted."
    if Fraction(answer.value).denominator == 1:
        return ""
    if finite_decimal(answer.value):
        return "Write the answer as an exact decimal number (3/4 as 0.75)."
    return ("Write the answer as a decimal number with at least three correct decimals "
            "(1/3 as 0.333).")


def text_html(text: str) -> str:
    """Plain question text as HTML paragraphs: a blank line starts a new one,
    a line end stays a line break."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    paragraphs = [part for part in text.split("\n\n") if part.strip()]
    return "".join("<p>" + "<br/>".join(escape.html_text(line) for line in part.split("\n"))
                   + "</p>" for part in paragraphs)


def question_html(question: Question, picture: str | None = None) -> str:
    """The question as HTML for a tool that reads decimals only: its text,
    how to write the answer, and the picture (``picture``: its src)."""
    parts = [text_html(question.text)]
    advice = how_to_write(question.answer)
    if advice:
        parts.append(text_html(advice))
    if picture is not None:
        parts.append(f'<p><img src="{escape.html_text(picture)}" '
                     f'alt="{escape.html_text(picture_alt(question))}"/></p>')
    return "".join(parts)


def picture_alt(question: Question) -> str:
    return f"The scene of {question.title}: the grid and the primitive, before any step"


def worked_html(worked: Worked, table_class: str = "") -> str:
    """The worked steps as an HTML table (of the tool's CSS class
    ``table_class``) followed by the sentence that says how the answer follows."""
    head = "".join(f"<th>{escape.html_text(name)}</th>" for name in worked.columns)
    rows = "".join("<tr>" + "".join(f"<td>{escape.html_text(cell)}</td>" for cell in row)
                   + "</tr>" for row in worked.rows)
    css = f' class="{escape.html_text(table_class)}"' if table_class else ""
    return (f"<table{css}><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>"
            f"<p>{escape.html_text(worked.summary)}</p>")


def questions(bank) -> list[tuple[str, Question]]:
    """Every question of ``bank`` with the name of its group, in order."""
    return [(group, question) for group, members in bank.groups for question in members]


def group_name(bank, group: str) -> str:
    """What a group is called in a quiz tool: the student's id, or the seed."""
    return group or f"seed {bank.seed}"

