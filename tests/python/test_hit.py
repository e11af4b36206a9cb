"""Path hit tests (contains, winding, nearest, intersects_rect,
stroke_distance, stroke_bounds) against closed forms and dense sampling, and
their errors."""
import math

import numpy as np
import pytest

from casteljau import Path, StrokeGeometry


def circle(cx, cy, r, clockwise=False):
    p = Path().move_to(cx + r, cy)
    sweep = not clockwise
    p.arc_to(r, r, 0, False, sweep, cx - r, cy).arc_to(r, r, 0, False, sweep, cx + r, cy)
    return p.close()


def ring():
    """Circles of radius 10 and 5 about the origin, drawn the same way: winding 2 inside both."""
    path = circle(0, 0, 10)
    path.move_to(5, 0).arc_to(5, 5, 0, False, True, -5, 0).arc_to(5, 5, 0, False, True, 5, 0)
    return path.close()


def test_contains_is_exact_on_the_circle():
    p = circle(0, 0, 100)
    angles = np.linspace(0, 2 * math.pi, 360, endpoint=False) + 0.37
    unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    assert p.contains(unit * (100 - 1e-6)).all()
    assert not p.contains(unit * (100 + 1e-6)).any()
    assert p.contains((0, 0)) is True
    assert p.contains([150.0, 0.0]) is False


def test_array_answers_equal_point_answers():
    p = ring()
    rng = np.random.default_rng(3)
    pts = rng.uniform(-12, 12, size=(500, 2))
    for rule in ("nonzero", "evenodd"):
        got = p.contains(pts, rule=rule)
        assert got.dtype == np.bool_ and got.shape == (500,)
        assert list(got) == [p.contains(tuple(q), rule=rule) for q in pts]
    windings = p.winding(pts)
    assert windings.dtype.kind == "i"
    assert list(windings) == [p.winding(tuple(q)) for q in pts]


def test_fill_rules_on_the_ring():
    p = ring()
    assert abs(p.winding((0, 0))) == 2 and abs(p.winding((7.5, 0.1))) == 1
    assert p.winding((20, 0)) == 0
    assert p.contains((0, 0)) and not p.contains((0, 0), rule="evenodd")
    assert p.contains((7.5, 0.1), rule="evenodd")
    pts = np.random.default_rng(4).uniform(-12, 12, size=(400, 2))
    r = np.hypot(pts[:, 0], pts[:, 1])
    clear = np.abs(r - 5) > 1e-9
    clear &= np.abs(r - 10) > 1e-9
    expected = (r < 10) & (r > 5)
    assert (p.contains(pts, rule="evenodd")[clear] == expected[clear]).all()


def test_nearest_matches_dense_sampling():
    p = Path().move_to(0, 0).cubic_to(30, 60, 70, -40, 100, 20).line_to(100, 80)
    ts = np.linspace(0, 1, 200001)
    mt = 1 - ts
    bx = mt**3 * 0 + 3 * mt**2 * ts * 30 + 3 * mt * ts**2 * 70 + ts**3 * 100
    by = mt**3 * 0 + 3 * mt**2 * ts * 60 + 3 * mt * ts**2 * -40 + ts**3 * 20
    rng = np.random.default_rng(5)
    for q in rng.uniform(-20, 120, size=(40, 2)):
        d, (x, y), index, t = p.nearest(*q)
        cubic_best = np.hypot(bx - q[0], by - q[1]).min()
        # The line x = 100, 20 <= y <= 80.
        line_best = math.hypot(q[0] - 100, q[1] - min(max(q[1], 20), 80))
        brute = min(cubic_best, line_best)
        assert d <= brute + 1e-9
        assert d >= brute - 1e-3  # the samples' spacing
        assert math.isclose(math.hypot(x - q[0], y - q[1]), d, rel_tol=1e-12, abs_tol=1e-12)
        assert index in (0, 1) and 0 <= t <= 1
    assert Path().nearest(1, 2) is None


def test_intersects_rect_fill_and_outline():
    p = circle(0, 0, 100)
    assert p.intersects_rect(-10, -10, 10, 10)  # wholly inside the fill
    assert not p.intersects_rect(-10, -10, 10, 10, fill=False)  # meets no curve
    assert p.intersects_rect(95, -5, 105, 5, fill=False)
    assert not p.intersects_rect(80, 80, 90, 90)  # the corner outside the circle
    assert p.intersects_rect(10, 10, -10, -10)  # corners in any order


def test_stroke_distance_and_bounds_follow_caps_and_dashes():
    line = Path().move_to(0, 0).line_to(100, 0)
    butt = StrokeGeometry(width=10)
    assert line.stroke_distance(50, 3, butt) == 0
    assert line.stroke_distance(50, 20, butt) == pytest.approx(15, abs=1e-3)
    assert line.stroke_distance(-3, 0, butt) == pytest.approx(3, abs=1e-3)  # no reach past the end
    round_cap = StrokeGeometry(width=10, cap="round")
    assert line.stroke_distance(-8, 0, round_cap) == pytest.approx(3, abs=1e-3)
    assert line.stroke_distance(-3, 0, round_cap) == 0
    dashed = StrokeGeometry(width=10, dashes=[20, 10])
    assert line.stroke_distance(25, 0, dashed) == pytest.approx(5, abs=1e-3)  # a gap's middle
    x0, y0, x1, y1 = line.stroke_bounds(butt, tolerance=0.01)
    assert (x0, y0) == pytest.approx((0, -5), abs=0.0101)
    assert (x1, y1) == pytest.approx((100, 5), abs=0.0101)
    assert x0 <= 0 and y0 <= -5 and x1 >= 100 and y1 >= 5  # holds the stroke
    assert Path().stroke_bounds(butt) is None


def test_errors():
    p = circle(0, 0, 1)
    with pytest.raises(ValueError, match="not finite"):
        p.contains((math.nan, 0))
    with pytest.raises(ValueError, match=r"points\[1\] is not finite"):
        p.contains(np.array([[0.0, 0.0], [math.inf, 0.0]]))
    with pytest.raises(ValueError, match="shape"):
        p.contains(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="rule"):
        p.contains((0, 0), rule="odd")
    with pytest.raises(ValueError, match="not finite"):
        p.nearest(0, math.inf)
    with pytest.raises(ValueError, match="not finite"):
        p.intersects_rect(0, 0, math.nan, 1)
    with pytest.raises(ValueError, match="tolerance"):
        p.stroke_distance(0, 0, StrokeGeometry(), tolerance=0)
    with pytest.raises(ValueError, match="tolerance"):
        p.stroke_bounds(StrokeGeometry(), tolerance=math.inf)
