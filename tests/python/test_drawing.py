"""Drawing (edits and partial redraws equal to fresh renders, hit-testing) and
the canvases' zero-copy buffers."""
import gc
import math

import numpy as np
import pytest

import casteljau
from casteljau import Affine, Canvas, Canvas8, Drawing, Paint, Path, StrokeGeometry

W, H = 160, 120


def blob(rng):
    cx, cy, r = rng.uniform(0, W), rng.uniform(0, H), rng.uniform(4, 25)
    p = Path()
    n = 5
    for i in range(n):
        a0, a1 = 2 * math.pi * i / n, 2 * math.pi * (i + 1) / n
        k = rng.uniform(0.6, 1.4)
        if i == 0:
            p.move_to(cx + r * math.cos(a0), cy + r * math.sin(a0))
        p.cubic_to(cx + k * r * math.cos(a0 + 0.4), cy + k * r * math.sin(a0 + 0.4),
                   cx + k * r * math.cos(a1 - 0.4), cy + k * r * math.sin(a1 - 0.4),
                   cx + r * math.cos(a1), cy + r * math.sin(a1))
    return p.close()


def color(rng):
    return Paint.solid(*rng.uniform(0, 1, size=3), rng.uniform(0.3, 1))


def build(rng):
    d = Drawing(W, H)
    for i in range(40):
        path = blob(rng)
        if i % 3 == 0:
            g = StrokeGeometry(width=rng.uniform(0.5, 6), join=["miter", "round", "bevel"][i % 3],
                               cap="round", dashes=[6, 3] if i % 2 else [])
            d.stroke(path, color(rng), g)
        elif i % 5 == 0:
            x0, y0, x1, y1 = path.bounds()
            d.fill(path, Paint.linear(x0, y0, x1, y1, [(0, (1, 0, 0)), (1, (0, 0, 1, 0.5))]),
                   rule="evenodd")
        else:
            d.fill(path, color(rng), Affine.translate(rng.uniform(-5, 5), 0))
    return d


def edits(d, rng):
    """Yields after each edit, with its dirty rectangle."""
    yield d.replace(3, transform=Affine.translate(30, 10))
    yield d.replace(4, paint=Paint.solid(0, 0.5, 0, 0.8))
    yield d.replace(0, geometry=StrokeGeometry(width=9, join="round"))
    yield d.replace(7, path=blob(rng))
    yield d.replace(10, rule="nonzero", paint=Paint.radial(80, 60, 30, [(0, (1, 1, 0)), (1, (0, 1, 1))]))
    yield d.remove(12)
    yield d.replace(12, path=blob(rng))  # a removed shape stays removed (no paint)
    i = d.fill(blob(rng), color(rng))
    yield d.damage(i)


@pytest.mark.parametrize("canvas_type", [Canvas, Canvas8])
def test_edits_then_render_region_equal_a_fresh_render(canvas_type):
    rng = np.random.default_rng(11)
    d = build(rng)
    canvas = d.render(canvas_type(W, H), background="white")
    pixels = np.asarray(canvas)
    for dirty in edits(d, rng):
        x0, y0, x1, y1 = dirty
        assert 0 <= x0 <= x1 <= W and 0 <= y0 <= y1 <= H
        before = pixels.copy()
        d.render_region(canvas, dirty, background="white")
        fresh = np.asarray(d.render(canvas_type(W, H), background="white"))
        assert np.array_equal(pixels, fresh)
        # Only the dirty rectangle changed.
        outside = np.ones((H, W), bool)
        outside[y0:y1, x0:x1] = False
        assert np.array_equal(pixels[outside], before[outside])


def test_render_options_and_threads():
    d = build(np.random.default_rng(5))
    one = np.asarray(d.render(threads=1, tolerance=0.1))
    two = np.asarray(d.render(threads=2, tolerance=0.1))
    assert np.array_equal(one, two)
    assert not np.array_equal(one, np.asarray(d.render(antialias=False)))
    with pytest.raises(ValueError, match="canvas: 10 x 10"):
        d.render(Canvas(10, 10))
    with pytest.raises(TypeError):
        d.render(np.zeros((H, W, 4), np.float32))


def test_hit_testing():
    d = Drawing(100, 100)
    square = Path.from_svg_d("M10 10 H50 V50 H10 Z")
    a = d.fill(square, Paint.solid(1, 0, 0))
    b = d.stroke(Path.from_svg_d("M0 80 L100 80"), Paint.css("navy"), StrokeGeometry(width=4))
    c = d.fill(square, Paint.solid(0, 1, 0), Affine.translate(20, 20))
    assert (a, b, c) == (0, 1, 2) and len(d) == 3
    assert d.shape_at(15, 15) == a
    assert d.shape_at(45, 45) == c  # the topmost
    assert d.shape_at(50, 81) == b
    assert d.shape_at(50, 85) is None
    assert d.shape_at(50, 84, tolerance=3) == b
    assert d.shape_at(95, 5) is None
    assert d.shapes_in(0, 0, 100, 100) == [a, b, c]
    assert d.shapes_in(60, 60, 65, 65) == [c]
    assert d.shapes_in(0, 75, 5, 78) == [b]
    d.remove(c)
    assert d.shape_at(45, 45) == a
    with pytest.raises(IndexError):
        d.remove(3)
    with pytest.raises(ValueError, match="is not a stroke"):
        d.replace(a, geometry=StrokeGeometry())
    with pytest.raises(ValueError, match="invertible"):
        d.fill(square, Paint.solid(0, 0, 0), Affine.scale(0))


def test_canvas_buffer_is_zero_copy():
    c = Canvas(7, 5)
    a = np.asarray(c)
    assert a.shape == (5, 7, 4) and a.dtype == np.float32 and a.strides == (7 * 16, 16, 4)
    assert np.shares_memory(a, np.asarray(c))
    assert not a.any()
    a[1, 2] = [0.5, 0, 0, 0.5]  # premultiplied half-transparent red
    assert c.to_rgba8()[1, 2].tolist() == [255, 0, 0, 128]
    # Rendering into the canvas shows through the array.
    d = Drawing(7, 5)
    d.fill(Path.from_svg_d("M0 0 H7 V5 H0 Z"), Paint.solid(0, 0, 1))
    d.render(c)
    assert a[4, 6].tolist() == [0, 0, 1, 1]
    # The array keeps the canvas alive.
    del c, d
    gc.collect()
    assert a[0, 0].tolist() == [0, 0, 1, 1]
    a[0, 0] = 0


def test_canvas8_buffer_and_conversions():
    c = Canvas8(3, 2, background=(1, 1, 1, 0.5))
    a = np.asarray(c)
    assert a.shape == (2, 3, 4) and a.dtype == np.uint8 and a.strides == (12, 4, 1)
    assert a[0, 0].tolist() == [128, 128, 128, 128]
    a[0, 0] = [0, 0, 0, 255]
    assert c.to_rgba8()[0, 0].tolist() == [0, 0, 0, 255]
    assert c.to_rgba()[1, 1].tolist() == pytest.approx([1, 1, 1, 128 / 255])
    f = Canvas(3, 2, background="red")
    assert f.to_rgba8()[0, 0].tolist() == [255, 0, 0, 255]
    with pytest.raises(ValueError, match="outside the limits"):
        Canvas(20000, 10)


def test_canvas_save(tmp_path):
    c = Canvas(8, 8, background="#ff000080")
    c.save(str(tmp_path / "c.png"))
    from conftest import decode_png
    assert decode_png(tmp_path / "c.png")[0, 0].tolist() == c.to_rgba8()[0, 0].tolist()
    with pytest.raises(OSError):
        c.save(str(tmp_path))


def test_paints_and_geometry():
    p = Paint.linear(0, 0, 10, 0, [(0, (1, 0, 0)), (1, (0, 0, 1, 1))], spread="reflect")
    assert p.kind == "linear"
    p.opacity = 0.5
    assert p.opacity == 0.5
    assert Paint.css("#ff0000").color == (1, 0, 0, 1)
    with pytest.raises(ValueError):
        Paint.solid(1.5, 0, 0)
    with pytest.raises(ValueError):
        Paint.linear(0, 0, 1, 0, [(0.5, (1, 0, 0)), (0.2, (0, 0, 1))])
    with pytest.raises(ValueError):
        Paint.css("nope")
    g = StrokeGeometry(width=2, join="round", cap="square", miter_limit=10, dashes=[1, 2],
                       dash_offset=0.5)
    assert (g.width, g.join, g.cap, g.miter_limit, g.dashes, g.dash_offset) == \
        (2, "round", "square", 10, [1, 2], 0.5)
    assert "join='round'" in repr(g)
    with pytest.raises(ValueError):
        StrokeGeometry(join="sharp")
    with pytest.raises(ValueError):
        StrokeGeometry(dashes=[-1])
    with pytest.raises(TypeError):
        StrokeGeometry(2)  # keyword-only
