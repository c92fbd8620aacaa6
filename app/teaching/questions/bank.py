"""Drawing a bank: ``count`` variants of each template, each with a seed of
its own derived from the bank's seed (or, per student, from the student's
id), all different from one another.

Seeds are derived with SHA-256, never Python's ``hash()`` (which changes
from one process to the next), so the same seed or id gives the same
questions on every machine.
"""
from __future__ import annotations

import csv
import dataclasses
import hashlib
from pathlib import Path

from app.teaching.questions import registry
from app.teaching.questions.model import Bank, Question

MAX_COUNT = 500
MAX_REDRAWS = 50  # redraws of one variant whose question repeats an earlier one
ID_COLUMNS = ("id", "student", "email")
MAX_STUDENTS = 5000


def derived_seed(*parts) -> int:
    """A 63-bit seed from ``parts`` (joined as text), the same everywhere."""
    text = "\x1f".join(str(part) for part in parts)
    return int.from_bytes(hashlib.sha256(text.encode("utf-8")).digest()[:8], "big") >> 1


def check_count(count: int) -> int:
    if not 1 <= count <= MAX_COUNT:
        raise ValueError(f"--count {count}: give 1 .. {MAX_COUNT} variants per template")
    return count


def group(names, count: int, seed, scene=None, progress=None) -> tuple[Question, ...]:
    """``count`` distinct variants of each template of ``names``, in order,
    titled "<title> (#n)"; with ``scene``, all about that scene's inputs.
    ``progress()`` is called after each question when given."""
    check_count(count)
    templates = [registry.get(name) for name in names]
    questions: list[Question] = []
    seen: set[str] = set()
    for template in templates:
        for n in range(1, count + 1):
            question = _distinct(template, seed, n, seen, scene)
            seen.add(question.text)
            questions.append(dataclasses.replace(question, title=f"{question.title} (#{n})"))
            if progress is not None:
                progress()
    return tuple(questions)


def _distinct(template, seed, n: int, seen: set, scene) -> Question:
    for attempt in range(MAX_REDRAWS):
        question = template.make(derived_seed(seed, template.name, n, attempt), scene)
        if question.text not in seen:
            return question
    raise ValueError(f"{template.name}: no new variant after {MAX_REDRAWS} draws for variant "
                     f"{n}; ask for fewer (--count)")


def draw(names, count: int, seed: int, scene=None, progress=None) -> Bank:
    """One group of ``count`` variants of each template, from ``seed``
    (about ``scene``'s inputs when given)."""
    return Bank(groups=(("", group(names, count, seed, scene, progress)),), seed=seed)


def per_student(names, count: int, ids, seed: int = 0, scene=None, progress=None) -> Bank:
    """A group for each student id, its seeds derived from the id (and ``seed``)."""
    ids = list(dict.fromkeys(ids))
    if not ids:
        raise ValueError("no student ids given")
    return Bank(groups=tuple((sid, group(names, count, f"{seed}\x1e{sid}", scene, progress))
                             for sid in ids),
                seed=seed)


def read_ids(path) -> list[str]:
    """The student ids of a CSV file: the column named id, student or email
    (the first such heading), else the first column; ValueError (one line)
    for a file that cannot be read or holds no id."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
        rows = [row for row in csv.reader(text.splitlines()) if any(cell.strip() for cell in row)]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise ValueError(f"--per-student {path}: cannot be read as a UTF-8 CSV file "
                         f"({getattr(error, 'strerror', None) or error})") from None
    if not rows:
        raise ValueError(f"--per-student {path}: holds no student id")
    heading = [cell.strip().lower() for cell in rows[0]]
    named = next((heading.index(name) for name in ID_COLUMNS if name in heading), None)
    column, body = (named, rows[1:]) if named is not None else (0, rows)
    ids = [row[column].strip() for row in body if len(row) > column and row[column].strip()]
    if not ids:
        raise ValueError(f"--per-student {path}: holds no student id")
    if len(ids) > MAX_STUDENTS:
        raise ValueError(f"--per-student {path}: {len(ids)} ids; at most {MAX_STUDENTS}")
    return list(dict.fromkeys(ids))
