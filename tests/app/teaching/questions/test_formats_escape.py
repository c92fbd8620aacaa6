"""The escaping the quiz-tool writers add to app/model/escape.py, and every
writer fuzzed with adversarial text in each field a person or a scene file
can fill: the file still parses as its format, keeps its structure, and
gives the text back (what the format cannot hold as U+FFFD or a space)."""
from __future__ import annotations

import io
import json
import re
import xml.etree.ElementTree as ET
import zipfile

from hypothesis import given
from hypothesis import strategies as st

from app.model import escape
from app.teaching.questions import gift, moodle, qti
from app.teaching.questions.model import CHOICE, SHORT, Answer, Bank
from tests.app.cli.test_fuzz_cli import fuzz_settings
from tests.app.teaching.questions import test_formats_gift, test_formats_moodle, test_formats_qti
from tests.support import question_bank as qb

DANGEROUS = ["<", "&", "]]>", "{", "}", "=", "~", "#", ":", "\\", "\\n", "*", "####", "::",
             "\n", "\r\n", "\r", "\x00", "\x01", "\x85", "\u2028", "\ud800", "\udfff", "\ufffe",
             "$CATEGORY:", "//", "[html]", "\"", "'", "-->", "@@PLUGINFILE@@/x.png"]
# XML 1.0's Char production: what a document can hold.
XML_CHAR = re.compile("[\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def texts():
    anything = st.characters(codec=None, exclude_categories=())
    part = st.one_of(st.sampled_from(DANGEROUS), st.text(alphabet=anything, max_size=4))
    return st.lists(part, min_size=1, max_size=8).map("".join).filter(str.strip)


def as_xml(text: str, attribute: bool = False) -> str:
    """``text`` as an XML parser gives it back: in element text, line ends
    as \\n (XML 1.0, "End-of-Line Handling"; an attribute's are written as
    character references, which stay); a character XML cannot hold as U+FFFD."""
    if not attribute:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    return "".join(char if XML_CHAR.fullmatch(char) else "\ufffd" for char in text)


def test_gift_text_escapes_each_mark_and_keeps_one_line():
    assert escape.gift_text("a~b=c#d{e}f:g\\h") == "a\\~b\\=c\\#d\\{e\\}f\\:g\\\\h"
    assert escape.gift_text("one\r\ntwo\rthree\n\nfour") == "one\\ntwo\\nthree\\n\\nfour"
    assert escape.gift_text("\x00\x1f\ud800\u2028") == "  \ufffd "


def test_a_short_answer_matches_a_star_as_a_star():
    assert escape.shortanswer("a*b**") == "a\\*b\\*\\*"
    assert escape.shortanswer("\ud800") == "\ufffd"


def test_a_category_name_keeps_its_slash():
    assert escape.moodle_category("2025/26: group A") == "2025//26: group A"
    assert escape.moodle_category("a\nb") == "a b"


def test_json_text_leaves_no_lone_surrogate_or_control():
    text = escape.json_text("a\ud800b\x00c\td\ne")
    assert text == "a\ufffdb\ufffdc\td\ne"
    assert json.loads(json.dumps(text, ensure_ascii=False)) == text
    text.encode("utf-8")


def fuzzed_bank(title, text, short, choices, summary) -> Bank:
    worked = qb.Worked(columns=("step", title), rows=(("0", summary),), summary=summary)
    return Bank(groups=((title, (
        qb.question("line-pixel-at-step", 1, title, text, Answer(SHORT, short, short), worked),
        qb.question("line-step-choice", 2, title, text,
                    Answer(CHOICE, 1, choices[1], choices=tuple(choices)), worked))),), seed=3)


FIELDS = dict(title=texts(), text=texts(), short=texts(),
              choices=st.lists(texts(), min_size=2, max_size=3, unique=True), summary=texts())


@given(**FIELDS)
@fuzz_settings(30)
def test_moodle_xml_keeps_any_text(title, text, short, choices, summary):
    root = ET.fromstring(moodle.xml_bytes(fuzzed_bank(title, text, short, choices, summary)))
    assert test_formats_moodle.structure_problems(root) == []
    category, first, second = root.findall("question")
    assert first.findtext("name/text") == as_xml(title)
    assert first.findtext("answer/text") == as_xml(short).replace("*", "\\*")
    assert [a.get("fraction") for a in second.findall("answer")] == [
        "100" if i == 1 else "0" for i in range(len(choices))]
    assert qb.table_cells(first.findtext("generalfeedback/text"))[1] == ["0", as_xml(summary)]


@given(**FIELDS)
@fuzz_settings(30)
def test_qti_keeps_any_text(title, text, short, choices, summary):
    bank = fuzzed_bank(title, text, short, choices, summary)
    archive = zipfile.ZipFile(io.BytesIO(qti.zip_bytes(bank)))
    manifest = ET.fromstring(archive.read("imsmanifest.xml"))
    assert test_formats_qti.problems(manifest, test_formats_qti.CP,
                                     test_formats_qti.MANIFEST_RULES) == []
    first, second = (ET.fromstring(archive.read(f"items/q000{n}.xml")) for n in (1, 2))
    for item in (first, second):
        assert test_formats_qti.problems(item, test_formats_qti.QTI,
                                         test_formats_qti.ITEM_RULES) == []
    assert first.get("title") == as_xml(f"[{title}] {title}", attribute=True)
    assert test_formats_qti.score(first, as_xml(short, attribute=True)) == 1  # its mapKey
    assert [c.text or "" for c in second.iter(f"{test_formats_qti.QTI}simpleChoice")] == [
        as_xml(choice) for choice in choices]


def as_gift(text: str) -> str:
    """``text`` as GIFT gives it back: line ends as \\n, other controls as
    spaces, a lone surrogate as U+FFFD."""
    text = re.sub("\r\n|\r", "\n", text)
    text = re.sub("[\x00-\x09\x0b-\x1f\x7f\x85\u2028\u2029]", " ", text)
    return re.sub("[\ud800-\udfff]", "\ufffd", text)


@given(**FIELDS)
@fuzz_settings(30)
def test_gift_keeps_any_text(title, text, short, choices, summary):
    data = gift.gift_bytes(fuzzed_bank(title, text, short, choices, summary))
    first, second = test_formats_gift.read(data)
    assert first["title"] == as_gift(title)
    assert first["answers"] == [("=", as_gift(short).replace("*", "\\*").strip())]
    assert [mark for mark, _ in second["answers"]] == [
        "=" if i == 1 else "~" for i in range(len(choices))]
