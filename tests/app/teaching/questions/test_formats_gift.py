"""The GIFT writer, read back by a reader written from Moodle's "GIFT
format" page: questions apart by blank lines, ``//`` comment lines,
``$CATEGORY:`` lines, ``::title::``, a ``[html]`` text, an answer block in
braces (``{#value:tolerance}``, ``{=a =b}``, ``{=right ~wrong}``) with the
general feedback after ``####``; a backslash makes ~ = # { } : and itself
text, and ``\\n`` is a line end."""
from __future__ import annotations

import re

from app.teaching.questions import gift
from tests.support import question_bank as qb

MARK = re.compile(r"\\(.)")


def unescape(text: str) -> str:
    return MARK.sub(lambda m: "\n" if m.group(1) == "n" else m.group(1), text)


def split_at(text: str, marks: str) -> list[tuple[str, str]]:
    """``text`` cut before each unescaped mark: (mark, piece) pairs."""
    pieces, mark, start, i = [], "", 0, 0
    while i < len(text):
        if text[i] == "\\":
            i += 2
            continue
        if text[i] in marks:
            pieces.append((mark, text[start:i]))
            mark, start = text[i], i + 1
        i += 1
    return pieces + [(mark, text[start:])]


def read(data: bytes) -> list[dict]:
    """The categories and questions of a GIFT file."""
    found, category = [], None
    for block in data.decode("utf-8").split("\n\n"):
        lines = [line for line in block.split("\n") if line and not line.startswith("//")]
        if not lines:
            continue
        assert len(lines) == 1, block  # a question never spans a blank line
        if lines[0].startswith("$CATEGORY: "):
            category = lines[0].removeprefix("$CATEGORY: ")
            continue
        found.append(dict(category=category, **_question(lines[0])))
    return found


def _question(line: str) -> dict:
    parts = split_at(line, "{}")
    assert [mark for mark, _ in parts] == ["", "{", "}"] and parts[2][1] == ""
    head, block = parts[0][1], parts[1][1]
    title_parts = split_at(head, ":")
    # "::title::text": no unescaped colon in the title or the text
    assert [piece for _, piece in title_parts][:2] == ["", ""] and len(title_parts) == 5
    title, text = title_parts[2][1], title_parts[4][1]
    assert title_parts[3][1] == ""
    assert text.startswith("[html]")
    block, feedback = block.split(" ####")  # an escaped # is \#, never four in a row
    if block.startswith("#"):
        value, tolerance = [unescape(p) for _, p in split_at(block[1:], ":")]
        answers = [("#", value, tolerance)]
    else:
        answers = [(mark, unescape(piece).strip()) for mark, piece in split_at(block, "=~")[1:]]
    return dict(title=unescape(title), text=unescape(text.removeprefix("[html]")),
                answers=answers, feedback=unescape(feedback))


def test_every_kind_of_answer_has_its_block():
    questions = read(gift.gift_bytes(qb.bank()))
    assert [q["answers"] for q in questions[:6]] == [
        [("#", "-3", "0")], [("#", "-0.75", "0")], [("#", "0.333333", "0.0005")],
        [("#", "0.285714", "0.001")],
        [("=", "(2, 1)"), ("=", "(2,1)"), ("=", "2, 1")],
        [("~", "E"), ("=", "NE"), ("~", "neither")]]
    assert "at least three correct decimals" in questions[2]["text"]


def test_the_header_says_pictures_cannot_be_carried_and_feedback_holds_the_steps():
    data = gift.gift_bytes(qb.bank())
    assert data.startswith(b"// RasterLab question bank, seed 7.")
    assert b"GIFT cannot carry pictures" in data.split(b"\n\n")[0]
    first = read(data)[0]
    assert "<img" not in first["text"]
    assert qb.table_cells(first["feedback"]) == qb.worked_cells(qb.WORKED)


def test_each_student_has_a_category():
    questions = read(gift.gift_bytes(qb.per_student()))
    assert [q["category"] for q in questions] == ["$course$/top/RasterLab/s1//a:b"] * 3 + [
        "$course$/top/RasterLab/s2"] * 3
    assert read(gift.gift_bytes(qb.bank()))[0]["category"] == "$course$/top/RasterLab/seed 7"


def test_awkward_text_comes_back_as_written():
    short, choice = read(gift.gift_bytes(qb.bank()))[6:8]
    # The control character is a space in GIFT; the lone surrogate U+FFFD.
    written = qb.AWKWARD.replace("\ud800", "\ufffd").replace("\x01", " ")
    assert short["title"] == "Awkward " + written
    assert "".join(qb.html_fragment(short["text"]).find("p").itertext()) == "Type " + written
    assert short["answers"] == [("=", "x\\*y {z}: =1"), ("=", "<a&b>")]
    assert ["".join(qb.html_fragment(text).itertext()) for _, text in choice["answers"]] == [
        "=1 <b>", "~2 {c}", "#3 : &d;"]
    assert [mark for mark, _ in choice["answers"]] == ["=", "~", "~"]
