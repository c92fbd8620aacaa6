"""What every quiz-tool writer shares: the same bank gives the same bytes
(no time of writing anywhere), the files written are the ones returned, and
each write goes through the output policy of app/model/files.py: a file
RasterLab did not write is replaced only with force, and no half-written
or temporary file is left."""
from __future__ import annotations

from pathlib import Path

import pytest

from app.model.files import OutputRefused
from app.teaching.questions import gift, moodle, prairielearn, qti
from tests.support import question_bank as qb

WRITERS = {"moodle": (moodle, "bank.xml"), "qti": (qti, "bank.zip"),
           "gift": (gift, "bank.gift.txt"), "prairielearn": (prairielearn, "course")}


def contents(root: Path) -> dict[str, bytes]:
    if root.is_file():
        return {root.name: root.read_bytes()}
    return {str(path.relative_to(root)): path.read_bytes()
            for path in sorted(root.rglob("*")) if path.is_file()}


@pytest.mark.parametrize("name", sorted(WRITERS))
def test_the_same_bank_gives_the_same_bytes(tmp_path, name):
    writer, target = WRITERS[name]
    first, second = tmp_path / "a" / target, tmp_path / "b" / target
    for path in (first, second):
        path.parent.mkdir()
        written = writer.write(qb.bank(), path)
        assert written and all(Path(file).is_file() for file in written)
    assert contents(first) == contents(second)
    writer.write(qb.bank(), first)  # written again over its own files, without force
    assert contents(first) == contents(second)
    if name != "prairielearn":  # PrairieLearn draws its own variants: no seed there
        other = tmp_path / "c" / target
        other.parent.mkdir()
        writer.write(qb.bank(seed=8), other)
        assert contents(other) != contents(first)  # the seed is stated


@pytest.mark.parametrize("name", sorted(WRITERS))
def test_a_file_rasterlab_did_not_write_is_kept_without_force(tmp_path, name):
    writer, target = WRITERS[name]
    path = tmp_path / target
    foreign = path / "questions" / "line-step-choice" / "server.py" if name == "prairielearn" \
        else path
    foreign.parent.mkdir(parents=True, exist_ok=True)
    foreign.write_bytes(b"my own notes\n")
    with pytest.raises(OutputRefused, match="give --force to replace it"):
        writer.write(qb.bank(), path)
    assert foreign.read_bytes() == b"my own notes\n"
    writer.write(qb.bank(), path, force=True)
    assert foreign.read_bytes() != b"my own notes\n"
    leftovers = [p.name for p in tmp_path.rglob("*") if p.name.endswith(".tmp")
                 or p.name.startswith(".rasterlab-prairielearn-")]
    assert leftovers == []


@pytest.mark.parametrize("name", sorted(WRITERS))
def test_a_folder_where_the_file_goes_is_refused(tmp_path, name):
    writer, target = WRITERS[name]
    path = tmp_path / target
    if name == "prairielearn":
        path.write_text("", encoding="utf-8")  # a file where the course folder goes
    else:
        path.mkdir()
    with pytest.raises(OutputRefused):
        writer.write(qb.bank(), path)
