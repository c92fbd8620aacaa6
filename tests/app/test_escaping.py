"""Text a person typed (a scene's title, its bookmark names, an answer) goes
through the real commands with each format's dangerous sequences, and every
result is parsed back as its reader would: the page in Chromium, the SVG by
an XML parser, the LaTeX by a small tokeniser, the Markdown by Markdown
renderers, the CSV by csv.reader. The text comes out as itself, never as
markup, a command, a link, an image or a formula."""
from __future__ import annotations

import csv
import io
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from app.model import escape
from app.model.scene import Scene, save
from app.teaching.exercise import Exercise
from tests.support import record
from tests.support.browser import open_page, start_browser

DANGEROUS = ["<!--<script>", "</script>", "]]>", "\\input{/etc/hostname}", "line\n\\write18{ls}",
             "100% sure", "![x](http://evil/x.png)", "<img src=x onerror=alert(1)>",
             "=cmd|' /C calc'!A0", "<http://evil/>", "[a](http://evil/) *b* `c` # d",
             "^^J ~ $ & _ { } [ ] | \" '", "cr\rlf\r\nsep\u2028end"]
TITLE = " ".join(DANGEROUS)
LINES = re.compile("\r\n|\r|\n")  # where TeX ends a line


def one_line(text: str) -> str:
    """``text`` as a one-line format shows it: each control character (line
    ends included) and U+2028 a space."""
    return re.sub("[\x00-\x1f\x7f\u2028]", " ", text)


def collapsed(text: str) -> str:
    """``text`` as the DOM gives an option's text or a document's title."""
    return re.sub("[ \t\n\f\r]+", " ", text).strip()


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    scene = Scene(algorithm="line-bresenham", points=((1, 1), (12, 6)), width=14, height=8,
                  title=TITLE, bookmarks=tuple({"name": name, "step": k + 1}
                                               for k, name in enumerate(DANGEROUS[:10])))
    path = tmp_path_factory.mktemp("scene") / "scene.json"
    save(scene, path)
    return path


# ------------------------------------------------------------------ HTML
@pytest.fixture(scope="module")
def browser():
    driver = start_browser()
    yield driver
    driver.quit()


def test_the_page_starts_and_shows_every_text_literally(scene_file, tmp_path, run_cli, browser):
    page = tmp_path / "page.html"
    status, _, err = run_cli("export", scene_file, "--html", page)
    assert status == 0, err
    raw = page.read_text(encoding="utf-8")
    # One script element, ended where the player ends it; no comment opened by the data.
    assert raw.count("</script") == 1 and raw.count("<!--") == 1
    open_page(browser, page)  # fails when the player does not start
    browser.find_element(By.TAG_NAME, "body").send_keys(Keys.ARROW_RIGHT)
    assert browser.find_element(By.ID, "stepno").get_attribute("data-step") == "1"
    shown = browser.execute_script(
        "return [document.getElementById('title').textContent, document.title,"
        " [...document.querySelectorAll('#chapters option')].slice(1).map(o => o.text),"
        " [...document.querySelectorAll('#marks span')].map(s => s.title),"
        " document.querySelectorAll('img, script, iframe, a').length]")
    title, tab, chapters, marks, elements = shown
    assert title == TITLE and tab == collapsed(f"{TITLE} \u2014 RasterLab")
    assert chapters == [collapsed(f"{name} (step {k + 1})") for k, name in enumerate(DANGEROUS[:10])]
    assert marks == DANGEROUS[:10]
    assert elements == 1  # the player's own script


# ------------------------------------------------------------------ SVG
def test_every_svg_frame_parses_with_the_title_as_given(scene_file, tmp_path, run_cli):
    folder = tmp_path / "svg"
    status, _, err = run_cli("export", scene_file, "--svg-dir", folder, "--to", "3")
    assert status == 0, err
    frames = sorted(folder.glob("*.svg"))
    assert len(frames) == 4
    for frame in frames:
        root = ET.parse(frame).getroot()
        names = {element.tag.split("}")[1] for element in root.iter()}
        assert names <= {"svg", "title", "desc", "rect", "polyline", "polygon", "text"}
        assert root.find("{http://www.w3.org/2000/svg}title").text == TITLE
        assert root.find("{http://www.w3.org/2000/svg}desc").text.startswith(TITLE + ": ")


# ------------------------------------------------------------------ LaTeX
# What the program's own LaTeX uses, and the escape forms of text.
ESCAPES = {"textbackslash", "textasciicircum", "textasciitilde", "textless", "textgreater",
           "textbar", "{", "}", "$", "&", "#", "_", "%"}
UNTEX = {r"\textbackslash{}": "\\", r"\textasciicircum{}": "^", r"\textasciitilde{}": "~",
         r"\textless{}": "<", r"\textgreater{}": ">", r"\textbar{}": "|", "{[}": "[", "{]}": "]",
         r"\{": "{", r"\}": "}", r"\$": "$", r"\&": "&", r"\#": "#", r"\_": "_", r"\%": "%"}


def tex_tokens(text: str) -> tuple[list[str], list[str]]:
    """(the control sequences, the comment lines) of ``text``, read as TeX
    reads it: a comment runs from an unescaped % to the line's end."""
    commands, comments = [], []
    i = 0
    while i < len(text):
        char = text[i]
        if char == "\\":
            word = re.match(r"[A-Za-z]+|.", text[i + 1:], re.S).group()
            commands.append(word)
            i += 1 + len(word)
        elif char == "%":
            end = LINES.search(text, i)
            comments.append(text[i:end.start() if end else len(text)])
            i = end.end() if end else len(text)
        else:
            assert text[i:i + 2] != "^^", "^^ notation outside a comment"
            i += 1
    return commands, comments


def untex(text: str) -> str:
    pattern = "|".join(re.escape(form) for form in sorted(UNTEX, key=len, reverse=True))
    return re.sub(pattern, lambda match: UNTEX[match.group()], text)


def braced(text: str, start: int) -> str:
    """The group opening at ``text[start]``, without its braces."""
    depth, i = 0, start
    while True:
        if text[i] == "\\":
            i += 2
            continue
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[start + 1:i]
        i += 1


def test_the_beamer_frame_title_typesets_as_given(scene_file, tmp_path, run_cli):
    tex = tmp_path / "frames.tex"
    status, _, err = run_cli("export", scene_file, "--pdf", tmp_path / "frames.pdf",
                             "--beamer", tex, "--to", "2")
    assert status == 0, err
    text = tex.read_text(encoding="utf-8")
    commands, comments = tex_tokens(text)
    assert set(commands) <= ESCAPES | {"begin", "end", "centering", "only", "includegraphics",
                                       "linewidth", "textheight"}
    assert comments == [l for l in text.splitlines() if l.startswith("%")]
    title = braced(text, text.index("\\begin{frame}") + len("\\begin{frame}"))
    assert untex(title) == one_line(TITLE)
    assert "\\textbackslash\\{\\}" not in text


def test_a_pdf_name_latex_cannot_read_is_refused_before_any_work(tmp_path, run_cli):
    pdf = tmp_path / "a%b.pdf"
    status, out, err = run_cli("export", "demo-bresenham", "--pdf", pdf,
                               "--beamer", tmp_path / "a.tex")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "'%'" in err and not pdf.exists() and not (tmp_path / "a.tex").exists()


def test_the_worksheet_tex_keeps_the_title_in_its_comment(scene_file, tmp_path, run_cli):
    from app.model.escape import latex_text
    from app.teaching.worksheet import FIELDS
    status, _, err = run_cli("worksheet", scene_file, "--out", tmp_path, "--format", "tex")
    assert status == 0, err
    for name, kind in (("worksheet.tex", "Worksheet"), ("answers.tex", "Answer key")):
        text = (tmp_path / name).read_text(encoding="utf-8")
        head = text[:text.index("\\begin{tabular}")]
        commands, comments = tex_tokens(text)
        assert set(commands) <= ESCAPES | {"begin", "end", "hline", "\\"}
        # Every line of the title is a comment line of its own (the student's
        # sheet then has its name and date line).
        fields = [latex_text(FIELDS) + r" \\"] if kind == "Worksheet" else []
        assert [line for line in LINES.split(head)[:-1]
                if not (line.startswith("% ") or line == "%")] == fields
        lines = LINES.split(f"{kind}: {TITLE} (line-bresenham)")
        assert [c[2:] for c in comments[:len(lines)]] == [one_line(line).rstrip() for line in lines]
        assert comments[len(lines)].startswith("% Inputs: P = (")


def test_latex_text_typesets_every_special_character():
    for text in DANGEROUS + ["a\\b", "{}", "\x00\x0c\x7f"]:
        commands, comments = tex_tokens(escape.latex_text(text))
        assert set(commands) <= ESCAPES and comments == []
        assert untex(escape.latex_text(text)) == one_line(text)


# ------------------------------------------------------------------ Markdown
class Html(HTMLParser):
    """The tags of a rendered page, their attributes, and the h1's text."""

    def __init__(self, text):
        super().__init__(convert_charrefs=True)
        self.tags, self.heading, self._in_h1 = [], "", False
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._in_h1 = self._in_h1 or tag == "h1"

    def handle_endtag(self, tag):
        self._in_h1 = self._in_h1 and tag != "h1"

    def handle_data(self, data):
        if self._in_h1:
            self.heading += data


def render_python_markdown(text):
    markdown = pytest.importorskip("markdown")
    return markdown.markdown(text, extensions=["tables"])


def render_commonmark(text):
    markdown_it = pytest.importorskip("markdown_it")
    return markdown_it.MarkdownIt("commonmark").enable("table").render(text)


@pytest.mark.parametrize("render", [render_python_markdown, render_commonmark])
def test_the_markdown_worksheet_renders_no_html_link_or_remote_image(
        render, scene_file, tmp_path, run_cli):
    status, _, err = run_cli("worksheet", scene_file, "--out", tmp_path, "--format", "md")
    assert status == 0, err
    page = Html(render((tmp_path / "worksheet.md").read_text(encoding="utf-8")))
    tags = {tag for tag, _ in page.tags}
    assert tags <= {"h1", "p", "code", "pre", "table", "thead", "tbody", "tr", "th", "td", "img"}
    assert [attrs["src"] for tag, attrs in page.tags if tag == "img"] == ["worksheet-grid.png"]
    assert page.heading == "Worksheet: " + one_line(TITLE)


@pytest.mark.parametrize("render", [render_python_markdown, render_commonmark])
def test_markdown_text_in_a_table_cell_is_one_cell_of_text(render):
    text = "| a | b |\n|---|---|\n| " + " | ".join(
        escape.markdown_text(cell) for cell in (DANGEROUS[8], DANGEROUS[6])) + " |\n"
    page = Html(render(text))
    assert [tag for tag, _ in page.tags].count("td") == 2
    assert {tag for tag, _ in page.tags} <= {"table", "thead", "tbody", "tr", "th", "td"}


# ------------------------------------------------------------------ CSV
def guarded(cell: str) -> str:
    return "'" + cell if cell[:1] in ("=", "+", "-", "@", "\t", "\r") else cell


def test_answers_read_back_as_text_no_spreadsheet_runs():
    exercise = Exercise(record("line-bresenham", ((2, 3), (17, 9))), "decision")
    typed = ["=cmd|' /C calc'!A0", "+1+2", "@SUM(A1)", "-2+3", "\tx", "line\nbreak", "NE"]
    for given in typed:
        exercise.answer(given)
    rows = list(csv.reader(io.StringIO(exercise.csv_text())))
    assert [row[rows[0].index("given")] for row in rows[1:1 + len(typed)]] == [guarded(given) for given in typed]


def test_numbers_stay_numbers_in_csv():
    numbers = ["-2", "-0.5", "+3", "-1/2", "-1e-3", ".5", "-inf", "17"]
    assert escape.csv_row(numbers + [-4, 2.5, None]) == numbers + [-4, 2.5, None]
    assert escape.csv_row(["-2-", "-1/2/3", "- 2", "=2"]) == ["'-2-", "'-1/2/3", "'- 2", "'=2"]


def test_the_worksheet_csv_keeps_negative_numbers(scene_file, tmp_path, run_cli):
    status, _, err = run_cli("worksheet", scene_file, "--out", tmp_path, "--format", "csv")
    assert status == 0, err
    rows = list(csv.reader(open(tmp_path / "answers.csv", encoding="utf-8")))
    negative = [cell for row in rows[1:] for cell in row if cell.startswith("-")]
    assert negative and all(re.fullmatch(r"-\d+", cell) for cell in negative)
    assert not any(cell.startswith("'") for row in rows for cell in row)


# ------------------------------------------------------------------ every format
def test_lone_surrogates_and_controls_never_break_a_writer():
    text = "a\ud800b\x00c\x1bd"
    for function in (escape.html_text, escape.xml_text, escape.latex_text, escape.latex_comment,
                     escape.markdown_text, escape.csv_cell):
        function(text).encode("utf-8")
    ET.fromstring(f"<t a=\"{escape.xml_text(text)}\">{escape.xml_text(text)}</t>")
    assert "\\ud800" in escape.script_json(text)


def test_foreign_text_keeps_lines_and_tabs_and_nothing_a_terminal_acts_on():
    text = escape.foreign_text("a\tb\r\nc\rd\x00\x07\x1b[2J\x7f\x9b\ud800\udfff\ufffe é≤")
    assert text == "a\tb\nc\nd\ufffd\ufffd\ufffd[2J\ufffd\ufffd\ufffd\ufffd\ufffd é≤"
    text.encode("utf-8")
    ET.fromstring(f"<a>{escape.xml_text(text)}</a>")
    assert escape.foreign_text("x" * 10, limit=4) == "xxxx\n[6 more characters not shown]"
