"""`rasterlab run --describe`: the run's steps in words, one a line (the
descriptions a screen reader hears in the window: app/model/step_words.py)."""
from __future__ import annotations

import sys

from app.cli_parser import CommandError


def add_describe_option(run) -> None:
    run.add_argument("--describe", action="store_true",
                     help="print each step in words, one a line (\"step 2 of 7: d = -1, at most "
                          "0, so E: plot (1, 0)\"): a transcript of the run")


def check_describe(args) -> None:
    """--describe prints lines of its own: refuse it with another output."""
    if args.describe and (args.steps or args.json or args.ascii or args.csv):
        raise CommandError("--describe prints the steps in words: use it without --steps, "
                           "--json, --ascii or --csv")


def print_descriptions(args, trace) -> int:
    from app.model.step_words import describe
    for index in range(len(trace)):
        sys.stdout.write(describe(trace, index, args.numbers) + "\n")
    return 0
