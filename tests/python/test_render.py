"""render_svg and render_file: the CLI's pixels, sources, options and stats."""
import os
import pathlib
import warnings

import numpy as np
import pytest

import casteljau
from conftest import EXAMPLES, decode_png, run_cli

SVGS = sorted((EXAMPLES / "svg").glob("*.svg"))
SMALL = b'<svg xmlns="http://www.w3.org/2000/svg" width="40" height="30">' \
        b'<circle cx="20" cy="15" r="12" fill="#2a6fb0" fill-opacity="0.6"/></svg>'


def test_examples_exist():
    assert len(SVGS) >= 8


@pytest.mark.parametrize("svg", SVGS, ids=lambda p: p.stem)
@pytest.mark.parametrize("background", [None, "white"])
def test_pixels_equal_the_cli_png(svg, background, cli, tmp_path):
    out = tmp_path / "cli.png"
    args = ["render", svg, "-o", out] + (["--background", background] if background else [])
    run_cli(cli, *args)
    expected = decode_png(out)
    got = casteljau.render_svg(svg, background=background)
    assert got.dtype == np.uint8 and got.shape == expected.shape
    assert np.array_equal(got, expected)


@pytest.mark.parametrize("options, flags", [
    (dict(width=333), ["--width", "333"]),
    (dict(scale=0.5, canvas="u8"), ["--scale", "0.5", "--pixels", "u8"]),
    (dict(height=101, tolerance=0.9, method="uniform", segments=3),
     ["--height", "101", "--tolerance", "0.9", "--flatten", "uniform", "--segments", "3"]),
    (dict(antialias=False, gradient_interpolation="linear", background="#123a"),
     ["--antialias", "off", "--gradient-interpolation", "linear", "--background", "#123a"]),
])
def test_options_give_the_cli_pixels(options, flags, cli, tmp_path):
    svg = EXAMPLES / "svg" / "gradients.svg"
    out = tmp_path / "cli.png"
    run_cli(cli, "render", svg, "-o", out, *flags)
    assert np.array_equal(casteljau.render_svg(svg, **options), decode_png(out))


def test_threads_do_not_change_the_pixels():
    svg = EXAMPLES / "svg" / "dense.svg"
    one = casteljau.render_svg(svg, threads=1)
    assert np.array_equal(one, casteljau.render_svg(svg, threads=2))
    assert np.array_equal(one, casteljau.render_svg(svg))


def test_float32_rounds_to_the_u8_pixels():
    svg = EXAMPLES / "svg" / "opacity.svg"
    f = casteljau.render_svg(svg, pixels="float32")  # drawn on the float canvas (auto)
    u = casteljau.render_svg(svg, canvas="float")
    assert f.dtype == np.float32 and f.shape == u.shape
    assert f.min() >= 0 and f.max() <= 1
    # The library's rounding: round(255 v), halves away from zero.
    s = f * np.float32(255)
    t = np.trunc(s)
    assert np.array_equal((t + (s - t >= 0.5)).astype(np.uint8), u)


def test_sources_path_pathlike_text_bytes(tmp_path):
    svg = EXAMPLES / "svg" / "curves.svg"
    by_path = casteljau.render_svg(str(svg))
    assert np.array_equal(by_path, casteljau.render_svg(svg))
    assert np.array_equal(by_path, casteljau.render_svg(pathlib.PurePath(svg)))
    text = svg.read_text()
    assert np.array_equal(by_path, casteljau.render_svg("\n  " + text))
    assert np.array_equal(by_path, casteljau.render_svg(svg.read_bytes()))
    with pytest.raises(TypeError):
        casteljau.render_svg(42)


def test_size_options():
    a = casteljau.render_svg(SMALL)
    assert a.shape == (30, 40, 4)
    assert casteljau.render_svg(SMALL, width=80).shape == (60, 80, 4)
    assert casteljau.render_svg(SMALL, height=15).shape == (15, 20, 4)
    assert casteljau.render_svg(SMALL, scale=2.5).shape == (75, 100, 4)
    assert casteljau.render_svg(SMALL, background=(1, 1, 1))[0, 0].tolist() == [255] * 4


@pytest.mark.parametrize("options, message", [
    (dict(width=10, height=10), "at most one of width, height and scale"),
    (dict(width=0.5), "width 0.5: must be in"),
    (dict(scale=1e7), "scale"),
    (dict(tolerance=2), "tolerance 2: must be a number of device pixels in"),
    (dict(tolerance=float("nan")), "tolerance nan"),
    (dict(background="no-such-color"), "background 'no-such-color' is not a color"),
    (dict(background=(2, 0, 0)), "color components are in"),
    (dict(pixels="u16"), "pixels 'u16'"),
    (dict(canvas="half"), "canvas pixels 'half'"),
    (dict(method="best"), "method 'best'"),
    (dict(segments=4), "segments: only with method='uniform'"),
    (dict(threads=-1), "threads -1"),
    (dict(scale=1e6), "<bytes>: output size 40000000 x 30000000 px is outside the limits"),
    (dict(color_scheme="blue"), "color_scheme 'blue'"),
])
def test_bad_options_raise_value_error(options, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(")):
        casteljau.render_svg(SMALL, **options)


DARK = b'<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4"><style>rect { fill: #000 }' \
       b' @media (prefers-color-scheme: dark) { rect { fill: #fff } }</style>' \
       b'<rect width="4" height="4"/></svg>'


def test_color_scheme_answers_media_queries(cli, tmp_path):
    assert casteljau.render_svg(DARK)[0, 0].tolist() == [0, 0, 0, 255]
    dark = casteljau.render_svg(DARK, color_scheme="dark")
    assert dark[0, 0].tolist() == [255] * 4
    svg, out = tmp_path / "dark.svg", tmp_path / "dark.png"
    svg.write_bytes(DARK)
    run_cli(cli, "render", svg, "-o", out, "--color-scheme", "dark")
    assert np.array_equal(dark, decode_png(out))
    stats = casteljau.render_file(svg, tmp_path / "lib.png", color_scheme="dark")
    assert np.array_equal(decode_png(tmp_path / "lib.png"), dark) and stats["warnings"] == []


RESPONSIVE = b'<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4"><style>rect { fill: #000 }' \
             b' @media (max-width: 16px) { rect { fill: #fff } }</style>' \
             b'<rect width="4" height="4"/></svg>'


def test_media_width_is_the_size_drawn_at(cli, tmp_path):
    # Its own 4 px, then drawn 16 and 17 px wide: as the CLI's --width answers it.
    assert casteljau.render_svg(RESPONSIVE)[0, 0].tolist() == [255] * 4
    assert casteljau.render_svg(RESPONSIVE, width=16)[0, 0].tolist() == [255] * 4
    wide = casteljau.render_svg(RESPONSIVE, scale=4.25)
    assert wide.shape[:2] == (17, 17) and wide[0, 0].tolist() == [0, 0, 0, 255]
    svg, out = tmp_path / "responsive.svg", tmp_path / "responsive.png"
    svg.write_bytes(RESPONSIVE)
    run_cli(cli, "render", svg, "-o", out, "--width", "17")
    assert np.array_equal(wide, decode_png(out))


def test_options_are_keyword_only():
    with pytest.raises(TypeError):
        casteljau.render_svg(SMALL, 100)


def test_render_file_writes_the_cli_image(cli, tmp_path):
    svg = EXAMPLES / "svg" / "strokes.svg"
    for ext in ("png", "jpg"):
        mine, theirs = tmp_path / ("mine." + ext), tmp_path / ("cli." + ext)
        stats = casteljau.render_file(svg, mine, scale=1.5)
        run_cli(cli, "render", svg, "-o", theirs, "--scale", "1.5")
        assert mine.read_bytes() == theirs.read_bytes()
    assert stats["input"] == str(svg) and stats["output"] == str(mine)
    for key in ("width", "height", "threads", "pixels", "parse_ms", "frame_ms", "encode_ms",
                "total_ms", "warnings"):
        assert key in stats, key
    assert (stats["width"], stats["height"]) == casteljau.render_svg(svg, scale=1.5).shape[1::-1]
    assert stats["threads"] == 1 and stats["pixels"] == "u8" and stats["warnings"] == []
    assert 0 <= stats["parse_ms"] <= stats["total_ms"]
    assert stats["frame_ms"] > 0 and stats["encode_ms"] > 0


def test_render_file_u8_canvas(cli, tmp_path):
    svg = EXAMPLES / "svg" / "holes.svg"
    stats = casteljau.render_file(str(svg), str(tmp_path / "a.png"), pixels="u8", threads=2)
    run_cli(cli, "render", svg, "-o", tmp_path / "b.png", "--pixels", "u8")
    assert stats["pixels"] == "u8" and stats["threads"] == 2
    assert np.array_equal(decode_png(tmp_path / "a.png"), decode_png(tmp_path / "b.png"))


def test_render_file_replaces_atomically_and_reports_io_errors(tmp_path):
    svg = EXAMPLES / "svg" / "stars.svg"
    out = tmp_path / "out.png"
    out.write_text("precious")
    with pytest.raises(ValueError):
        casteljau.render_file(SVGS[0], out, tolerance=5)
    assert out.read_text() == "precious"
    casteljau.render_file(svg, out)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(OSError, match="is a folder"):
        casteljau.render_file(svg, tmp_path)
    with pytest.raises(OSError):
        casteljau.render_file(svg, tmp_path / "missing" / "x.png")
    with pytest.raises(OSError):
        casteljau.render_file(tmp_path / "missing.svg", tmp_path / "y.png")
    assert not [f for f in os.listdir(tmp_path) if ".tmp-" in f]


def test_warnings_are_svg_warnings():
    svg = b'<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n' \
          b'<rect width="abc" height="5" fill="red"/></svg>'
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        casteljau.render_svg(svg)
    assert len(caught) == 1 and issubclass(caught[0].category, casteljau.SvgWarning)
    assert str(caught[0].message) == \
        "<bytes>:2: <rect>: attribute width: 'abc' is not a length; ignored"
    with pytest.raises(ValueError, match="<bytes>:2: <rect>: attribute width"):
        casteljau.render_svg(svg, strict=True)


def test_docstrings():
    for name in casteljau.__all__:
        obj = getattr(casteljau, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__.strip()) > 20, name
    for cls in (casteljau.Path, casteljau.Affine, casteljau.Drawing, casteljau.Canvas,
                casteljau.Canvas8, casteljau.Paint, casteljau.StrokeGeometry):
        for attr, member in vars(cls).items():
            if not attr.startswith("_") and callable(member):
                assert member.__doc__, cls.__name__ + "." + attr
