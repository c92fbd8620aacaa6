"""The exercise record for grading: every attempt appended to one CSV file
as it happens.

Qt-free. ``AttemptLog(path).append(row)`` adds one row of
``exercise.ATTEMPT_FIELDS`` (the header first when the file is new) and
flushes it to the disk before returning. Rows are only ever appended: an
undone answer stays, followed by its "undo" row, so the file is a trail of
what the student did rather than a state that can be rewritten.
"""
from __future__ import annotations

import csv
import os
from pathlib import Path

from app.model.escape import csv_row
from app.teaching.exercise import ATTEMPT_FIELDS

FILE_NAME = "exercise-attempts.csv"


class AttemptLog:
    def __init__(self, path: Path):
        self.path = Path(path)

    def append(self, row: list) -> None:
        """Append one attempt; raises OSError when the file cannot be written."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        with open(self.path, "a", newline="", encoding="utf-8") as out:
            writer = csv.writer(out, lineterminator="\n")
            if out.tell() == 0:
                writer.writerow(ATTEMPT_FIELDS)
            writer.writerow(csv_row(row))
            out.flush()
            os.fsync(out.fileno())
