"""Banks: distinct variants, seeds derived the same everywhere, students'
ids read from a CSV file; the Markdown and PDF sheets read back."""
import hashlib

import pytest
from pypdf import PdfReader

from app.teaching.questions import bank, sheets
from app.teaching.questions.writers import WRITERS

NAMES = ["line-bresenham-d", "circle-midpoint-d", "fill-span"]


def test_variants_are_distinct_and_titled_in_order():
    drawn = bank.draw(NAMES, 6, seed=3)
    (group, questions), = drawn.groups
    assert group == "" and len(questions) == 18
    assert len({q.text for q in questions}) == 18
    assert [q.title.rsplit(" ", 1)[1] for q in questions] == [f"(#{n})" for n in range(1, 7)] * 3
    assert [q.template for q in questions] == [name for name in NAMES for _ in range(6)]
    assert bank.draw(NAMES, 6, seed=3) == drawn
    assert bank.draw(NAMES, 6, seed=4) != drawn


def test_seeds_are_derived_with_sha256():
    digest = hashlib.sha256("7\x1fline-bresenham-d\x1f1\x1f0".encode()).digest()
    assert bank.derived_seed(7, "line-bresenham-d", 1, 0) == int.from_bytes(digest[:8], "big") >> 1


def test_a_template_that_runs_out_of_variants_gives_up_in_one_line(monkeypatch):
    template = bank.registry.get("line-bresenham-d")
    same = template.make(1)
    monkeypatch.setitem(bank.registry.TEMPLATES, "line-bresenham-d",
                        template.__class__(template.name, template.family, template.title,
                                           template.algorithms, lambda seed, scene=None: same))
    with pytest.raises(ValueError, match="no new variant after 50 draws") as error:
        bank.draw(["line-bresenham-d"], 2, 0)
    assert "\n" not in str(error.value)


@pytest.mark.parametrize("count", [0, 501])
def test_counts_out_of_range_are_refused(count):
    with pytest.raises(ValueError, match="1 .. 500"):
        bank.draw(NAMES, count, 0)


def test_per_student_groups_follow_the_id():
    drawn = bank.per_student(["fill-aet"], 2, ["ann", "bob", "ann"])
    assert [group for group, _ in drawn.groups] == ["ann", "bob"]
    again = bank.per_student(["fill-aet"], 2, ["bob"])
    assert again.groups[0] == drawn.groups[1]
    assert drawn.groups[0][1] != drawn.groups[1][1]


@pytest.mark.parametrize("text, ids", [
    ("s1\ns2\n", ["s1", "s2"]),
    ("name,email\nAnn,ann@uni.edu\nBob,bob@uni.edu\n", ["ann@uni.edu", "bob@uni.edu"]),
    ("Student,grade\n42,A\n43,B\n42,C\n", ["42", "43"]),
])
def test_ids_are_read_from_a_csv_file(tmp_path, text, ids):
    path = tmp_path / "ids.csv"
    path.write_text(text, encoding="utf-8")
    assert bank.read_ids(path) == ids


@pytest.mark.parametrize("data, message", [
    (b"", "holds no student id"), (b"\xff\xfe\x00bad", "cannot be read"),
    (b"id,name\n", "holds no student id")])
def test_a_bad_ids_file_is_refused_in_one_line(tmp_path, data, message):
    path = tmp_path / "ids.csv"
    path.write_bytes(data)
    with pytest.raises(ValueError, match=message) as error:
        bank.read_ids(path)
    assert "\n" not in str(error.value)


def test_the_writers_are_named_by_format():
    assert WRITERS["md"] is sheets.write_md and WRITERS["pdf"] is sheets.write_pdf


def test_markdown_sheets_keep_the_key_apart(tmp_path):
    drawn = bank.per_student(["circle-octant-pixels"], 1, ["ann", "bob"])
    files = sheets.write_md(drawn, tmp_path / "out")
    names = sorted(path.name for path in files)
    assert names == ["key.md", "picture-001.png", "picture-002.png", "questions.md"]
    sheet = (tmp_path / "out" / "questions.md").read_text(encoding="utf-8")
    key = (tmp_path / "out" / "key.md").read_text(encoding="utf-8")
    for _, (question,) in drawn.groups:
        assert question.answer.text not in sheet
        assert question.answer.text in key
    assert "Student: ann" in sheet and "Student: bob" in sheet and "![" in sheet
    assert (tmp_path / "out" / "picture-001.png").read_bytes().startswith(b"\x89PNG")
    # A shorter bank removes the pictures of the longer one it replaces.
    sheets.write_md(bank.draw(["circle-octant-pixels"], 1, 0), tmp_path / "out")
    assert not (tmp_path / "out" / "picture-002.png").exists()


def test_the_pdf_sheet_has_a_page_per_student_and_a_separate_key(tmp_path):
    drawn = bank.per_student(["line-bresenham-pixel"], 1, ["s1", "s2", "s3"])
    sheets.write_pdf(drawn, tmp_path)
    sheet = PdfReader(tmp_path / "questions.pdf")
    assert len(sheet.pages) == 3
    for page, (sid, (question,)) in zip(sheet.pages, drawn.groups):
        text = " ".join(page.extract_text().split())
        assert f"student: {sid}" in text
        assert " ".join(question.text.split())[:60] in text
        assert question.answer.text not in text.split("plotted at step")[-1]
        assert page.images  # the picture is embedded
    key = " ".join(" ".join(page.extract_text() for page in
                            PdfReader(tmp_path / "key.pdf").pages).split())
    for _, (question,) in drawn.groups:
        assert f"Answer: {question.answer.text}" in key
        assert question.worked.summary in key


def test_progress_is_told_once_per_question_drawn():
    from app.teaching.questions import bank
    calls = []
    drawn = bank.per_student(["fill-span", "line-bresenham-ne"], 2, ["ann", "bob", "cy"],
                             progress=lambda: calls.append(1))
    assert len(calls) == 2 * 2 * 3 == sum(len(q) for _, q in drawn.groups)
