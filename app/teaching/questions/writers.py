"""The formats a bank is written in: each name maps to ``write(bank,
path) -> list[Path]`` (the files written). ``OUTPUTS`` maps a format to
what the command checks before drawing the bank (app/model/files.py's
``Output`` list for ``path``); a format without an entry writes one file."""
from __future__ import annotations

from pathlib import Path

from app.model.files import Output
from app.teaching.questions import sheets

WRITERS = {
    "md": sheets.write_md,
    "pdf": sheets.write_pdf,
}

OUTPUTS = {
    "md": sheets.outputs,
    "pdf": sheets.outputs,
}


def outputs(fmt: str, path) -> list[Output]:
    """The outputs ``fmt`` writes at ``path``, for ``check_outputs``."""
    return OUTPUTS[fmt](path) if fmt in OUTPUTS else [Output("--out", Path(path))]
