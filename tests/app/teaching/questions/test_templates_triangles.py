"""The triangle templates over 200 seeds each, against exact oracles written
in tests/support/question_oracles.py (edge functions, barycentric weights,
DESIGN.md's top-left rule, perspective-correct interpolation)."""
from __future__ import annotations

from fractions import Fraction

import pytest

from app.model.scene import Scene
from app.teaching.questions import triangle_draws, triangles
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT
from tests.support import question_oracles as oracle

SEEDS = range(200)
PNG = b"\x89PNG\r\n\x1a\n"


def _triangle(question):
    tri = oracle.exact_points(question.scene.points)
    assert oracle.twice_area(tri) >= triangle_draws.MIN_AREA2, "counter-clockwise, no sliver"
    for x, y in tri:  # on the 1/2 px grid, within the grid
        assert (2 * x).denominator == 1 and (2 * y).denominator == 1
        assert 0 <= x <= question.scene.width and 0 <= y <= question.scene.height
    return tri


@pytest.mark.usefixtures("no_pictures")
def test_edge_values_equal_the_edge_functions_at_the_centre():
    for seed in SEEDS:
        question = triangles.EDGE_VALUES.make(seed)
        tri = _triangle(question)
        point = oracle.centre(oracle.asked_pixel(question.text))
        expected = [oracle.edge_value(tri, k, point) for k in range(3)]
        assert question.answer.kind == SHORT
        assert oracle.numbers(question.answer.value) == expected, seed
        assert all(oracle.numbers(text) == expected for text in question.answer.also)
        assert "e0 = (" in question.worked.summary and len(question.worked.rows) == 3


@pytest.mark.usefixtures("no_pictures")
def test_barycentric_weights_are_exact_area_ratios():
    for seed in SEEDS:
        question = triangles.BARYCENTRIC.make(seed)
        tri = _triangle(question)
        pixel = oracle.asked_pixel(question.text)
        expected = oracle.weights(tri, oracle.centre(pixel))
        assert oracle.numbers(question.answer.value) == expected, seed
        assert sum(expected) == 1 and min(expected) >= 0  # p is a covered pixel
        assert question.answer.text == "(" + ", ".join(str(w) for w in expected) + ")"


@pytest.mark.usefixtures("no_pictures")
def test_top_left_verdicts_follow_the_rule_and_ask_about_ties():
    answers, ties = [], 0
    for seed in SEEDS:
        question = triangles.TOP_LEFT.make(seed)
        tri = _triangle(question)
        point = oracle.centre(oracle.asked_pixel(question.text))
        es = [oracle.edge_value(tri, k, point) for k in range(3)]
        on_edge = min(es) == 0
        ties += on_edge
        filled = oracle.inside(tri, point)
        assert question.answer.kind == CHOICE and question.answer.choices == ("yes", "no")
        assert question.answer.value == (0 if filled else 1), seed
        if on_edge and min(es) == 0 and not any(e < 0 for e in es):
            assert ("keeps" if filled else "leaves out") in question.worked.summary
        answers.append((on_edge, filled))
    assert ties >= 80, "the rule decides in many variants"
    assert {(True, True), (True, False), (False, True), (False, False)} <= set(answers)


@pytest.mark.usefixtures("no_pictures")
def test_perspective_values_divide_the_interpolated_s_over_w_by_1_over_w():
    for seed in SEEDS:
        question = triangles.PERSPECTIVE.make(seed)
        tri = _triangle(question)
        options = question.scene.options
        w, s = options["w"], options["s"]
        assert len(set(w)) > 1
        expected = oracle.perspective_value(tri, oracle.centre(oracle.asked_pixel(question.text)),
                                            w, s)
        assert question.answer.kind == NUMERICAL
        assert question.answer.value == expected, seed
        assert question.answer.text == f"{float(expected):.3f}"
        assert 0 < question.answer.tolerance <= 0.001
        lo, hi = min(s), max(s)
        assert lo <= expected <= hi


@pytest.mark.parametrize("template", triangles.TEMPLATES, ids=lambda t: t.name)
def test_a_seed_gives_the_same_question_and_seeds_differ(template, no_pictures):
    first, again = template.make(7), template.make(7)
    assert first == again
    texts = {template.make(seed).text for seed in range(40)}
    assert len(texts) >= 38
    assert first.title and "#" not in first.title  # the bank numbers the variants
    assert template.family == "triangles" and template.algorithms[0] == first.scene.algorithm


@pytest.mark.parametrize("template", triangles.TEMPLATES, ids=lambda t: t.name)
def test_a_question_carries_a_picture_of_its_scene(template):
    question = template.make(3)
    assert question.picture.startswith(PNG)


@pytest.mark.parametrize("template", triangles.TEMPLATES, ids=lambda t: t.name)
def test_a_given_scene_is_asked_about(template, no_pictures):
    drawn = template.make(11)
    question = template.make(5, scene=drawn.scene)
    assert oracle.exact_points(question.scene.points) == oracle.exact_points(drawn.scene.points)
    assert question.seed == 5


def test_a_scene_of_another_algorithm_is_refused(no_pictures):
    scene = Scene(algorithm="line-bresenham", points=((1, 1), (5, 3)), width=8, height=6)
    for template in triangles.TEMPLATES:
        with pytest.raises(ValueError, match=template.name):
            template.make(1, scene=scene)


def test_a_given_scene_with_its_own_options():
    scene = Scene(algorithm="triangle-perspective", points=((1, 1), (7, 1.5), (2, 6)),
                  options={"w": (1.0, 2.0, 4.0), "s": (0.0, 4.0, 8.0)}, width=8, height=8)
    question = triangles.PERSPECTIVE.make(2, scene=scene)
    tri = oracle.exact_points(scene.points)
    point = oracle.centre(oracle.asked_pixel(question.text))
    assert question.answer.value == oracle.perspective_value(tri, point, (1, 2, 4), (0, 4, 8))
    assert Fraction(question.answer.text) == round(question.answer.value, 3)


def test_a_clockwise_scene_is_asked_about_counter_clockwise():
    scene = Scene(algorithm="triangle-perspective", points=((1, 1), (2, 6), (7, 1.5)),
                  options={"w": (1.0, 4.0, 2.0), "s": (0.0, 8.0, 4.0)}, width=8, height=8)
    question = triangles.PERSPECTIVE.make(4, scene=scene)
    assert "P0 = (1, 1), P1 = (7, 1.5), P2 = (2, 6), with w = 1, 2, 4" in question.text
    assert "s = 0, 4, 8" in question.text
    tri = oracle.exact_points(((1, 1), (7, 1.5), (2, 6)))
    point = oracle.centre(oracle.asked_pixel(question.text))
    assert question.answer.value == oracle.perspective_value(tri, point, (1, 2, 4), (0, 4, 8))
