"""The formats a bank is written in, one protocol for all: each name maps
to ``outputs(bank, path)`` (the app/model/files.py ``Output``
list the policy checks) and ``write(bank, path, force=False) -> list[Path]``
(the files written, whole or not at all; OutputRefused, one line, when the
policy refuses one). The command checks ``outputs`` with an empty bank
before drawing, so a refused path costs no drawing."""
from __future__ import annotations

from app.model.files import Output
from app.teaching.questions import gift, moodle, prairielearn, qti, sheets
from app.teaching.questions.model import Bank

FORMATS = {  # name -> (outputs, write)
    "moodle-xml": (moodle.outputs, moodle.write),
    "qti": (qti.outputs, qti.write),
    "gift": (gift.outputs, gift.write),
    "prairielearn": (prairielearn.outputs, prairielearn.write),
    "pdf": (sheets.outputs, sheets.write_pdf),
    "md": (sheets.outputs, sheets.write_md),
}
WRITERS = {name: write for name, (_, write) in FORMATS.items()}


def outputs(fmt: str, path) -> list[Output]:
    """The outputs ``fmt`` writes at ``path`` whatever the bank holds, for
    ``check_outputs`` before the bank is drawn."""
    return FORMATS[fmt][0](Bank(groups=(), seed=0), path)
