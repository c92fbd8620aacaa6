"""No lost work: unsaved changes, the recovery copy, and closing.

``MainWindow.add_recovery()`` (after ``add_file_actions``) keeps track
of whether the scene on show differs from the one last opened or saved
(its "view" part aside: the step on show and the speed are not work). While
it differs, the title shows "*" and, a moment after the last edit, the
scene is written atomically to a recovery file in the application data
folder. Saving or going back to the saved scene removes the copy, and so
does a normal close, which first asks whether to save.

Each running program owns one recovery file, held by a ``QLockFile``; a
file whose lock no live program holds was left by a program that crashed or
was killed. ``offer_recovery(window)`` offers to restore it at the next
start. A recovery file that cannot be read is set aside (renamed), with a
message saying where, and never stops the program.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QEvent, QLockFile, QObject, QTimer, Signal
from PySide6.QtWidgets import QMessageBox

from algorithms.core.registry import InputError

from app.model import scene as scenes
from app.gui.appdata import APP_NAME, data_dir, ensure
from app.model.scene import Scene, SceneError, one_line

AUTOSAVE_DELAY_MS = 2000
POLL_MS = 1500
FOLDER_NAME = "recovery"
PREFIX = "scene-"


def recovery_dir() -> Path:
    return data_dir() / FOLDER_NAME


def content(scene: Scene) -> dict:
    """What counts as the work in a scene: all of it but the view."""
    data = scene.to_json()
    data.pop("view", None)
    return data


@dataclass
class Pending:
    """A recovery file left by a program that did not close normally."""
    path: Path
    lock: QLockFile  # held by this program while it deals with the file

    @property
    def saved_at(self) -> datetime:
        try:
            return datetime.fromtimestamp(self.path.stat().st_mtime)
        except OSError:
            return datetime.now()

    def release(self) -> None:
        self.lock.unlock()


def pending_recoveries(folder: Path | None = None) -> list[Pending]:
    """Recovery files no running program owns, newest first; each comes
    locked, so a second program starting now will not offer it too."""
    folder = folder if folder is not None else recovery_dir()
    found = []
    for path in folder.glob(f"{PREFIX}*.json"):
        lock = QLockFile(str(path.with_suffix(".lock")))
        lock.setStaleLockTime(0)  # never stale by age: only a dead owner frees it
        if lock.tryLock(0):
            found.append(Pending(path, lock))
    found.sort(key=lambda p: p.saved_at, reverse=True)
    return found


def set_aside(path: Path) -> Path | None:
    """Rename a broken recovery file out of the way; its new name, or None."""
    target = path.with_name(f"{path.stem}.broken-{time.strftime('%Y%m%d-%H%M%S')}.json.txt")
    try:
        path.replace(target)
    except OSError:
        return None
    return target


class Recovery(QObject):
    """Unsaved-change tracking, autosave and the question on close for one
    window (with its ``file_actions``)."""

    autosaved = Signal(str)  # the recovery file's path

    def __init__(self, window, folder: Path | None = None, delay_ms: int = AUTOSAVE_DELAY_MS,
                 poll_ms: int = POLL_MS):
        super().__init__(window)
        self.window = window
        self.files = window.file_actions
        self.folder = folder if folder is not None else recovery_dir()
        stamp = f"{os.getpid()}-{time.time_ns()}"
        self.path = self.folder / f"{PREFIX}{stamp}.json"
        self._lock = QLockFile(str(self.path.with_suffix(".lock")))
        self._lock.setStaleLockTime(0)
        self._baseline = self._content()
        self._last = self._baseline  # the scene at the last check
        self._written = None  # the scene in the recovery file
        self._forced = False  # restored from a recovery file: unsaved until saved
        self.dirty = False
        self.problem = ""  # why the last autosave failed, if it did
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(delay_ms)
        self._timer.timeout.connect(self.autosave)
        # Edits that come without a signal (a change made in code, a field
        # added later) are caught by a slow look at the scene.
        self._poll = QTimer(self)
        self._poll.setInterval(poll_ms)
        self._poll.timeout.connect(self.check)
        self._poll.start()
        self._connect()
        self.update_title()

    def _connect(self) -> None:
        window, files = self.window, self.files
        window.player.traceChanged.connect(self.check)
        window.y_down_action.toggled.connect(lambda _on: self.check())
        window.grid_editor.originChanged.connect(lambda _on: self.check())
        files.saved.connect(self.mark_clean)
        files.opened.connect(self.mark_clean)
        files.reverted.connect(self.check)
        # The window sets its own title on every scene change; ours adds
        # the scene's name and the unsaved mark.
        window.windowTitleChanged.connect(lambda _title: self.update_title())
        window.installEventFilter(self)

    # ----------------------------------------------------------- state
    def _content(self) -> dict | None:
        try:
            return content(self.files.current_scene())
        except (SceneError, InputError, ValueError):
            return None

    def check(self) -> None:
        """Compare the scene with the saved one; call after any edit."""
        if self.files.opening:
            return  # an opened file still records: neither saved nor edited yet
        current = self._content()
        changed, self._last = current != self._last, current
        dirty = self._forced or current != self._baseline
        if dirty and changed:
            self._timer.start()  # restarted by each edit: saved once editing pauses
        elif dirty and current != self._written and not self._timer.isActive():
            self._timer.start()  # not written yet (a failed try): try again
        elif not dirty and self.dirty:
            self._timer.stop()
            self.remove_file()
        self._set_dirty(dirty)

    def _set_dirty(self, dirty: bool) -> None:
        if dirty != self.dirty:
            self.dirty = dirty
            self.window.setWindowModified(dirty)

    def mark_clean(self, *_args) -> None:
        """The scene on show is the saved one (just opened or saved)."""
        self._forced = False
        self._baseline = self._content()
        self._timer.stop()
        self.remove_file()
        self._set_dirty(False)
        self.update_title()

    def mark_dirty(self) -> None:
        """Unsaved whatever it holds (a restored scene), until saved."""
        self._forced = True
        self.check()

    def scene_name(self) -> str:
        path = self.files.path
        if path is not None:
            return Path(path).name
        return self.files.title or "Untitled"

    def update_title(self) -> None:
        spec = self.window.player.spec
        algorithm = f" \u2014 {spec.title}" if spec is not None else ""
        title = f"{self.scene_name()}[*]{algorithm} \u2014 {APP_NAME}"
        if self.window.windowTitle() != title:
            self.window.setWindowTitle(title)
        self.window.setWindowModified(self.dirty)

    # -------------------------------------------------------- autosave
    def autosave(self) -> bool:
        """Write the scene to the recovery file now (if it is unsaved)."""
        self._timer.stop()
        if not self.dirty:
            return False
        scene = self.files.current_scene()
        try:
            # Only a copy that would load back is worth keeping: a scene
            # still being drawn waits until its points are complete.
            scenes.from_json(scene.to_json())
            ensure(self.folder)
            if not self._lock.isLocked() and not self._lock.tryLock(0):
                raise OSError(f"cannot lock {self._lock.fileName()}")
            scenes.save(scene, self.path)
        except (ValueError, InputError) as error:  # SceneError is a ValueError
            self.problem = one_line(str(error))
            return False
        except OSError as error:
            self.problem = one_line(f"cannot write the recovery file: {error}")
            self.window.statusBar().showMessage(self.problem, 8000)
            return False
        self.problem = ""
        self._written = self._last = content(scene)
        self.autosaved.emit(str(self.path))
        return True

    def remove_file(self) -> None:
        self._written = None
        try:
            self.path.unlink(missing_ok=True)
        except OSError:
            pass  # left for the next start to offer; harmless

    def shutdown(self) -> None:
        """A normal end: no recovery copy, no lock."""
        self._timer.stop()
        self._poll.stop()
        self.remove_file()
        self._lock.unlock()

    # ----------------------------------------------------------- close
    def eventFilter(self, watched, event) -> bool:  # noqa: N802
        if watched is self.window and event.type() == QEvent.Type.Close:
            if not self.confirm_close():
                event.ignore()
                return True  # the window stays open
            self.shutdown()
        return False

    def confirm_close(self, before: str = "closing") -> bool:
        """Ask about unsaved changes; True when the window may close (or,
        with ``before="opening another scene"``, the scene may be replaced)."""
        self.check()
        if not self.dirty:
            return True
        buttons = QMessageBox.StandardButton
        answer = QMessageBox.question(
            self.window, "Unsaved changes",
            f"Save the changes to {self.scene_name()} before {before}?",
            buttons.Save | buttons.Discard | buttons.Cancel, buttons.Save)
        if answer == buttons.Save:
            return bool(self.files.save())  # a cancelled save dialog keeps the window
        return answer == buttons.Discard

    # --------------------------------------------------------- restore
    def offer(self) -> bool:
        """At start: offer the newest recovery file a crashed or killed
        program left. True when a scene was restored."""
        try:
            pending = pending_recoveries(self.folder)
        except OSError:
            return False
        if not pending:
            return False
        newest, others = pending[0], pending[1:]
        for item in others:
            item.release()  # offered at a later start
        try:
            return self._offer(newest)
        finally:
            newest.release()
            Path(newest.lock.fileName()).unlink(missing_ok=True)

    def _offer(self, item: Pending) -> bool:
        when = item.saved_at.strftime("%Y-%m-%d %H:%M:%S")
        answer = ask_restore(self.window, when)
        if answer == DISCARD:
            item.path.unlink(missing_ok=True)
        if answer != RESTORE:
            return False
        try:
            scene = scenes.load(item.path, confine=False)  # written by this program
            self.files.apply_scene(scene)
        except (SceneError, InputError) as error:
            aside = set_aside(item.path)
            where = f"It was set aside as {aside}." if aside else \
                f"It was left at {item.path}."
            QMessageBox.warning(self.window, "Restore unsaved scene",
                                f"The unsaved scene cannot be restored:\n"
                                f"{one_line(str(error))}\n{where}")
            return False
        self.files.path = None  # saving asks where: the scene came from no file
        self.mark_dirty()
        self.update_title()
        # Our own copy first, then the old one goes: never a moment without.
        if self.autosave():
            item.path.unlink(missing_ok=True)
        else:
            aside = set_aside(item.path)
            if aside is not None:
                self.window.statusBar().showMessage(f"The recovered scene was kept as {aside}",
                                                    10000)
        return True


RESTORE, DISCARD, LATER = "restore", "discard", "later"


def ask_restore(parent, when: str) -> str:
    """RESTORE, DISCARD or LATER (closed, Escape: asked again next time)
    for the scene saved at ``when``."""
    box = QMessageBox(QMessageBox.Icon.Question, "Restore unsaved scene",
                      f"RasterLab did not close normally. Restore the unsaved scene "
                      f"from {when}?", QMessageBox.StandardButton.NoButton, parent)
    restore = box.addButton("Restore", QMessageBox.ButtonRole.AcceptRole)
    restore.setToolTip("Show the scene as it was when last saved for recovery")
    discard = box.addButton(QMessageBox.StandardButton.Discard)
    discard.setToolTip("Delete the recovered scene and start with the usual one")
    later = box.addButton("Not now", QMessageBox.ButtonRole.RejectRole)
    later.setToolTip("Keep the recovered scene and ask again at the next start")
    box.setDefaultButton(restore)
    box.setEscapeButton(later)
    box.exec()
    return {restore: RESTORE, discard: DISCARD}.get(box.clickedButton(), LATER)
