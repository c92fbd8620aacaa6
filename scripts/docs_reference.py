"""Write the generated pages of the documentation.

    python scripts/docs_reference.py           write the pages
    python scripts/docs_reference.py --check   exit 1 and name the pages that are out of date

docs/reference/algorithms.md comes from the registry (every algorithm, its
inputs, options and oracle), docs/reference/command-line.md from the
command line's own parser (every command and option). tests/docs/test_docs.py
fails when a committed page differs from what this script writes now.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from algorithms.core import registry  # noqa: E402  (the checkout first on the path)
from app import cli  # noqa: E402

GENERATED = "<!-- Written by scripts/docs_reference.py; edit the code, not this page. -->\n"


# --------------------------------------------------------------- algorithms
def algorithms_page() -> str:
    specs = registry.all_specs()
    lines = [GENERATED, "# Algorithms", "",
             f"RasterLab has {len(specs)} algorithms in {len(registry.FAMILIES)} families. "
             "Each entry gives the name that `rasterlab run`, scene files and the window use, "
             "the points it takes, its options with their defaults, and what the tests hold "
             "its results to. Options are set with `--set NAME=VALUE` on the command line, "
             "in the *options* of a scene file, or in the window's options panel.", ""]
    for family in registry.FAMILIES:
        members = [spec for spec in specs if spec.family == family]
        lines += [f"## {family.capitalize()}", ""]
        lines += [", ".join(f"[`{spec.name}`](#{spec.name})" for spec in members), ""]
        for spec in members:
            lines += _algorithm(spec)
    return "\n".join(lines).rstrip("\n") + "\n"


def _algorithm(spec) -> list[str]:
    lines = [f"### {spec.name}", "", f"**{_text(spec.title)}**: {_text(spec.summary)}.", "",
             f"- Takes: {_inputs(spec.inputs)}."]
    if spec.kernel is not None:
        lines.append("- Has a fast kernel, which gives the same pixels without recording steps.")
    if spec.oracle is not None:
        lines.append(f"- Tested against ({spec.oracle.kind}): {_text(spec.oracle.about)}")
    lines.append("")
    if spec.options:
        lines += ["| option | type | default | values | meaning |", "| --- | --- | --- | --- | --- |"]
        lines += [_option_row(option) for option in spec.options]
    else:
        lines.append("No options.")
    return lines + [""]


def _inputs(inputs) -> str:
    integer = "whole-number" if inputs.integer else "real"
    names = f" ({', '.join(inputs.names)})" if inputs.names and not inputs.multiple else ""
    if inputs.contours:
        return (f"one or more contours of at least {inputs.count} {integer} points each, "
                "one `--points` list per contour")
    if inputs.multiple:
        return f"{inputs.count}k {integer} points, {inputs.count} for each of k primitives"
    plural = "s" if inputs.count != 1 else ""
    return f"{inputs.count} {integer} point{plural}{names}"


def _option_row(option) -> str:
    return (f"| `{option.name}` | {option.kind} | {_code(_default(option.default))} | "
            f"{_values(option)} | {_text(option.help)} |")


def _default(value) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (tuple, list)):
        return ",".join(map(str, value)) or "none"
    return str(value)


def _values(option) -> str:
    parts = []
    if option.choices:
        parts.append(", ".join(_code(choice) for choice in option.choices))
    if option.minimum is not None or option.maximum is not None:
        low = "" if option.minimum is None else registry.format_value(option.minimum)
        high = "" if option.maximum is None else registry.format_value(option.maximum)
        parts.append(f"{low} .. {high}".strip())
    return "; ".join(parts)


def _code(text: str) -> str:
    return f"`{text}`" if text else ""


_ESCAPES = {"\\": "\\\\", "*": "\\*", "_": "\\_", "[": "\\[", "]": "\\]",
            "|": "\\|", "<": "&lt;", ">": "&gt;"}


def _text(text: str) -> str:
    """Plain text as Markdown shows it literally (also inside a table cell);
    `code` stays code."""
    return "".join(_ESCAPES.get(char, char) for char in " ".join(text.split()))


# ------------------------------------------------------------- command line
# Made from the arguments the parser was given (app/cli_parser.py keeps them)
# rather than argparse's --help text, whose layout changes between Python
# versions.
def command_line_page() -> str:
    parser = cli.build_parser()
    commands = _commands(parser)
    lines = [GENERATED, "# Command line", "", _text(parser.description), "",
             "`python -m rasterlab` is the same command. Bad input of any kind ends with "
             "exit status 2 and one line on stderr. Every command takes `--help`.", "",
             "| command | what it does |", "| --- | --- |"]
    lines += [f"| [`rasterlab {name}`](#rasterlab-{name}) | {_text(about)} |"
              for name, (about, _) in commands.items()]
    lines += ["", "`rasterlab --version` prints the version.", ""]
    for name, (about, command) in commands.items():
        lines += [f"## rasterlab {name}", "", _sentence(command.description or about), "",
                  f"`{_synopsis(name, command)}`", "",
                  "| argument | meaning |", "| --- | --- |"]
        lines += [_argument_row(action) for action in _arguments(command)]
        lines.append("")
    return "\n".join(lines).rstrip("\n") + "\n"


def _commands(parser) -> dict:
    """Each command's name: (one-line help, its parser)."""
    return {name: (command.summary, command) for name, command in parser.commands.items()}


def _arguments(command) -> list:
    """The command's arguments as it was given them (app/cli_parser.py keeps them), --help aside."""
    return [action for action in command.arguments if action.dest != "help"]


def _synopsis(name: str, command) -> str:
    words = [f"rasterlab {name}"]
    for action in _arguments(command):
        if not action.option_strings:
            word = action.metavar or action.dest
            words.append(f"[{word}]" if action.nargs == "?" else word)
        elif action.required:
            words.append(f"{action.option_strings[0]} {action.metavar}")
    return " ".join(words) + " [options]"


def _argument_row(action) -> str:
    if action.option_strings:
        flags = ", ".join(action.option_strings)
        value = "" if action.nargs == 0 else f" {_value_name(action)}"
        name = f"`{flags}{value}`"
    else:
        name = f"`{action.metavar or action.dest}`"
    return f"| {name} | {_text(_help_text(action))} |"


def _sentence(text: str) -> str:
    text = _text(text).rstrip(".")
    return text[:1].upper() + text[1:] + "."


def _value_name(action) -> str:
    if action.metavar is not None:
        return action.metavar + (f" [{action.metavar} ...]" if action.nargs == "+" else "")
    if action.choices is not None:
        return "{" + ",".join(map(str, action.choices)) + "}"
    return action.dest.upper()


def _help_text(action) -> str:
    """The help with its %(default)s and the like filled in, as --help shows it."""
    params = {key: value for key, value in vars(action).items() if value is not argparse.SUPPRESS}
    if action.choices is not None:
        params["choices"] = ", ".join(map(str, action.choices))
    return (action.help or "") % params


# --------------------------------------------------------------------- main
PAGES = {"docs/reference/algorithms.md": algorithms_page,
         "docs/reference/command-line.md": command_line_page}


def pages() -> dict[str, str]:
    """Each generated page's path (from the checkout) and its text now."""
    return {path: make() for path, make in PAGES.items()}


def main(argv: list[str] | None = None) -> int:
    check = "--check" in (sys.argv[1:] if argv is None else argv)
    stale = []
    for path, text in pages().items():
        target = ROOT / path
        current = target.read_text(encoding="utf-8") if target.is_file() else None
        if current == text:
            continue
        stale.append(path)
        if not check:
            target.write_text(text, encoding="utf-8", newline="\n")
    for path in stale:
        print(f"{path}: {'out of date' if check else 'written'}")
    return 1 if check and stale else 0


if __name__ == "__main__":
    sys.exit(main())
