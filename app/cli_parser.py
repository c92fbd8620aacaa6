"""The command line's parser: argparse's, raising CommandError instead of
exiting, and keeping what it was given for the reference pages."""
from __future__ import annotations

import argparse


class CommandError(Exception):
    """Bad command-line input; the message is the one line printed."""


class Parser(argparse.ArgumentParser):
    """argparse's parser, raising CommandError instead of exiting, that keeps
    what it was given (``arguments``, ``commands``, ``summary``) so that the
    reference pages are made from it through public attributes only."""

    def __init__(self, *args, summary: str = "", **kwargs):
        self.arguments: list[argparse.Action] = []  # in the order they were added
        self.commands: dict[str, Parser] = {}
        self.summary = summary  # the one line `rasterlab --help` gives a command
        super().__init__(*args, **kwargs)

    def error(self, message):
        raise CommandError(message)

    def add_argument(self, *args, **kwargs):
        action = super().add_argument(*args, **kwargs)
        self.arguments.append(action)
        return action

    def add_mutually_exclusive_group(self, **kwargs):
        return _Recorded(super().add_mutually_exclusive_group(**kwargs), self.arguments)

    def add_command(self, commands, name: str, help: str, **kwargs) -> Parser:
        """A command of ``commands`` (what add_subparsers gave), kept in ``self.commands``."""
        command = commands.add_parser(name, help=help, summary=help, **kwargs)
        self.commands[name] = command
        return command


class _Recorded:
    """A group of mutually exclusive options whose arguments are kept with the parser's."""

    def __init__(self, group, arguments: list):
        self.group, self.arguments = group, arguments

    def add_argument(self, *args, **kwargs):
        action = self.group.add_argument(*args, **kwargs)
        self.arguments.append(action)
        return action


def add_numbers_option(parser, what: str) -> None:
    """``--numbers exact|decimal``: how ``what`` shows fractions
    (app/model/notation.py)."""
    from app.model.notation import NUMBERS
    parser.add_argument("--numbers", choices=NUMBERS, default=NUMBERS[0],
                        help=f"how {what} show numbers: decimal, or exact: every value the "
                             "algorithm keeps exactly as a fraction p/q, as the lecture notes "
                             "print them (an ET's 1/m as -5/2, Bresenham's m, barycentric "
                             "weights) (default %(default)s)")
