"""The coverage template over 200 seeds, against sample counting in
Fractions (tests/support/question_oracles.py): the n x n regular samples of
the pixel at (2a + 1) / 2n, each tested against the triangle's edges."""
from __future__ import annotations

from fractions import Fraction

import pytest

from app.model.scene import Scene
from app.teaching.questions import antialias
from app.teaching.questions.model import NUMERICAL
from tests.support import question_oracles as oracle

SEEDS = range(200)


@pytest.mark.usefixtures("no_pictures")
def test_the_coverage_is_the_fraction_of_samples_inside():
    sizes = set()
    for seed in SEEDS:
        question = antialias.COVERAGE.make(seed)
        n = question.scene.options["n"]
        assert 2 <= n <= 4 and question.scene.options["pattern"] == "grid"
        sizes.add(n)
        pixel = oracle.asked_pixel(question.text)
        expected = oracle.coverage(question.scene.points, pixel, n)
        answer = question.answer
        assert answer.kind == NUMERICAL and answer.tolerance == 0
        assert answer.value == expected, seed
        assert 0 < expected < 1, "a pixel the triangle's edge crosses"
        hits, total = answer.text.split("/")
        assert int(total) == n * n and Fraction(int(hits), n * n) == expected
        assert len(question.worked.rows) == n * n
        assert sum(row[3] == "inside" for row in question.worked.rows) == int(hits)
    assert sizes == {2, 3, 4}


@pytest.mark.usefixtures("no_pictures")
def test_no_sample_of_the_asked_pixel_lies_on_an_edge():
    for seed in range(60):
        question = antialias.COVERAGE.make(seed)
        n = question.scene.options["n"]
        tri = oracle.triangles_of(question.scene.points)[0]
        i, j = oracle.asked_pixel(question.text)
        for a in range(n):
            for b in range(n):
                sample = (i + Fraction(2 * a + 1, 2 * n), j + Fraction(2 * b + 1, 2 * n))
                assert all(oracle.edge_value(tri, k, sample) != 0 for k in range(3))


def test_a_seed_gives_the_same_question_and_seeds_differ(no_pictures):
    assert antialias.COVERAGE.make(5) == antialias.COVERAGE.make(5)
    texts = {antialias.COVERAGE.make(seed).text for seed in range(40)}
    assert len(texts) >= 38


def test_a_question_carries_a_picture_and_a_given_scene_is_asked_about():
    drawn = antialias.COVERAGE.make(6)
    assert drawn.picture.startswith(b"\x89PNG")
    again = antialias.COVERAGE.make(8, scene=drawn.scene)
    assert again.scene.points == drawn.scene.points
    assert again.scene.options["n"] == drawn.scene.options["n"]


def test_a_scene_unfit_for_the_question_is_refused(no_pictures):
    jitter = Scene(algorithm="aa-supersample", points=((1, 1), (6, 2), (3, 5)),
                   options={"pattern": "jitter"}, width=8, height=6)
    with pytest.raises(ValueError, match="pattern grid"):
        antialias.COVERAGE.make(1, scene=jitter)
    line = Scene(algorithm="line-bresenham", points=((1, 1), (5, 3)), width=8, height=6)
    with pytest.raises(ValueError, match="aa-coverage"):
        antialias.COVERAGE.make(1, scene=line)
