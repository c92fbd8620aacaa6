"""Question sheets on paper: Markdown or PDF, one sheet per student (or one
for the whole bank), and a separate answer key with the worked steps.

The files go into a folder, staged and moved in together
(app/model/staging.py) with a manifest of the names written, as a
worksheet's are, so a failure never leaves a new sheet beside an old key:

- md: questions.md and key.md, with the pictures beside them
  (picture-001.png, ... in the order the questions come);
- pdf: questions.pdf (each student's sheet from a new page) and key.pdf,
  drawn with fpdf2 in the shipped DejaVu fonts.

Nothing depends on the clock or the machine: the same bank gives the same
bytes.
"""
from __future__ import annotations

import io
from datetime import datetime, timezone
from pathlib import Path

from app.model.escape import markdown_text
from app.model.files import Output, check_outputs, listed
from app.model.shipped import FONTS
from app.model.staging import listed_names, write_bytes, write_folder
from app.teaching.worksheet import FIELDS

MANIFEST = ".rasterlab-questions.json"
EPOCH = datetime(2000, 1, 1, tzinfo=timezone.utc)  # the PDFs' date: fixed, so files repeat
FONT_FILES = {("sans", ""): "DejaVuSans.ttf", ("sans", "B"): "DejaVuSans-Bold.ttf",
              ("mono", ""): "DejaVuSansMono.ttf", ("mono", "B"): "DejaVuSansMono-Bold.ttf"}
PICTURE_WIDTH = 90  # mm on the page, at most


def file_names(fmt: str) -> list[str]:
    """The fixed names of format ``fmt`` (pictures aside)."""
    return [f"questions.{fmt}", f"key.{fmt}"]


def outputs(bank, path) -> list[Output]:
    """What the sheets write at ``path`` (app/model/files.py policy)."""
    path = Path(path)
    return [Output("--out", path, folder=True)] + [
        Output("--out", path / name, foreign=listed(MANIFEST))
        for fmt in ("md", "pdf") for name in file_names(fmt)]


def _numbered(bank):
    """(group id, number within the bank, question) in order."""
    n = 0
    for sid, questions in bank.groups:
        for question in questions:
            n += 1
            yield sid, n, question


# ------------------------------------------------------------------ Markdown
def markdown(bank, key: bool) -> str:
    md = markdown_text
    lines = [f"# {'Answer key' if key else 'Questions'} (seed {bank.seed})", ""]
    current = None
    for sid, n, question in _numbered(bank):
        if sid != current:
            current = sid
            lines += [f"## Student: {md(sid)}", ""] if sid else []
            if not key:
                lines += [md(FIELDS), ""]
        lines += [f"### {n}. {md(question.title)}", "", md(question.text), ""]
        if question.picture:
            lines += [f"![the scene of question {n}](picture-{n:03d}.png)", ""]
        if key:
            lines += _markdown_key(question)
    return "\n".join(lines)


def _markdown_key(question) -> list[str]:
    md = markdown_text
    worked = question.worked
    lines = [f"**Answer:** {md(question.answer.text)}", ""]
    if worked.columns:
        lines += ["| " + " | ".join(md(c) for c in worked.columns) + " |",
                  "|" + "|".join("---" for _ in worked.columns) + "|"]
        lines += ["| " + " | ".join(md(c) for c in row) + " |" for row in worked.rows]
        lines.append("")
    return lines + [md(worked.summary), ""]


def write_md(bank, path, force: bool = False) -> list[Path]:
    check_outputs(outputs(bank, path), force=force)
    files = {"questions.md": markdown(bank, False).encode("utf-8"),
             "key.md": markdown(bank, True).encode("utf-8")}
    files.update((f"picture-{n:03d}.png", q.picture) for _, n, q in _numbered(bank) if q.picture)
    return _write_sheets(path, files)


# ----------------------------------------------------------------------- PDF
def _new_pdf(title: str):
    from fpdf import FPDF  # loaded only when a PDF is written
    pdf = FPDF(format="A4")
    pdf.set_creation_date(EPOCH)
    pdf.set_title(title)
    pdf.set_margins(15, 15, 15)
    pdf.set_auto_page_break(True, margin=15)
    for (family, style), name in FONT_FILES.items():
        pdf.add_font(family, style, str(FONTS / name))  # shipped: no system font is asked for
    return pdf


def pdf_bytes(bank, key: bool) -> bytes:
    """Each group from a new page: its heading, then each question with its
    picture; on the key, the answer and the worked steps under each."""
    pdf = _new_pdf(f"{'Answer key' if key else 'Questions'} (seed {bank.seed})")
    current = None
    for sid, n, question in _numbered(bank):
        if sid != current or current is None:
            current = sid
            pdf.add_page()
            pdf.set_font("sans", "B", 14)
            kind = "Answer key" if key else "Questions"
            heading = f"{kind}, student: {sid}" if sid else kind
            pdf.multi_cell(0, 7, f"{heading} (seed {bank.seed})", new_x="LMARGIN", new_y="NEXT")
            if not key:
                pdf.set_font("sans", "", 10)
                pdf.multi_cell(0, 8, FIELDS, new_x="LMARGIN", new_y="NEXT")
        _pdf_question(pdf, n, question, key)
    return bytes(pdf.output())


def _pdf_question(pdf, n: int, question, key: bool) -> None:
    # A question starts a page of its own rather than leave its picture
    # (or its worked steps) to the next one.
    if pdf.get_y() + _room(question, key) > pdf.h - pdf.b_margin:
        pdf.add_page()
    pdf.ln(3)
    pdf.set_font("sans", "B", 11)
    pdf.multi_cell(0, 6, f"{n}. {question.title}", new_x="LMARGIN", new_y="NEXT")
    pdf.set_font("sans", "", 9.5)
    pdf.multi_cell(0, 5, question.text, new_x="LMARGIN", new_y="NEXT")
    if question.picture and not key:
        _pdf_picture(pdf, question.picture)
    if key:
        pdf.set_font("sans", "B", 10)
        pdf.multi_cell(0, 6, f"Answer: {question.answer.text}", new_x="LMARGIN", new_y="NEXT")
        _pdf_table(pdf, question.worked)
        pdf.set_font("sans", "", 9)
        pdf.multi_cell(0, 5, question.worked.summary, new_x="LMARGIN", new_y="NEXT")


def _room(question, key: bool) -> float:
    """About the height (mm) a question takes: its text, and its picture or
    its worked steps; a question longer than a page still runs on."""
    text = 12 + 5 * (len(question.text) // 100 + 1)
    if key:
        return text + 12 + 4.5 * (len(question.worked.rows) + 1)
    return text + (_picture_size(question.picture)[1] + 3 if question.picture else 0)


def _picture_size(png: bytes) -> tuple[float, float]:
    """The picture's width and height on the page, in mm."""
    from PIL import Image
    with Image.open(io.BytesIO(png)) as image:
        width, height = image.size
    w = min(PICTURE_WIDTH, width * 0.25)  # 0.25 mm a screen pixel: a 16 px cell is 4 mm
    return w, w * height / width


def _pdf_picture(pdf, png: bytes) -> None:
    w, h = _picture_size(png)
    if pdf.get_y() + h > pdf.h - pdf.b_margin:
        pdf.add_page()
    pdf.image(io.BytesIO(png), x=pdf.l_margin, y=pdf.get_y() + 1, w=w, h=h)
    pdf.set_y(pdf.get_y() + h + 2)


def _pdf_table(pdf, worked) -> None:
    if not worked.columns:
        return
    pdf.set_font("mono", "", 7.5)
    with pdf.table(text_align="LEFT", line_height=4, first_row_as_headings=True) as table:
        for row in (worked.columns, *worked.rows):
            cells = table.row()
            for cell in row:
                cells.cell(cell)


def write_pdf(bank, path, force: bool = False) -> list[Path]:
    check_outputs(outputs(bank, path), force=force)
    return _write_sheets(path, {"questions.pdf": pdf_bytes(bank, False),
                               "key.pdf": pdf_bytes(bank, True)})


# --------------------------------------------------------------------- files
def _write_sheets(path, files: dict[str, bytes]) -> list[Path]:
    """Write ``files`` (name -> bytes) into the folder ``path`` together;
    the paths written. Pictures an earlier bank wrote there and this one
    does not (of a longer bank) are removed; the other format's sheets
    written there before stay the program's."""
    earlier = listed_names(path, MANIFEST)
    stale = [name for name in earlier if name.startswith("picture-") and name not in files]
    return write_folder(path, "questions", sorted(files), write_bytes(files), MANIFEST,
                        keep=earlier, remove=stale)