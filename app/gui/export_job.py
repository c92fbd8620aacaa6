"""The export of a recorded run beside the window: the export dialog for
one scene's run and the thread that writes the files (app/gui/file_actions.py
opens it from File > Export)."""
from __future__ import annotations

import threading
from pathlib import Path

from PySide6.QtCore import QObject, QSettings, Qt, QThread, Signal

from widgets.export_dialog import ExportDialog

from app.gui.look import apply_look
from app.model.scene import one_line
from app.render import export as exporting
from app.render import formats

# Where the last export went (a QSettings key): the next one starts there.
EXPORT_FOLDER_KEY = "export/folder"


class ExportThread(QThread):
    """Runs one export beside the window; ``cancel()`` stops it at the next
    frame, and then nothing is written."""

    progressed = Signal(int, int)
    succeeded = Signal(object)
    failed = Signal(str)
    cancelled = Signal()

    def __init__(self, scene, trace, differences, settings, outputs, parent=None):
        super().__init__(parent)
        self.job = (scene, trace, differences, settings, outputs)
        self._stop = threading.Event()

    def cancel(self) -> None:
        self._stop.set()

    def run(self) -> None:  # the thread's body
        scene, trace, differences, settings, outputs = self.job
        try:
            result = formats.export_all(outputs, scene, settings, exporting.MAX_FRAMES_BYTES,
                                        progress=self.progressed.emit,
                                        cancelled=self._stop.is_set, trace=trace,
                                        differences=differences, names=exporting.NAMES)
        except exporting.ExportCancelled:
            self.cancelled.emit()
        except exporting.ExportError as error:
            self.failed.emit(str(error))
        except Exception as error:  # noqa: BLE001 - reported in the dialog, not a crash
            self.failed.emit(one_line(f"the export failed: {type(error).__name__}: {error}"))
        else:
            self.succeeded.emit(result)


class ExportController(QObject):
    """The export dialog for one scene's recorded run (``trace``), and the
    thread that exports it."""

    def __init__(self, window, scene, trace, differences, default_path: str,
                 settings: QSettings | None = None):
        super().__init__(window)
        self.scene, self.trace, self.differences = scene, trace, differences
        self.settings = settings
        self.thread: ExportThread | None = None
        self.result = None
        self.dialog = ExportDialog(window, exporting.MAX_FPS, exporting.MAX_SCALE,
                                   exporting.MAX_HOLD)
        self.dialog.setWindowModality(Qt.WindowModality.WindowModal)
        apply_look(self.dialog, window.dark)
        self.dialog.set_steps(window.player.index, len(trace) - 1)
        self.dialog.set_bookmarks(scene.bookmarks)
        self.dialog.set_values({"scale": exporting.auto_scale(trace.width, trace.height),
                                "gif": default_path})
        self.dialog.exportRequested.connect(self.start)
        self.dialog.cancelRequested.connect(self.cancel)
        self.dialog.changed.connect(self._summarise)
        self.dialog.finished.connect(lambda _result: self._stop_thread())
        self._summarise()

    def export_settings(self) -> tuple[exporting.ExportSettings, formats.Outputs]:
        values = self.dialog.values()
        settings = exporting.ExportSettings(
            first=values["first"], last=values["last"], fps=values["fps"], hold=values["hold"],
            scale=values["scale"], grid_lines=values["grid_lines"],
            primitive=values["primitive"], highlight=values["highlight"],
            caption=values["caption"], panel=values["panel"], theme=values["theme"],
            loop=values["loop"], per=values["per"], unit=values["unit"],
            reasoning=values["reasoning"], axes=values["axes"],
            vertex_labels=values["vertex_labels"], text_size=values["text_size"])
        return settings, formats.Outputs(**{key: values[key] or None for key in (
            "gif", "frames_dir", "mp4", "webm", "svg_dir", "pdf", "html")},
            transcript=values["transcript"])

    def _summarise(self) -> None:
        values = self.dialog.values()
        try:
            steps, said = exporting.chosen_frames(self.scene, self.trace,
                                                  self.export_settings()[0])
            count = len(steps)
        except exporting.ExportError:
            count, said = 0, ""
        trace = self.trace
        seconds = sum(exporting.frame_durations(count, values["fps"], values["hold"])) / 1000
        self.dialog.set_size_text(
            f"{count:,} frame{'s' if count != 1 else ''}, {seconds:g} s; grid "
            f"{trace.width * values['scale']}x{trace.height * values['scale']} pixels"
            + (f"\n{said[0].upper()}{said[1:]}" if said else ""))

    def start(self) -> None:
        if self.thread is not None:
            return
        settings, outputs = self.export_settings()
        refused = _transcript_refused(outputs)
        if refused:
            self.dialog.set_message(refused)
            return
        self.outputs = outputs
        self.result = None
        self.thread = ExportThread(self.scene, self.trace, self.differences, settings, outputs,
                                   self)
        self.thread.progressed.connect(self.dialog.set_progress)
        self.thread.succeeded.connect(self._succeeded)
        self.thread.failed.connect(self._failed)
        self.thread.cancelled.connect(self._cancelled)
        self.thread.finished.connect(self._thread_done)
        self.dialog.set_message("Exporting\u2026")
        self.dialog.set_running(True)
        self.thread.start()

    def cancel(self) -> None:
        if self.thread is not None:
            self.dialog.set_message("Cancelling\u2026")
            self.thread.cancel()

    def close(self) -> None:
        self._stop_thread()
        self.dialog.close()

    @property
    def busy(self) -> bool:
        return self.thread is not None

    def _stop_thread(self) -> None:
        thread = self.thread
        if thread is not None:
            thread.cancel()
            thread.wait()

    def _succeeded(self, done) -> None:
        result, page = done
        self.result = result
        self.dialog.finish_progress("Done")
        self.dialog.set_message("Wrote " + "; ".join(formats.summary(self.outputs, result, page))
                                + ".")
        if self.settings is not None and result is not None and result.gif is not None:
            self.settings.setValue(EXPORT_FOLDER_KEY, str(Path(result.gif).resolve().parent))

    def _failed(self, message: str) -> None:
        self.dialog.finish_progress("Failed", done=False)
        self.dialog.set_message(f"Not exported: {message}", error=True)

    def _cancelled(self) -> None:
        self.dialog.finish_progress("Cancelled", done=False)
        self.dialog.set_message("Cancelled; nothing was written.")

    def _thread_done(self) -> None:
        thread, self.thread = self.thread, None
        self.dialog.set_running(False)
        if thread is not None:
            thread.deleteLater()


def _transcript_refused(outputs) -> str:
    """Why a transcript of ``outputs`` may not be written (in its place a
    file RasterLab did not write, or no file at all), or ""."""
    if not outputs.transcript:
        return ""
    from app.render import transcript
    for output in transcript.outputs(outputs.gif, outputs.mp4, outputs.webm):
        path = Path(output.path)
        if path.exists() and (not path.is_file() or output.foreign(path)):
            return (f"Not exported: {path} is in the transcript's place and is not a "
                    "transcript RasterLab wrote: rename it, or turn the transcript off")
    return ""
