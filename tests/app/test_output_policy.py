"""The output policy every writer follows (app/model/files.py): nothing an
export, check, run --save or worksheet writes destroys a file it should
not touch; what is refused gets one line and exit status 2, before any work.
Also: no file name makes the output streams raise, and a worksheet PDF that
cannot be written ends in one line."""
import json
import os
import shutil
import subprocess
import sys
from dataclasses import replace

import pytest

from app.model import scene as scenes
from app.model import shipped
from app.model import files
from tests.support import ROOT

GIF = b"GIF89a"


def _one_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.json"
    shutil.copyfile(shipped.scene_path("demo-bresenham"), path)
    return path


def _refused(run_cli, *argv) -> str:
    status, out, err = run_cli(*argv)
    assert status == 2 and out == "", (status, out, err)
    return _one_line(err)


# ------------------------------------------------------- inputs and outputs
@pytest.mark.parametrize("option", ["--gif", "--html", "--pdf", "--mp4"])
def test_an_export_over_its_own_scene_is_refused(run_cli, scene_file, option):
    before = scene_file.read_bytes()
    line = _refused(run_cli, "export", scene_file, option, scene_file)
    assert "is the input" in line
    assert scene_file.read_bytes() == before


def test_an_export_over_its_scene_through_a_link_is_refused(run_cli, scene_file, tmp_path):
    link = tmp_path / "link.gif"
    link.symlink_to(scene_file)
    before = scene_file.read_bytes()
    assert "is the input" in _refused(run_cli, "export", scene_file, "--gif", link)
    assert scene_file.read_bytes() == before and link.is_symlink()


def test_two_outputs_of_one_name_are_refused(run_cli, scene_file, tmp_path):
    line = _refused(run_cli, "export", scene_file, "--gif", tmp_path / "a.gif",
                    "--mp4", tmp_path / "a.gif")
    assert "also the output of --gif" in line
    assert not (tmp_path / "a.gif").exists()


def test_frames_and_svg_in_one_folder_are_refused(run_cli, scene_file, tmp_path):
    line = _refused(run_cli, "export", scene_file, "--frames-dir", tmp_path / "f",
                    "--svg-dir", tmp_path / "f")
    assert "also the output of --frames-dir" in line


def test_the_junit_report_never_replaces_the_submission(run_cli, tmp_path):
    submission = tmp_path / "sub.py"
    shutil.copyfile(shipped.templates()["line"], submission)
    before = submission.read_bytes()
    line = _refused(run_cli, "check", submission, "--against", "line-bresenham",
                    "--junit", submission)
    assert "is the input" in line
    assert submission.read_bytes() == before


def test_run_save_never_replaces_the_scene_it_runs(run_cli, scene_file):
    before = scene_file.read_bytes()
    line = _refused(run_cli, "run", "--scene", scene_file, "--save", scene_file, "--force")
    assert "is the input" in line
    assert scene_file.read_bytes() == before


def test_a_hard_link_of_an_input_is_the_input(tmp_path):
    source = tmp_path / "in.json"
    source.write_text("{}")
    os.link(source, tmp_path / "same.gif")
    with pytest.raises(files.OutputRefused, match="is the input"):
        files.check_outputs([files.Output("--gif", tmp_path / "same.gif")], [source])


# -------------------------------------------------- files the program did not write
def test_a_file_of_another_format_is_kept_unless_forced(run_cli, scene_file, tmp_path):
    notes = tmp_path / "notes.gif"
    notes.write_text("my notes")
    line = _refused(run_cli, "export", scene_file, "--gif", notes)
    assert "is not a GIF file RasterLab wrote" in line and "--force" in line
    assert notes.read_text() == "my notes"
    status, _, err = run_cli("export", scene_file, "--gif", notes, "--force")
    assert status == 0, err
    assert notes.read_bytes().startswith(GIF)


def test_a_gif_is_replaced_by_the_next_export(run_cli, scene_file, tmp_path):
    out = tmp_path / "a.gif"
    for _ in range(2):
        status, _, err = run_cli("export", scene_file, "--gif", out)
        assert status == 0, err


def test_a_users_frame_is_kept(run_cli, scene_file, tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / "frame_0001.png").write_bytes(b"my own drawing")
    line = _refused(run_cli, "export", scene_file, "--frames-dir", folder)
    assert "frame_0001.png was not written by RasterLab" in line
    assert (folder / "frame_0001.png").read_bytes() == b"my own drawing"
    assert sorted(p.name for p in folder.iterdir()) == ["frame_0001.png"]


@pytest.mark.parametrize("option, suffix", [("frames_dir", ".png"), ("svg_dir", ".svg")])
def test_a_users_frame_is_found_before_the_run_is_recorded(tmp_path, option, suffix):
    # The check every export makes before recording (formats.check) knows no
    # frame count yet; it must still find the user's frame, so a long
    # recording is not thrown away at the end.
    from app.render import formats
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / f"frame_0003{suffix}").write_bytes(b"my own drawing")
    scene = scenes.load(shipped.scene_path("demo-bresenham"))
    with pytest.raises(files.OutputRefused, match="frame_0003.* was not written by RasterLab"):
        formats.check(formats.Outputs(**{option: str(folder)}), scene)
    formats.check(formats.Outputs(**{option: str(folder)}, force=True), scene)


def test_frames_replace_the_frames_of_an_earlier_export(run_cli, scene_file, tmp_path):
    folder = tmp_path / "frames"
    for _ in range(2):
        status, _, err = run_cli("export", scene_file, "--frames-dir", folder)
        assert status == 0, err
    assert (folder / "frame_0000.png").read_bytes().startswith(b"\x89PNG")


def test_force_replaces_a_users_frame(run_cli, scene_file, tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    (folder / "frame_0001.png").write_bytes(b"my own drawing")
    status, _, err = run_cli("export", scene_file, "--frames-dir", folder, "--force")
    assert status == 0, err
    assert (folder / "frame_0001.png").read_bytes().startswith(b"\x89PNG")


# ---------------------------------------------------- devices, FIFOs, folders
@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="os.mkfifo: POSIX only")
@pytest.mark.parametrize("option", ["--gif", "--html", "--pdf"])
def test_a_fifo_is_never_written(run_cli, scene_file, tmp_path, option):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    line = _refused(run_cli, "export", scene_file, option, fifo)
    assert "is a FIFO" in line
    assert os.path.exists(fifo) and not fifo.is_file()


@pytest.mark.skipif(not os.path.exists("/dev/null"), reason="no /dev/null on this system")
def test_a_device_is_never_written(run_cli, scene_file, tmp_path):
    # Only through a link: code without the policy would replace the link,
    # never the device (naming /dev/null itself, it would replace the
    # device when run as root).
    link = tmp_path / "null.gif"
    link.symlink_to("/dev/null")
    assert "is a device" in _refused(run_cli, "export", scene_file, "--gif", link)
    assert link.is_symlink()
    with pytest.raises(files.OutputRefused, match="is a device"):
        files.check_outputs([files.Output("--gif", "/dev/null")])


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="os.mkfifo: POSIX only")
def test_a_fifo_among_the_frames_is_refused_even_with_force(run_cli, scene_file, tmp_path):
    folder = tmp_path / "frames"
    folder.mkdir()
    os.mkfifo(folder / "frame_0000.png")
    line = _refused(run_cli, "export", scene_file, "--frames-dir", folder, "--force")
    assert "not a regular file" in line


def test_a_folder_where_a_file_goes_is_refused(run_cli, scene_file, tmp_path):
    (tmp_path / "out.gif").mkdir()
    assert "is a folder" in _refused(run_cli, "export", scene_file, "--gif", tmp_path / "out.gif")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="os.mkfifo: POSIX only")
def test_write_atomically_refuses_a_fifo(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(OSError, match="is a FIFO"):
        files.write_atomically(fifo, b"data")
    assert not fifo.is_file()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="os.mkfifo: POSIX only")
def test_a_scene_is_never_saved_over_a_fifo(run_cli, tmp_path):
    fifo = tmp_path / "scene.json"
    os.mkfifo(fifo)
    line = _refused(run_cli, "run", "line-bresenham", "--points", "0,0", "5,2", "--save", fifo)
    assert "is a FIFO" in line


# ------------------------------------------------------------ symbolic links
# Decided once: a file's output written through a link reaches its target
# and the link stays, for every single-file writer.
@pytest.mark.parametrize("option, mark", [("--gif", GIF), ("--html", b"<!DOCTYPE html"),
                                          ("--pdf", b"%PDF-"), ("--mp4", b"ftyp")])
def test_a_link_is_written_through_and_stays(run_cli, scene_file, tmp_path, option, mark):
    target = tmp_path / "real"
    link = tmp_path / "link"
    link.symlink_to(target)
    status, _, err = run_cli("export", scene_file, option, link)
    assert status == 0, err
    assert link.is_symlink() and target.is_file()
    assert mark in target.read_bytes()[:16]


def test_frames_go_through_a_linked_folder(run_cli, scene_file, tmp_path):
    (tmp_path / "real").mkdir()
    (tmp_path / "link").symlink_to(tmp_path / "real", target_is_directory=True)
    status, _, err = run_cli("export", scene_file, "--frames-dir", tmp_path / "link")
    assert status == 0, err
    assert (tmp_path / "link").is_symlink()
    assert (tmp_path / "real" / "frame_0000.png").is_file()


# ---------------------------------------------------------- save and open agree
def _bookmarked(count: int) -> scenes.Scene:
    scene = scenes.load(shipped.scene_path("demo-bresenham"))
    return replace(scene, bookmarks=[{"name": f"b{k}", "step": 0} for k in range(count)])


def test_a_scene_opened_from_a_compact_file_saves_as_one_that_opens(tmp_path):
    scene = _bookmarked(200_000)
    compact = tmp_path / "compact.json"
    compact.write_text(json.dumps(scene.to_json(), separators=(",", ":")))
    indented = len(json.dumps(scene.to_json(), indent=2).encode())
    assert compact.stat().st_size <= scenes.MAX_FILE_BYTES < indented  # the case of the issue
    saved = tmp_path / "saved.json"
    scenes.save(scenes.load(compact), saved)
    assert saved.stat().st_size <= scenes.MAX_FILE_BYTES
    assert len(scenes.load(saved).bookmarks) == 200_000


def test_a_scene_too_large_to_open_is_not_saved(tmp_path):
    scene = replace(_bookmarked(1), description="x" * (scenes.MAX_FILE_BYTES + 1))
    saved = tmp_path / "scene.json"
    saved.write_text("old")
    with pytest.raises(scenes.SceneError, match="not saved"):
        scenes.save(scene, saved)
    assert saved.read_text() == "old"


def test_a_small_scene_is_saved_indented(tmp_path):
    saved = tmp_path / "scene.json"
    scenes.save(_bookmarked(2), saved)
    assert saved.read_text().startswith("{\n  ")


# ------------------------------------------------------------------ messages
@pytest.mark.skipif(sys.platform == "win32", reason="names are UTF-16 there: every name encodes")
def test_a_name_that_is_not_utf8_prints_on_a_strict_utf8_stdout(tmp_path):
    name = os.fsencode(tmp_path) + b"/\xff.gif"
    env = {"PATH": os.environ.get("PATH", ""), "PYTHONPATH": str(ROOT),
           "LC_ALL": "C.UTF-8", "PYTHONIOENCODING": "utf-8:strict"}
    done = subprocess.run([sys.executable, "-m", "rasterlab", "export", "demo-bresenham",
                           "--gif", name], cwd=ROOT, env=env, capture_output=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert b"Traceback" not in done.stderr
    assert b"\\udcff.gif" in done.stdout
    assert os.path.isfile(name)


@pytest.mark.skipif(sys.platform == "win32" or os.geteuid() == 0,
                    reason="a folder no one may write into needs POSIX permissions and no root")
def test_a_worksheet_pdf_that_cannot_be_written_is_one_line(tmp_path):
    out = tmp_path / "read-only"
    out.mkdir()
    out.chmod(0o500)
    try:
        done = subprocess.run([sys.executable, "-m", "rasterlab", "worksheet",
                               "demo-bresenham", "--out", out], cwd=ROOT,
                              capture_output=True, text=True, timeout=120)
    finally:
        out.chmod(0o700)
    assert done.returncode == 2
    line = _one_line(done.stderr)  # not Qt's QPainter warnings
    assert line.startswith("rasterlab: ") and str(out) in line
    assert list(out.iterdir()) == []


def test_a_worksheet_pdf_that_fails_leaves_no_folder(tmp_path, monkeypatch):
    from app.teaching import worksheet

    def failing(sheet, path, answers):
        raise OSError(f"{path}: cannot write the file (Permission denied)")
    sheet = worksheet.build(scenes.load(shipped.scene_path("demo-bresenham")),
                            None)
    with pytest.raises(OSError):
        worksheet.write(sheet, tmp_path / "a" / "b", "pdf", failing)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(sys.platform == "win32", reason="RLIMIT_FSIZE: POSIX only")
def test_a_worksheet_pdf_over_the_file_size_limit_is_one_line_and_no_folder(tmp_path):
    # A write the system refuses whoever runs it (root included): files are
    # limited to 4 KB, less than a worksheet's PDF.
    import resource

    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
    done = subprocess.run([sys.executable, "-m", "rasterlab", "worksheet", "demo-bresenham",
                           "--out", tmp_path / "new" / "sheet"], cwd=ROOT, capture_output=True,
                          text=True, timeout=120, preexec_fn=small_files)
    assert done.returncode == 2
    assert _one_line(done.stderr).startswith("rasterlab: ")
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------- folders written together: report, worksheet
class _NoRows:
    rows = []


def _no_measuring(monkeypatch):
    """The report is written from no rows: the measuring is not what is tested."""
    from app.analysis import measure
    monkeypatch.setattr(measure, "run", lambda config, progress=None: (_NoRows, {}))


def _measuring_refused(monkeypatch):
    """A refusal must come before any measuring: measuring fails the test."""
    from app.analysis import measure

    def never(config, progress=None):
        raise AssertionError("the report measured before its outputs were checked")
    monkeypatch.setattr(measure, "run", never)


def test_a_report_keeps_a_users_file_before_any_measuring(run_cli, tmp_path, monkeypatch):
    out = tmp_path / "out"
    out.mkdir()
    (out / "report.md").write_text("my own notes\n")
    _measuring_refused(monkeypatch)
    err = _refused(run_cli, "report", "--quick", "--out", out)
    assert "report.md" in err and "--force" in err
    assert (out / "report.md").read_text() == "my own notes\n"
    _no_measuring(monkeypatch)
    status, _, err = run_cli("report", "--quick", "--out", out, "--force")
    assert status == 0, err
    assert (out / "report.md").read_text() != "my own notes\n"


def test_a_report_replaces_its_own_files(run_cli, tmp_path, monkeypatch):
    out = tmp_path / "out"
    _no_measuring(monkeypatch)
    for _ in range(2):
        status, _, err = run_cli("report", "--quick", "--out", out)
        assert status == 0, err
    assert json.loads((out / ".rasterlab-report.json").read_text()) == sorted(
        ["report.md", "measurements.csv", "measurements.json"])


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are a POSIX facility")
def test_a_fifo_in_the_report_folder_is_refused_before_any_measuring(run_cli, tmp_path,
                                                                      monkeypatch):
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / "measurements.csv")
    _measuring_refused(monkeypatch)
    err = _refused(run_cli, "report", "--quick", "--out", out, "--force")
    assert "measurements.csv" in err


def test_a_worksheet_keeps_a_users_file_unless_forced(run_cli, scene_file, tmp_path):
    out = tmp_path / "sheet"
    out.mkdir()
    (out / "answers.csv").write_text("my answers\n")
    err = _refused(run_cli, "worksheet", scene_file, "--out", out, "--format", "csv")
    assert "answers.csv" in err and "--force" in err
    assert (out / "answers.csv").read_text() == "my answers\n"
    status, _, err = run_cli("worksheet", scene_file, "--out", out, "--format", "csv",
                             "--force")
    assert status == 0, err
    assert (out / "answers.csv").read_text() != "my answers\n"
    status, _, err = run_cli("worksheet", scene_file, "--out", out, "--format", "csv")
    assert status == 0, err  # its own files, as the folder's manifest lists them
