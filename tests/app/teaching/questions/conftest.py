"""Fixtures of the question tests."""
import pytest

from app.teaching.questions import common


@pytest.fixture
def no_pictures(monkeypatch):
    """Questions without their picture: the tests that check answers over
    hundreds of seeds skip drawing it (each template's picture is tested once)."""
    monkeypatch.setattr(common, "picture", lambda scene, cell: b"picture")
