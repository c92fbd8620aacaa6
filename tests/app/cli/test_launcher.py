"""The `rasterlab` entry point: automatic collection is off for the window's
start-up from before the first import, and stays on for every command."""
import subprocess
import sys

from tests.support import ROOT

# A stand-in for the command line, so that no window opens: it reports
# whether automatic collection was on when the launcher took its main().
PROBE = """
import gc, sys, types


class CommandLine(types.ModuleType):
    def __getattr__(self, name):
        if name != "main":
            raise AttributeError(name)
        at_import = gc.isenabled()
        return lambda: print("COLLECTING", at_import, gc.isenabled()) or 0


sys.modules["app.cli"] = CommandLine("app.cli")
sys.argv = ["rasterlab"] + sys.argv[1:]
from app.launcher import main
sys.exit(main())
"""


def probe(*args):
    out = subprocess.run([sys.executable, "-c", PROBE, *args], cwd=ROOT, capture_output=True,
                         text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


def test_the_window_starts_with_automatic_collection_off():
    assert probe() == ["COLLECTING", "False", "False"]


def test_a_command_keeps_automatic_collection():
    assert probe("list") == ["COLLECTING", "True", "True"]


def test_the_real_command_runs_through_the_launcher():
    code = ("import gc, sys; sys.argv = ['rasterlab', 'list']; from app.launcher import main; "
            "status = main(); print('ON', gc.isenabled()); sys.exit(status)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0, out.stderr
    assert "line-bresenham" in out.stdout and out.stdout.split()[-2:] == ["ON", "True"]
