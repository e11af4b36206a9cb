"""Path (building, SVG data, the NumPy round trip) and Affine (the algebra)."""
import copy
import math
import pickle

import numpy as np
import pytest

import casteljau
from casteljau import Affine, Path


def sample_path():
    p = Path()
    p.line_to(5, 5)  # no move_to: starts at the origin
    p.move_to(10, 10).line_to(20, 10).quad_to(25, 15, 20, 20).cubic_to(15, 25, 12, 22, 10, 20)
    p.close()  # adds the closing line
    p.move_to(30, 30).conic_to(40, 30, 40, 40, math.sqrt(0.5)).line_to(30, 30).close()
    p.move_to(50, 50).arc_to(10, 5, 30, True, False, 70, 50)
    p.move_to(80, 80)  # a lone move_to at the end
    return p


def test_building_and_segments():
    p = sample_path()
    kinds = [s[0] for s in p.segments]
    assert kinds[:6] == ["line", "line", "quad", "cubic", "line", "conic"]
    assert kinds.count("conic") >= 2
    assert len(p) == len(p.segments)
    assert p.subpath_count == 5
    assert p.segments[1] == ("line", ((10.0, 10.0), (20.0, 10.0)), 1.0)
    assert p.segments[5][2] == pytest.approx(math.sqrt(0.5))
    assert p.current_point == (80.0, 80.0)
    assert "5 subpaths" in repr(p)


def test_numpy_round_trip_is_exact():
    p = sample_path()
    verbs, points, weights = p.to_numpy()
    assert verbs.dtype == np.uint8 and points.dtype == np.float64 and points.shape[1] == 2
    assert list(verbs[:7]) == [casteljau.MOVE, casteljau.LINE, casteljau.MOVE, casteljau.LINE,
                               casteljau.QUAD, casteljau.CUBIC, casteljau.LINE]
    assert (verbs == casteljau.CLOSE).sum() == 2
    assert len(weights) == (verbs == casteljau.CONIC).sum()
    q = Path.from_numpy(verbs, points, weights)
    assert q == p
    again = q.to_numpy()
    for a, b in zip(again, (verbs, points, weights)):
        assert np.array_equal(a, b)
    # Lists work as well as arrays, and a path with no conic needs no weights.
    r = Path.from_svg_d("M0 0 L10 0 Q 10 10 0 10 Z")
    v, pts, w = r.to_numpy()
    assert len(w) == 0
    assert Path.from_numpy(v.tolist(), pts.tolist()) == r


def test_random_paths_round_trip():
    rng = np.random.default_rng(7)
    for _ in range(50):
        p = Path()
        for verb in rng.integers(0, 6, size=20):
            x = rng.uniform(-100, 100, size=6)
            if verb == 0:
                p.move_to(x[0], x[1])
            elif verb == 1:
                p.line_to(x[0], x[1])
            elif verb == 2:
                p.quad_to(*x[:4])
            elif verb == 3:
                p.cubic_to(*x)
            elif verb == 4:
                p.conic_to(*x[:4], rng.uniform(0.1, 3))
            else:
                p.close()
        assert Path.from_numpy(*p.to_numpy()) == p
        assert pickle.loads(pickle.dumps(p)) == p


def test_from_numpy_validates():
    with pytest.raises(ValueError, match="take 2 points"):
        Path.from_numpy([0, 1], [[0, 0]])
    with pytest.raises(ValueError, match="not a verb"):
        Path.from_numpy([7], [[0, 0]])
    with pytest.raises(ValueError, match="weights"):
        Path.from_numpy([0, 4], [[0, 0], [1, 1], [2, 0]])
    with pytest.raises(ValueError, match="weight must be > 0"):
        Path.from_numpy([0, 4], [[0, 0], [1, 1], [2, 0]], [-1.0])
    with pytest.raises(ValueError, match="not finite"):
        Path.from_numpy([0], [[np.nan, 0]])
    with pytest.raises(ValueError):
        Path.from_numpy([0], np.zeros((1, 3)))
    with pytest.raises(ValueError, match="not finite"):
        Path().line_to(float("inf"), 0)


def test_from_svg_d():
    p = Path.from_svg_d("M0 0 C 50 100 150 -100 200 0")
    assert p.segments == [("cubic", ((0, 0), (50, 100), (150, -100), (200, 0)), 1.0)]
    x0, y0, x1, y1 = p.bounds()
    assert (x0, x1) == (0, 200) and y0 == pytest.approx(-y1) and 25 < y1 < 30
    assert p.control_bounds() == (0, -100, 200, 100)
    assert Path().bounds() is None
    with pytest.raises(ValueError, match="path data: at offset 9: expected a number"):
        Path.from_svg_d("M0 0 L10 x")
    partial = Path.from_svg_d("M0 0 L10 0 L10 x", strict=False)
    assert len(partial) == 1
    # Arcs are exact conics.
    arc = Path.from_svg_d("M0 0 A 10 10 0 0 1 20 0")
    assert {s[0] for s in arc.segments} == {"conic"}


def test_path_copy_and_transform():
    p = sample_path()
    q = copy.deepcopy(p)
    assert q == p and q is not p
    q.line_to(1, 1)
    assert q != p
    t = p.transformed(Affine.translate(1, 2))
    v0, pts0, _ = p.to_numpy()
    v1, pts1, _ = t.to_numpy()
    assert np.array_equal(v0, v1) and np.array_equal(pts1, pts0 + [1, 2])


def test_chaining_returns_the_same_path():
    p = Path()
    assert p.move_to(0, 0) is p
    assert p.line_to(1, 0).close() is p


# --- Affine ----------------------------------------------------------------

def test_affine_constructors():
    assert Affine() == Affine.identity()
    assert Affine.translate(3, 4).coefficients == (1, 0, 0, 1, 3, 4)
    assert Affine.scale(2).coefficients == (2, 0, 0, 2, 0, 0)
    assert Affine.scale(2, 3).apply((1, 1)) == (2, 3)
    r = Affine.rotate(90, degrees=True)
    assert r.apply((1, 0)) == pytest.approx((0, 1))
    assert Affine.rotate(math.pi / 2).apply((1, 0)) == pytest.approx((0, 1))
    assert Affine.skew_x(45, degrees=True).apply((0, 1)) == pytest.approx((1, 1))
    assert repr(Affine.translate(3, 4)) == "Affine(1, 0, 0, 1, 3, 4)"
    with pytest.raises(ValueError):
        Affine(float("nan"))


def test_affine_algebra():
    rng = np.random.default_rng(3)
    pts = rng.uniform(-50, 50, size=(100, 2))
    a = Affine.rotate(0.3) @ Affine.scale(2, 0.5)
    b = Affine.translate(5, -7) @ Affine.skew_y(0.2)
    c = Affine(1.5, 0.2, -0.3, 0.8, 4, 9)
    # Composition applies the right-hand map first, and is associative.
    assert np.allclose((a @ b).apply(pts), a.apply(b.apply(pts)))
    assert np.allclose(((a @ b) @ c).to_numpy(), (a @ (b @ c)).to_numpy())
    assert (a * b) == (a @ b)
    assert Affine.identity() @ c == c and c @ Affine.identity() == c
    assert np.allclose((c @ c.inverse()).to_numpy(), np.eye(3))
    assert np.allclose(c.inverse().apply(c.apply(pts)), pts)
    assert c.determinant() == pytest.approx(1.5 * 0.8 + 0.2 * 0.3)
    # The matrix form is the same map.
    m = c.to_numpy()
    homog = np.c_[pts, np.ones(len(pts))] @ m.T
    assert np.allclose(homog[:, :2], c.apply(pts))
    assert Affine.from_numpy(m) == c
    # Points: a tuple for a point, an array for an array, the input untouched.
    before = pts.copy()
    out = c(pts)
    assert out.shape == (100, 2) and out.dtype == np.float64
    assert np.array_equal(pts, before)
    assert isinstance(c.apply([1, 2]), tuple)
    assert c.apply(np.zeros((0, 2))).shape == (0, 2)
    with pytest.raises(ValueError):
        c.apply(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="singular"):
        Affine.scale(0).inverse()


def test_affine_values():
    a = Affine.translate(1, 2)
    assert hash(a) == hash(Affine.translate(1, 2))
    assert {a, Affine.translate(1, 2)} == {a}
    assert pickle.loads(pickle.dumps(a)) == a
    assert (a.a, a.b, a.c, a.d, a.e, a.f) == (1, 0, 0, 1, 1, 2)
