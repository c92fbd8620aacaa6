"""The visibility templates over 200 seeds each, against exact oracles in
tests/support/question_oracles.py: top-left coverage and barycentric depths
in Fractions per pixel, the z-buffer's nearest fragment and the painter's
back-to-front order by mean depth."""
from __future__ import annotations

import pytest

from app.model.scene import Scene
from app.teaching.questions import visibility
from app.teaching.questions.model import CHOICE
from tests.support import question_oracles as oracle

SEEDS = range(200)


def _inputs(question):
    points = question.scene.points
    depths = question.scene.options["z"]
    assert len(points) % 3 == 0 and len(depths) == len(points)
    for tri in oracle.triangles_of(points):
        assert oracle.twice_area(tri) >= visibility.MIN_AREA2
    return points, depths


@pytest.mark.usefixtures("no_pictures")
def test_the_visible_triangle_is_the_nearest_covering_the_centre():
    winners = set()
    for seed in SEEDS:
        question = visibility.VISIBLE.make(seed)
        points, depths = _inputs(question)
        pixel = oracle.asked_pixel(question.text)
        point = oracle.centre(pixel)
        covering = [n for n, tri in enumerate(oracle.triangles_of(points))
                    if oracle.inside(tri, point)]
        assert len(covering) >= 2, seed  # a question about depth, not about coverage
        zs = sorted(oracle.depth_at(points, depths, n, point) for n in covering)
        assert all(b - a >= 0.019 for a, b in zip(zs, zs[1:])), "no near ties"
        owner = oracle.zbuffer_owner(points, depths, pixel)
        answer = question.answer
        assert answer.kind == CHOICE
        assert answer.choices == tuple(f"T{n + 1}" for n in range(len(points) // 3))
        assert answer.value == owner, seed
        winners.add(owner)
    assert winners == {0, 1, 2}


@pytest.mark.usefixtures("no_pictures")
def test_the_painter_fails_exactly_where_its_order_differs_from_the_zbuffer():
    answers = []
    for seed in SEEDS:
        question = visibility.PAINTER.make(seed)
        points, depths = _inputs(question)
        fails = oracle.painter_fails(points, depths, question.scene.grid)
        assert question.answer.choices == ("yes", "no")
        assert question.answer.value == (0 if fails else 1), seed
        answers.append(fails)
    assert 60 <= sum(answers) <= 140, "both answers, about as often"


@pytest.mark.parametrize("template", visibility.TEMPLATES, ids=lambda t: t.name)
def test_a_seed_gives_the_same_question_and_seeds_differ(template, no_pictures):
    assert template.make(9) == template.make(9)
    texts = {template.make(seed).text for seed in range(40)}
    assert len(texts) >= 38
    assert template.make(9).title and "#" not in template.make(9).title  # the bank numbers them


@pytest.mark.parametrize("template", visibility.TEMPLATES, ids=lambda t: t.name)
def test_a_question_carries_a_picture_and_a_given_scene_is_asked_about(template):
    drawn = template.make(4)
    assert drawn.picture.startswith(b"\x89PNG")
    again = template.make(13, scene=drawn.scene)
    assert again.scene.points == drawn.scene.points
    assert again.answer.choices == drawn.answer.choices


def test_a_scene_unfit_for_the_question_is_refused(no_pictures):
    line = Scene(algorithm="line-bresenham", points=((1, 1), (5, 3)), width=8, height=6)
    apart = Scene(algorithm="zbuffer", points=((0, 0), (3, 0), (0, 3), (5, 5), (8, 5), (5, 8)),
                  options={"z": (0.5,) * 6}, width=10, height=10)
    for template in visibility.TEMPLATES:
        with pytest.raises(ValueError, match=template.name):
            template.make(1, scene=line)
    with pytest.raises(ValueError, match="two triangles"):
        visibility.VISIBLE.make(1, scene=apart)
