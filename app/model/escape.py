"""Text a person typed (scene titles, bookmark names, answers, file names),
made safe for each format the program writes, in one place.

Every function takes any ``str`` and returns text that the format reads as
that same text and as nothing else: no markup, command, comment end or
formula can come out of it. Characters no format can hold (lone surrogates,
which a JSON file may spell as ``\\ud800``, and control characters) become
U+FFFD or a space, so the UTF-8 writers never fail on them.

    html_text       HTML text and quoted attribute values
    script_json     a value as JSON inside a <script> element
    json_text       a string for a JSON file another program reads (no lone surrogate)
    xml_text        XML (SVG) text and quoted attribute values
    xml_chars       text an XML library (ElementTree) escapes: what XML cannot hold as U+FFFD
    latex_text      LaTeX text: every special character as its command
    latex_comment   LaTeX ``%`` comment lines, one per line of the text
    latex_file_name a file name LaTeX can be given, or ValueError
    markdown_text   Markdown inline text: no raw HTML, links or images
    csv_row         CSV cells guarded against spreadsheet formulas
    gift_text       Moodle GIFT text: its marks (~ = # { } : and \\) escaped, one line
    shortanswer     a Moodle short answer, matched as written: its wildcard * escaped
    moodle_category one name in a Moodle category path: its separator / doubled
    foreign_text    what another program wrote (a student's code), safe for any of these
                    and for a terminal: no control character, escape sequence or lone surrogate
"""
from __future__ import annotations

import html
import json
import re
from xml.sax.saxutils import escape as _xml_escape

# Lone surrogates: they cannot be written as UTF-8.
_SURROGATE = re.compile("[\ud800-\udfff]")
# Characters XML 1.0 cannot hold at all (besides surrogates).
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")
# Line ends and other controls: TeX ends a line (and so a comment) at \r and
# \n, reads ^^L as \par and refuses NUL and DEL; one line of text has none.
_CONTROL = re.compile("[\x00-\x1f\x7f\x85\u2028\u2029]")
_LINE_END = re.compile("\r\n|\r|\n")  # where TeX ends a line


# Control characters a terminal acts on (ESC starts an escape sequence, \x9b
# is CSI on its own) and the non-characters XML refuses; line ends and tabs stay.
_FOREIGN = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ufffe\uffff]")


def encodable(text: str) -> str:
    """``text`` with its lone surrogates (which no UTF encoding can write) as U+FFFD."""
    return _SURROGATE.sub("\ufffd", str(text))


def html_text(text: str) -> str:
    """HTML text, also safe inside a quoted attribute value (" and ' too)."""
    return html.escape(encodable(text), quote=True)


def script_json(value) -> str:
    """``value`` as JSON to place inside a <script> element: no ``<``, ``>``
    or ``&`` is left, so neither ``</script>`` nor ``<!--`` (which makes the
    HTML parser skip the element's real end) can appear. ``ensure_ascii``
    spells every other character, U+2028/2029 and lone surrogates included,
    as a \\u escape."""
    text = json.dumps(value, separators=(",", ":"), allow_nan=False, ensure_ascii=True)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def json_text(text: str) -> str:
    """A string for a JSON file another program reads: JSON can spell a
    lone surrogate (``\\ud800``) but many readers refuse it, and controls
    other than line ends and tabs mean nothing there; both as U+FFFD."""
    return _FOREIGN.sub("\ufffd", encodable(text))


def xml_chars(text: str) -> str:
    """``text`` with each character XML 1.0 cannot hold (controls, lone
    surrogates) as U+FFFD, for a library that escapes the rest itself:
    ElementTree writes them as they are, or as character references, and
    the file no longer parses."""
    return _NOT_XML.sub("\ufffd", encodable(text))


def xml_text(text: str) -> str:
    """XML text, also safe inside a double-quoted attribute value."""
    text = xml_chars(text)
    return _xml_escape(text, {'"': "&quot;", "\r": "&#13;", "\t": "&#9;", "\n": "&#10;"})


_LATEX = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
          "#": r"\#", "^": r"\textasciicircum{}", "_": r"\_", "~": r"\textasciitilde{}",
          "%": r"\%", "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}",
          # In braces, so that text after a tabular's \\ is not read as its [spacing].
          "[": "{[}", "]": "{]}"}


def latex_text(text: str) -> str:
    """LaTeX text that typesets as ``text``: each special character as its
    command, line ends and other controls as spaces."""
    text = _CONTROL.sub(" ", encodable(text))
    return "".join(_LATEX.get(char, char) for char in text)


def latex_comment(text: str) -> str:
    """``text`` as LaTeX comment lines, each starting with ``% ``: a line
    end in the text starts a new comment line instead of ending the comment."""
    lines = _LINE_END.split(encodable(text))
    return "\n".join(f"% {_CONTROL.sub(' ', line)}".rstrip() for line in lines)


# What a file name given to \includegraphics may not hold: TeX's special
# characters and controls (spaces and underscores are fine in LaTeX since 2019).
_NOT_IN_FILE_NAME = re.compile(r"[\\{}$&#^~%\"\x00-\x1f\x7f\x85\u2028\u2029\ud800-\udfff]")


def latex_file_name(name: str) -> str:
    """``name`` unchanged when LaTeX can read it as a file name; else ValueError
    naming the first character it cannot."""
    bad = _NOT_IN_FILE_NAME.search(name)
    if bad:
        raise ValueError(f"LaTeX cannot read a file name holding {bad.group()!r}")
    return name


_MARKDOWN_ENTITIES = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}
# Characters that start emphasis, code, links and images (no link without
# an unescaped "]"), close a heading or split a table cell: escaped with a
# backslash, which CommonMark and Python-Markdown read as the character.
_MARKDOWN_PUNCTUATION = set("\\`*_[]!#|")


def markdown_text(text: str) -> str:
    """Markdown inline text (a heading, a table cell) that renders as
    ``text``: ``<``, ``>`` and ``&`` as entities, so no raw HTML and no
    ``<http://...>`` autolink; link, image and emphasis marks escaped; line
    ends as spaces. A bare URL stays text, which some viewers show as a
    link; no image is ever fetched."""
    out = []
    for char in _CONTROL.sub(" ", encodable(text)):
        if char in _MARKDOWN_ENTITIES:
            out.append(_MARKDOWN_ENTITIES[char])
        else:
            out.append("\\" + char if char in _MARKDOWN_PUNCTUATION else char)
    return "".join(out)


# What a spreadsheet reads as a formula, or as the start of one (OWASP's list).
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?|[+-]?(inf|nan)",
                     re.IGNORECASE)


def csv_cell(cell):
    """A CSV cell that no spreadsheet runs: text starting with = + - @ or a
    tab or carriage return gets a leading apostrophe (shown by spreadsheets
    as text, kept by csv readers). Numbers, negative ones and fractions such
    as -1/2 included, and non-text cells are left as they are."""
    if not isinstance(cell, str):
        return cell
    cell = encodable(cell)
    if cell.startswith(_FORMULA_START) and not _NUMBER.fullmatch(cell):
        return "'" + cell
    return cell


def csv_row(cells) -> list:
    """A row for ``csv.writer``: every cell through ``csv_cell``."""
    return [csv_cell(cell) for cell in cells]


# GIFT's marks: a backslash before one makes it text (Moodle's "GIFT format"
# page); the backslash itself is escaped first, so "\\=" stays as written.
_GIFT_MARKS = set("\\~=#{}:")


def gift_text(text: str) -> str:
    """Text inside a GIFT question (title, text, answers, feedback) that Moodle
    reads as ``text``: each mark as ``\\mark``, line ends as GIFT's ``\\n``
    (a blank line would end the question), other controls as spaces."""
    lines = _LINE_END.split(encodable(text))
    return "\\n".join("".join("\\" + char if char in _GIFT_MARKS else char
                               for char in _CONTROL.sub(" ", line)) for line in lines)


def shortanswer(text: str) -> str:
    """A Moodle short answer that matches only ``text``: Moodle reads ``*``
    in an answer as "any characters", and ``\\*`` as the character itself."""
    return encodable(text).replace("*", "\\*")


def moodle_category(name: str) -> str:
    """One level of a Moodle category path (``$course$/top/NAME``): Moodle
    splits the path at ``/`` and reads ``//`` as a ``/`` within a name."""
    return _CONTROL.sub(" ", encodable(name)).replace("/", "//")


def foreign_text(text: str, limit: int | None = None) -> str:
    """Text another program produced (a student's messages, prints and
    names), safe to print and to hand to any writer above: lone surrogates
    and control characters other than line ends and tabs as U+FFFD, a
    carriage return as a line end; at most ``limit`` characters, with the
    count of those left out."""
    text = _FOREIGN.sub("\ufffd", encodable(text).replace("\r\n", "\n").replace("\r", "\n"))
    if limit is not None and len(text) > limit:
        text = f"{text[:limit]}\n[{len(text) - limit:,} more characters not shown]"
    return text
