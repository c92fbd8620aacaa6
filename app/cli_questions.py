"""`rasterlab questions`: a question bank drawn from templates with a seed
(or per student), written as an LMS import or paper sheets with a key."""
from __future__ import annotations

import itertools
from pathlib import Path

from algorithms.core.registry import InputError
from app.model.files import check_outputs

MAX_SEED = 2 ** 63 - 1


def add_questions_command(parser, commands) -> None:
    from app.teaching.questions.writers import WRITERS
    questions = parser.add_command(
        commands, "questions", help="write a question bank: seeded variants with answer keys",
        description="Draw COUNT variants of each TEMPLATE (`rasterlab questions --list`), "
                    "each with its inputs from a seed and its answer computed by the "
                    "algorithm, and write them as FORMAT to --out. The same seed gives the "
                    "same files byte for byte; --per-student gives each id of a CSV file "
                    "its own variants.")
    questions.add_argument("templates", nargs="*", metavar="TEMPLATE",
                           help="template names, as --list shows them")
    questions.add_argument("--list", action="store_true",
                           help="list the templates (name, family, title) and stop")
    questions.add_argument("--count", default="1", metavar="N",
                           help="variants of each template, 1 .. 500 (default %(default)s)")
    questions.add_argument("--seed", default="0", metavar="S",
                           help=f"the bank's seed, 0 .. {MAX_SEED} (default %(default)s)")
    questions.add_argument("--format", choices=sorted(WRITERS), metavar="FORMAT",
                           help=f"one of {', '.join(sorted(WRITERS))}")
    questions.add_argument("--out", metavar="PATH", help="the file or folder to write")
    questions.add_argument("--per-student", metavar="IDS.csv",
                           help="one group of variants per student id: the column id, "
                                "student or email, else the first column")
    questions.add_argument("--scene", metavar="SCENE",
                           help="ask about this scene's inputs (a file or a shipped scene's "
                                "name); the seed then picks only the step or the pixel")
    questions.add_argument("--force", action="store_true",
                           help="replace files RasterLab did not write")


def _whole(text: str, option: str, low: int, high: int) -> int:
    try:
        value = int(text.strip())
    except ValueError:
        raise InputError(f"{option} {text!r}: not a whole number") from None
    if not low <= value <= high:
        raise InputError(f"{option} {value}: give {low} .. {high}")
    return value


def command_questions(args) -> int:
    from app import progress
    from app.model import scene as scenes
    from app.teaching.questions import bank, registry, writers
    if args.list:
        width = max(len(name) for name in registry.TEMPLATES)
        for template in registry.TEMPLATES.values():
            print(f"{template.name:{width}}  {template.family:10}  {template.title}")
        return 0
    if not args.templates:
        raise InputError("name one or more templates (`rasterlab questions --list`)")
    if args.format is None or args.out is None:
        raise InputError("give --format and --out")
    count = _whole(args.count, "--count", 1, bank.MAX_COUNT)
    seed = _whole(args.seed, "--seed", 0, MAX_SEED)
    try:
        for name in args.templates:
            registry.get(name)
        ids = bank.read_ids(args.per_student) if args.per_student else None
        scene_path = _scene_path(args.scene)
        check_outputs(writers.outputs(args.format, args.out),
                      [args.per_student, scene_path], force=args.force)
        scene = scenes.load(scene_path) if scene_path is not None else None
        total = count * len(args.templates) * (len(ids) if ids is not None else 1)
        with progress.drawn(progress.CountBar("drawing", "questions, about")) as bar:
            done = itertools.count(1)
            tick = (lambda: bar(next(done), total)) if bar is not None else None
            drawn = (bank.per_student(args.templates, count, ids, seed, scene, tick)
                     if ids is not None else bank.draw(args.templates, count, seed, scene, tick))
    except ValueError as error:  # OutputRefused is one too
        raise InputError(str(error)) from None
    try:
        files = writers.WRITERS[args.format](drawn, Path(args.out), force=args.force)
    except ValueError as error:  # refused now (the path changed meanwhile), or unfit for it
        raise InputError(str(error)) from None
    total = sum(len(questions) for _, questions in drawn.groups)
    print(f"{args.out}: {total} questions in {len(drawn.groups)} group(s), "
          f"{len(files)} file(s) ({args.format}, seed {seed})")
    return 0


def _scene_path(text: str | None):
    """The file --scene names (a path or a shipped scene's name), or None."""
    from app.model import shipped
    return shipped.scene_path(text) if text is not None else None
