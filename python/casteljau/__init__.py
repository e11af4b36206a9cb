"""Casteljau: exact curve flattening, stroking, antialiased SVG rendering and
surface tessellation, from Python.

The C++ library does all the work (the extension module
``casteljau._casteljau``); this package adds no rendering of its own. The
GIL is released while parsing, rendering, flattening and tessellating, so
Python threads render in parallel.

Rendering SVG::

    import casteljau
    rgba = casteljau.render_svg("drawing.svg", width=512)        # (H, W, 4) uint8
    stats = casteljau.render_file("drawing.svg", "drawing.png")  # as the CLI writes it

Geometry and drawing::

    p = casteljau.Path.from_svg_d("M0 0 C 50 100 150 -100 200 0")
    points, info = casteljau.flatten(p, tolerance=0.1)
    d = casteljau.Drawing(256, 256)
    d.fill(p, casteljau.Paint.solid(0.8, 0.2, 0.1), casteljau.Affine.translate(20, 100))
    canvas = d.render()                 # a Canvas; numpy.asarray(canvas) shares its memory

Surfaces::

    vertices, triangles, st = casteljau.tessellate("teapot.bpt", tolerance=0.25)

Errors: input that cannot be used raises ValueError with the command-line
tool's message ("file:line: <element>: what"); files that cannot be read or
written raise OSError.
"""
import os as _os
import warnings as _warnings

from . import _casteljau
from ._casteljau import (
    CLOSE,
    CONIC,
    CUBIC,
    LINE,
    MOVE,
    QUAD,
    Affine,
    Canvas,
    Canvas8,
    Drawing,
    Paint,
    Path,
    PathArrays,
    StrokeGeometry,
    flatten,
    tessellate,
)

__all__ = [
    "Affine", "Canvas", "Canvas8", "Drawing", "Paint", "Path", "PathArrays", "StrokeGeometry",
    "SvgWarning", "flatten", "render_file", "render_svg", "tessellate",
    "MOVE", "LINE", "QUAD", "CUBIC", "CONIC", "CLOSE",
]
__version__ = "0.1.0"


class SvgWarning(UserWarning):
    """A problem in an SVG file that was recovered from as the SVG and CSS specs
    say (an invalid value ignored, path data drawn up to its error): the
    message is the CLI's warning, "file:line: <element>: what"."""


def _source(source):
    """(path, text, name) for render_svg's source argument."""
    if isinstance(source, bytes):
        return None, source, "<bytes>"
    if isinstance(source, str):
        if source.lstrip().startswith("<"):
            return None, source.encode("utf-8"), "<string>"
        return source, None, source
    if isinstance(source, _os.PathLike):
        path = _os.fsdecode(source)
        return path, None, path
    raise TypeError("render_svg: source must be a path (str or os.PathLike), SVG text (str) "
                    "or bytes, not %s" % type(source).__name__)


def render_svg(source, *, width=None, height=None, scale=None, background=None,
               tolerance=0.25, threads=0, pixels="u8", strict=False, canvas="auto",
               method="guided", segments=None, antialias=True, gradient_interpolation="srgb",
               color_scheme="light"):
    """Renders an SVG document to a NumPy array of straight RGBA pixels.

    source: a path (str or os.PathLike), SVG text (a str whose first non-blank
    character is '<') or bytes.

    The pixels are exactly those of the CLI's PNG (``casteljau render IN -o
    OUT.png`` with the same options): the same reader, output size, renderer
    and 8-bit conversion.

    Keyword-only options (the CLI's):
      width, height, scale: at most one; the output size from the document's
        (width or height keep the aspect ratio). Limits: 16384 px a side,
        2^26 pixels.
      background: None (transparent), a CSS color string or an (r, g, b[, a])
        tuple in [0, 1].
      tolerance: flatness bound in device pixels, in [1e-4, 1] (0.25).
      threads: threads rendering bands of rows (0: every core); the pixels do
        not depend on it.
      pixels: the array's dtype: "u8" (uint8, as the PNG) or "float32"
        (straight RGBA in [0, 1], before 8-bit rounding).
      strict: the first problem in the file is an error (ValueError) instead
        of a warning and the specs' recovery.
      canvas: the canvas drawn on, as the CLI's --pixels: "auto" (the default:
        "u8" for u8 arrays, as the CLI's PNG, "float" for float32 ones),
        "float" (exact) or "u8" (8 bits a channel, as Cairo and Skia draw).
      method, segments: the flattening method ("guided", the default,
        "integral", "adaptive", "uniform", "halving") and, for "uniform",
        segments per curve.
      antialias: exact-area coverage (True) or pixel centres (False).
      gradient_interpolation: "srgb" (SVG 1.1) or "linear" (linear light).
      color_scheme: what style sheets' @media (prefers-color-scheme) see:
        "light" (the default) or "dark".

    Returns an (H, W, 4) numpy array. Each recovered problem in the file is
    issued as an SvgWarning. Raises ValueError with the CLI's message
    ("file:line: <element>: what") for a document that cannot be drawn or an
    option out of range, OSError for a file that cannot be read.
    """
    path, text, name = _source(source)
    array, warnings = _casteljau._render_svg(
        path, text, name, width=width, height=height, scale=scale, background=background,
        tolerance=tolerance, threads=threads, pixels=pixels, canvas=canvas, strict=strict,
        method=method, segments=segments, antialias=antialias,
        gradient_interpolation=gradient_interpolation, color_scheme=color_scheme)
    for text in warnings:
        _warnings.warn(text, SvgWarning, stacklevel=2)
    return array


def render_file(source_path, output_path, *, width=None, height=None, scale=None,
                background=None, tolerance=0.25, threads=1, pixels="auto", strict=False,
                method="guided", segments=None, antialias=True, gradient_interpolation="srgb",
                color_scheme="light"):
    """Renders an SVG file to an image file, as ``casteljau render IN -o OUT``.

    The format follows output_path's extension (png, tif, exr, jpg), and the
    file is written atomically (a complete new file replaces an existing one,
    or nothing is written). Options as render_svg's, except:
      threads: 1 by default (a batch runs files in parallel instead);
      pixels: the canvas drawn on, as the CLI's --pixels: "auto" (the default:
        "u8" for 8-bit files, "float" for EXR and TIFF), "float" or "u8".

    Returns a dict: input, output, width, height, threads, pixels, parse_ms,
    frame_ms (one render of the parsed scene), encode_ms, total_ms and
    warnings (a list of "file:line: <element>: what" strings, the problems
    recovered from). Raises ValueError with the CLI's message for a file that
    cannot be drawn (or any problem, with strict=True) or an option out of
    range, OSError when the input cannot be read or the output written.
    """
    return _casteljau._render_file(
        _os.fsdecode(source_path), _os.fsdecode(output_path), width=width, height=height,
        scale=scale, background=background, tolerance=tolerance, threads=threads,
        pixels=pixels, strict=strict, method=method, segments=segments, antialias=antialias,
        gradient_interpolation=gradient_interpolation, color_scheme=color_scheme)
