"""The export's further formats, as the command line asks for them: video
(MP4, WebM), vector frames (an SVG folder, a PDF), a Beamer snippet, and
the transcripts beside a GIF or a video (``app/render/transcript.py``).
Each is a writer of the export's one writer protocol (``app.render.writers``),
so every format gets the same frames, range, timing and look."""
from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path
from typing import NamedTuple

from app.model.escape import latex_file_name
from app.model.files import Output, check_outputs, not_ours, write_atomically
from app.render import transcript
from app.render.settings import ExportError
from app.render.writers import foreign_frames


class Outputs(NamedTuple):
    """Where an export goes: any of these paths (None: not that format)."""

    gif: str | None = None
    frames_dir: str | None = None
    mp4: str | None = None
    webm: str | None = None
    svg_dir: str | None = None
    pdf: str | None = None
    beamer: str | None = None
    html: str | None = None
    # Replace files RasterLab did not write, and write a page over its size budget.
    force: bool = False
    # The steps in words beside a GIF (NAME.txt) and a video (NAME.vtt).
    transcript: bool = True


def check(args, scene, scene_path=None) -> None:
    """The output policy (``app.model.files.check_outputs``) for the outputs
    ``args`` names, the scene file ``scene_path`` and a texture file the
    scene reads being the inputs; OutputRefused before any work."""
    files = [("--gif", args.gif, "gif"), ("--mp4", args.mp4, "mp4"),
             ("--webm", args.webm, "webm"), ("--pdf", args.pdf, "pdf"),
             ("--beamer", args.beamer, "tex"), ("--html", args.html, "html")]
    folders = [("--frames-dir", args.frames_dir, ".png"), ("--svg-dir", args.svg_dir, ".svg")]
    outputs = [Output(option, path, foreign=not_ours(kind)) for option, path, kind in files] \
        + [Output(option, path, folder=True, foreign=foreign_frames(suffix))
           for option, path, suffix in folders]
    if args.transcript:
        outputs += transcript.outputs(args.gif, args.mp4, args.webm)
    texture = scene.options.get("texture")
    texture = texture if isinstance(texture, str) and os.path.isfile(texture) else None
    check_outputs(outputs, [scene_path, texture], args.force)


def export_all(args, scene, settings, frames_limit: int, progress=None, cancelled=None,
               trace=None, differences=None, names=("--from", "--to")):
    """Every output ``args`` (Outputs, or the command line's arguments) asks
    for: the frames (GIF, PNG, video, vector, Beamer) in one pass, then the
    page; (ExportResult or None, Page or None). An animation that would flash
    more than three times a second is slowed (``app.render.flash_guard``),
    and its summary line says so."""
    from app.render import export as exporting
    from app.render.flash_guard import flash_safe

    result = None
    frame_outputs = (args.gif, args.frames_dir, args.mp4, args.webm, args.svg_dir, args.pdf)
    if any(output is not None for output in frame_outputs):
        frame_settings, trace, slowed = flash_safe(scene, settings, trace)
        more = writers(args, frame_settings, scene)
        result = exporting.export(scene, frame_settings, gif=args.gif,
                                  frames_dir=args.frames_dir, progress=progress,
                                  cancelled=cancelled, names=names, frames_limit=frames_limit,
                                  writers=more, trace=trace, differences=differences,
                                  replace=args.force)
        if slowed:
            result = replace(result, chosen=f"{slowed}; {result.chosen}")
        finish(args, scene, more)
    page = write_html(args, scene, settings, trace) if args.html is not None else None
    return result, page


def summary(args, result, page) -> list[str]:
    """The command's lines: what was written, how many frames, how long, how large."""
    lines = []
    if result is not None:
        width, height = result.size
        written = [str(path) for path in (result.gif, result.frames_dir) if path is not None] \
            + [str(path) for path in (args.mp4, args.webm, args.svg_dir, args.pdf, args.beamer)
               if path is not None]
        lines.append(f"{' and '.join(written)}: {result.frames} "
                     f"frame{'s' if result.frames != 1 else ''} of {width}x{height} pixels, "
                     f"{sum(result.durations) / 1000:g} s"
                     + (f"; {result.chosen}" if result.chosen else ""))
    if page is not None:
        lines.append(f"{args.html}: an interactive page of {page.steps:,} steps, "
                     f"{page.size / 2 ** 20:.2f} MB")
    return lines


def writers(args, settings, scene) -> list:
    """The writers for the format options given (--mp4, --webm, --svg-dir, --pdf)
    and the transcripts (unless --no-transcript)."""
    out = []
    if args.mp4 is not None or args.webm is not None:
        from app.render.video import VideoWriter
        out += [VideoWriter(path, kind, settings.fps, settings.hold)
                for path, kind in ((args.mp4, "mp4"), (args.webm, "webm")) if path is not None]
    if args.svg_dir is not None or args.pdf is not None:
        from app.render.vector import PdfWriter, SvgFolderWriter
        only = bookmark_steps(scene) if getattr(args, "pages", "frames") == "bookmarks" else None
        out += [SvgFolderWriter(args.svg_dir, only, args.force)] if args.svg_dir is not None \
            else []
        out += [PdfWriter(args.pdf, only)] if args.pdf is not None else []
    if args.transcript:  # last: written once the pictures are
        out += transcript.writers(args.gif, args.mp4, args.webm, settings)
    return out


def bookmark_steps(scene) -> set[int]:
    """The steps of the scene's bookmarks: the vector frames of --pages bookmarks."""
    if not scene.bookmarks:
        raise ExportError("--pages bookmarks: the scene has no bookmarks (set them in the "
                          "window's Bookmarks panel, Ctrl+B)")
    return {int(b["step"]) for b in scene.bookmarks}


def finish(args, scene, done_writers) -> None:
    """What is written once the frames are: the Beamer snippet (--beamer)."""
    if args.beamer is None:
        return
    from app.render.vector import PdfWriter, beamer_snippet
    pdf = next(w for w in done_writers if isinstance(w, PdfWriter))
    title = scene.title or f"{scene.algorithm}"
    text = beamer_snippet(beamer_reference(args.pdf, args.beamer), pdf.pages, title)
    write_atomically(Path(args.beamer), text.encode("utf-8"), ExportError)


def beamer_reference(pdf, beamer) -> str:
    """The PDF as the Beamer snippet names it, relative to the snippet's
    folder; ExportError when LaTeX could not read that name (a %, a brace,
    a line end ...), which the command line checks before any work."""
    reference = os.path.relpath(Path(pdf).resolve(), Path(beamer).resolve().parent)
    try:
        return latex_file_name(Path(reference).as_posix())
    except ValueError as error:
        raise ExportError(f"--beamer: {error} ({reference!r}): rename the PDF") from None


class Page(NamedTuple):
    """What --html wrote: the run's steps and the page's size in bytes."""

    steps: int
    size: int


def write_html(args, scene, settings, trace=None) -> Page:
    """The interactive page (--html), from the scene's run (recorded here
    unless ``trace`` is the run already recorded)."""
    from app.render.html import write_page
    from app.render.settings import record

    if trace is None:
        trace = record(scene, memory_limit=settings.memory_limit,
                       time_limit=settings.time_limit, progress=settings.recording)
    size = write_page(scene, trace, args.html, settings.for_grid(trace.width, trace.height),
                      force=args.force)
    return Page(len(trace), size)
