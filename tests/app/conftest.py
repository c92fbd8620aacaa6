"""Fixtures shared by the tests of the app's packages."""
import subprocess
import sys

import pytest

from app import cli
from tests.support import ROOT


@pytest.fixture
def run_cli(capsys):
    """``run_cli(*argv, child=False)``: the command line, as (exit status,
    standard output, standard error). It runs in this process, or with
    ``child`` as a person starts it: ``python -m rasterlab`` in a process of its own."""
    def run(*argv, child=False):
        argv = [str(arg) for arg in argv]
        if child:
            done = subprocess.run([sys.executable, "-m", "rasterlab", *argv], cwd=ROOT,
                                  capture_output=True, text=True, timeout=120)
            return done.returncode, done.stdout, done.stderr
        status = cli.main(argv)
        out, err = capsys.readouterr()
        return status, out, err
    return run
