"""Pseudo-code built line by line under names, so generators yield names, not numbers.

A family writes its pseudo-code once with ``Code.add(key, text, ...)`` and
its generator yields ``code.at[key]`` (or a local bound to it before a hot
loop): inserting a line then never shifts the lines the generator names.
A line that writes pixels is named ``plot...`` and only such lines are of
kind PLOT, so the name a generator yields says whether the frame plots.

``check_family`` holds a family's source to that convention: the registry
calls it when a spec from outside the shipped families is registered, and
a test calls it for every shipped family (so start-up reads no source). It
reads the source text: a file read and a few regular expressions, not a parse.
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

from algorithms.core.steps import CALC, PLOT, VISIT, CodeLine


class Code:
    """Pseudo-code lines built by key, so generators can name lines by key."""

    def __init__(self):
        self.lines: list[CodeLine] = []
        self.at: dict[str, int] = {}

    def add(self, key: str, text: str, kind: str = CALC, branch: str = "", ops=None,
            per=None, candidates=()) -> None:
        if key in self.at:
            raise ValueError(f"pseudo-code line {key!r} is defined twice")
        self.at[key] = len(self.lines)
        self.lines.append(CodeLine(text, kind, branch, tuple(candidates), ops=nonzero(ops or {}),
                                   per={k: nonzero(v) for k, v in (per or {}).items()}))

    def __len__(self) -> int:
        return len(self.lines)


def nonzero(counts: dict) -> dict:
    """Operation counts without the zero entries, equal names summed."""
    merged = {}
    for name, count in counts.items():
        if count:
            merged[name] = merged.get(name, 0) + count
    return merged


def listing(build):
    """A spec's ``code(points, options)`` from a function that builds a Code."""
    def code(points, options):
        return tuple(build(points, options).lines)
    code.__name__ = build.__name__
    return code


PLOT_PREFIX = "plot"
# Each pattern starts with a literal, so the regular expression engine
# skips to candidates instead of trying every position.
_DEFINED = re.compile(r'code\.add\(\s*"([^"]+)"')
_USED = re.compile(r'at\["([^"]*)"\]')
_NUMBER_FIRST = re.compile(r"\((?:line=)?\s*\d")  # a call or tuple that starts with a number
_FRAMES = ("yield ", "Start", "Vars", "Table", "Note", "Span")
_KEYWORD = re.compile(r"^(\w+)\s*=(?!=)")
# What matters inside a call's brackets: strings and comments (skipped
# whole), brackets and commas.
_TOKEN = re.compile(r"""("(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*'|#[^\n]*|[()\[\]{},])""")
_KINDS = {"PLOT": PLOT, "VISIT": VISIT, "CALC": CALC}


def check_family(generator, checked: set) -> None:
    """Refuse a family whose source breaks the naming convention.

    The family is the generator's module, or every module of its package
    (algorithms.family.part), since one module may name lines another adds.
    ``checked`` holds the families already done.
    """
    module = sys.modules[generator.__module__]
    package = module.__name__.count(".") > 1
    family = Path(module.__file__).parent if package else Path(module.__file__)
    if family in checked:
        return
    files = sorted(family.glob("*.py")) if package else [family]
    check_sources({str(f): f.read_text(encoding="utf-8") for f in files})
    checked.add(family)


def check_sources(sources: dict[str, str]) -> None:
    """Hold the files that build a Code to the convention; ``sources`` maps
    file names to their text. Raises ValueError at the first fault: a frame
    or record that names its line by number, an ``at["key"]`` no
    ``code.add("key", ...)`` of the family defines, or a key whose name
    (plot...) and kind (PLOT) disagree."""
    coded = {name: text for name, text in sources.items() if "Code()" in text}
    for name, text in coded.items():
        numbered = next((match for match in _NUMBER_FIRST.finditer(text)
                         if text.endswith(_FRAMES, 0, match.start())), None)
        if numbered:
            raise ValueError(f"{_where(name, text, numbered.start())}: a frame names its "
                             "pseudo-code line by number; name it code.at[\"key\"]")
    if not coded:
        return
    defined = set()
    for name, text in sources.items():
        for match in _DEFINED.finditer(text):
            key, kind = match.group(1), _kind(_arguments(text, match.end()))
            defined.add(key)
            if kind is not None and (kind == PLOT) != key.startswith(PLOT_PREFIX):
                raise ValueError(f"{_where(name, text, match.start())}: line {key!r} is of kind "
                                 f"{kind}; lines named {PLOT_PREFIX}... and only they are PLOT")
    for name, text in sources.items():
        for match in _USED.finditer(text):
            before = text[match.start() - 1]
            if before.isalnum() or before == "_":
                continue  # another name that ends in "at", such as format["x"]
            if match.group(1) not in defined:
                raise ValueError(f"{_where(name, text, match.start())}: no pseudo-code line is "
                                 f"named {match.group(1)!r}")


def _where(name: str, text: str, offset: int) -> str:
    line = text.count("\n", 0, offset) + 1
    return f"{name}:{line}"


def _kind(arguments: list[str]):
    """The kind an add() call gives its line (``arguments`` follow the key):
    PLOT, VISIT, CALC, or None when computed, as nothing can be said of it
    before a run."""
    positional, kind = [], "CALC"
    for argument in arguments:
        keyword = _KEYWORD.match(argument)
        if keyword is None:
            positional.append(argument)
        elif keyword.group(1) == "kind":
            kind = argument[keyword.end():].strip()
    if len(positional) > 1:  # (text, kind, ...)
        kind = positional[1]
    return _KINDS.get(kind)


def _arguments(text: str, i: int) -> list[str]:
    """The arguments of a call after its first, as source text, from
    ``text[i]`` (just past the first) to the call's closing bracket."""
    arguments, depth, start = [], 0, i
    for token in _TOKEN.finditer(text, i):
        mark = token.group()
        if mark in "([{":
            depth += 1
        elif mark in ")]}" and depth:
            depth -= 1
        elif mark in ",)" and not depth:
            arguments.append(text[start:token.start()].strip())
            if mark == ")":
                break
            start = token.end()
    return [argument for argument in arguments if argument]
