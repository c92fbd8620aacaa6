import atexit
import os
import shutil
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

# Qt tests never need a display.
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
# Edits wait for their recording however long it takes, so a test sees the
# new trace at once; tests/app/gui/test_recording.py sets the wait to 0.
os.environ["RASTERLAB_RECORD_WAIT"] = "inf"
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

# No test reads or writes the person's real settings: for the whole session
# QSettings (every format and scope) lives in a temporary folder, set before
# Qt starts. Tests that need a clean file of their own set RASTERLAB_SETTINGS.
_SETTINGS_DIR = tempfile.mkdtemp(prefix="rasterlab-test-settings-")
atexit.register(shutil.rmtree, _SETTINGS_DIR, ignore_errors=True)
os.environ["XDG_CONFIG_HOME"] = _SETTINGS_DIR
os.environ.pop("RASTERLAB_SETTINGS", None)
# Recovery copies and the error log (app/gui/appdata.py) go there too; tests
# that look at them point RASTERLAB_DATA_DIR at a folder of their own.
os.environ["RASTERLAB_DATA_DIR"] = os.path.join(_SETTINGS_DIR, "data")
from PySide6.QtCore import QSettings  # noqa: E402 (after the environment is set)

for _format in (QSettings.Format.NativeFormat, QSettings.Format.IniFormat):
    for _scope in (QSettings.Scope.UserScope, QSettings.Scope.SystemScope):
        QSettings.setPath(_format, _scope, _SETTINGS_DIR)

# No property test fails because the machine is slow or loaded: hypothesis's
# time limit per example and its check for slow data generation are off.
settings.register_profile("rasterlab", deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("rasterlab")


def pytest_addoption(parser):
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite the golden frames (tests/app/render/golden/) from the "
                          "frames drawn now instead of comparing with them")


@pytest.fixture(autouse=True)
def _collect_garbage_after_each_test():
    """Once a window has turned automatic collection over to its main-thread
    timer (app/gui/main_thread_gc.py), tests that run no event loop would
    never collect: collect after each test as the timer would."""
    yield
    collector = sys.modules.get("app.gui.main_thread_gc")
    if collector is not None:
        collector.collect_now()
