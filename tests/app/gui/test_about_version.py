"""The version the About box shows, on Python 3.10 too (no tomllib there)."""
import sys
from importlib import metadata

import pytest

from app.gui import about
from tests.support import ROOT

TEXT = '''
[tool.other]
version = "9.9.9"

[project]
name = "rasterlab"
version = "1.2.3"

[project.optional-dependencies]
test = []
'''


@pytest.mark.parametrize("text, expected", [
    (TEXT, "1.2.3"),
    # The installed package's metadata, written from the same file by the build.
    ((ROOT / "pyproject.toml").read_text(encoding="utf-8"), metadata.version("rasterlab")),
])
def test_with_and_without_tomllib_the_project_version_is_read(monkeypatch, text, expected):
    assert about.declared_version(text) == expected
    monkeypatch.setitem(sys.modules, "tomllib", None)  # as on Python 3.10
    assert about.declared_version(text) == expected


def test_no_project_version_is_no_version(monkeypatch):
    monkeypatch.setitem(sys.modules, "tomllib", None)
    assert about.declared_version('[tool.other]\nversion = "9"\n') == ""
