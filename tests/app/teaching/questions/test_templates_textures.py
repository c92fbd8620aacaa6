"""The mip level template over 200 seeds, against the level worked out in
Fractions (tests/support/question_oracles.py): the affine mapping's
derivatives by Cramer's rule, rho^2 in texels, and the nearest level
(LINEAR_MIPMAP_NEAREST) decided on rho^2 against powers of two."""
from __future__ import annotations

import pytest

from app.model.scene import Scene
from app.teaching.questions import textures
from app.teaching.questions.model import NUMERICAL
from tests.support import question_oracles as oracle

SEEDS = range(200)
SIZE, TOP = (64, 64), 6  # checker:8: 64 x 64 texels, levels 0 .. 6


@pytest.mark.usefixtures("no_pictures")
def test_the_mip_level_is_the_nearest_to_log2_rho():
    levels = set()
    for seed in SEEDS:
        question = textures.MIP_LEVEL.make(seed)
        options = question.scene.options
        assert options["texture"] == "checker:8" and options["filter"] == "mip-nearest"
        assert set(options["w"]) == {1.0}, "an affine mapping, workable by hand"
        expected = oracle.mip_level(question.scene.points, options["uv"], SIZE, TOP)
        answer = question.answer
        assert answer.kind == NUMERICAL and answer.tolerance == 0
        assert answer.value == expected, seed
        assert answer.text == str(expected)
        assert "64 x 64" in question.text
        levels.add(expected)
    assert len(levels) >= 3, levels


def test_a_seed_gives_the_same_question_and_seeds_differ(no_pictures):
    assert textures.MIP_LEVEL.make(3) == textures.MIP_LEVEL.make(3)
    texts = {textures.MIP_LEVEL.make(seed).text for seed in range(40)}
    assert len(texts) >= 38


def test_a_question_carries_a_picture_and_a_given_scene_is_asked_about():
    drawn = textures.MIP_LEVEL.make(2)
    assert drawn.picture.startswith(b"\x89PNG")
    scene = Scene(algorithm="triangle-texture", points=((1, 1), (8, 1), (1, 7)),
                  options={"uv": (0, 0, 1, 0, 0, 1)}, width=10, height=8)
    question = textures.MIP_LEVEL.make(5, scene=scene)
    # du/dx = 1/7 and dv/dy = 1/6 of 64 texels: rho = 64/6, lambda = 3.4: level 3
    assert question.answer.value == oracle.mip_level(scene.points, (0, 0, 1, 0, 0, 1), SIZE,
                                                     TOP) == 3


def test_a_scene_of_another_algorithm_is_refused(no_pictures):
    line = Scene(algorithm="line-bresenham", points=((1, 1), (5, 3)), width=8, height=6)
    with pytest.raises(ValueError, match="texture-mip-level"):
        textures.MIP_LEVEL.make(1, scene=line)
