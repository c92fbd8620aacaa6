"""Point labels on the grid: placed apart, in screen pixels, without a font."""
from app.model.label_layout import GAP, Rect, place


def test_a_lone_label_sits_centred_over_its_point():
    (rect,) = place([(100.0, 50.0)], [(40.0, 16.0)], [True])
    assert rect == Rect(80.0, 50.0 - GAP - 16.0, 40.0, 16.0)


def test_a_label_below_its_point_starts_under_it():
    (rect,) = place([(100.0, 50.0)], [(40.0, 16.0)], [False])
    assert rect.top == 50.0 + GAP


def test_labels_of_two_points_close_together_do_not_intersect():
    # Two vertices 3 px apart, both labelled above: before, the labels lay
    # on top of one another.
    anchors = [(100.0, 50.0), (103.0, 51.0)]
    sizes = [(60.0, 16.0), (60.0, 16.0)]
    first, second = place(anchors, sizes, [True, True])
    assert not first.intersects(second)
    assert first.top == 50.0 - GAP - 16.0  # the first keeps its place
    assert second.top + second.height <= first.top  # the second moved further out


def test_many_labels_on_one_spot_all_get_a_place_of_their_own():
    rects = place([(200.0, 200.0)] * 6, [(50.0, 14.0)] * 6, [True, False] * 3)
    assert all(not a.intersects(b) for i, a in enumerate(rects) for b in rects[i + 1:])


def test_labels_far_apart_stay_where_they_are_put():
    rects = place([(0.0, 0.0), (500.0, 0.0)], [(40.0, 16.0)] * 2, [True, True])
    assert rects[0].top == rects[1].top == -GAP - 16.0


def test_rectangles_that_only_touch_do_not_intersect():
    assert not Rect(0, 0, 10, 10).intersects(Rect(10, 0, 10, 10))
    assert Rect(0, 0, 10, 10).intersects(Rect(9, 9, 10, 10))
