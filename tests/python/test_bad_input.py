"""The bad-input corpus (tests/bad_input) through the Python API: ValueError
with the CLI's message for what cannot be drawn, a result with its one
warning for what the specs say how to recover from (ValueError with
strict=True), OSError for what cannot be read or written; never a crash.

The tables of expected messages, and the generated files, are those of
tests/bad_input/bad_input_test.py (read from its source, so the two cannot
drift apart).
"""
import ast
import base64
import os
import re
import struct
import warnings
import zlib

import numpy as np
import pytest

import casteljau
from conftest import BAD_INPUT

PATCH_EXTENSIONS = (".bpt", ".map", ".json")


def corpus_tables():
    """BAD, RECOVERED and generate_bad (with the functions it calls) from
    bad_input_test.py, without running it."""
    tree = ast.parse((BAD_INPUT / "bad_input_test.py").read_text())
    keep = [n for n in tree.body
            if (isinstance(n, ast.Assign)
                and any(getattr(t, "id", "") in ("BAD", "RECOVERED", "BAD_BOUNDS", "GIB")
                        for t in n.targets))
            or (isinstance(n, ast.FunctionDef)
                and n.name in ("generate_bad", "content_bomb", "png_header_only"))]
    namespace = {"os": os, "base64": base64, "struct": struct, "zlib": zlib}
    exec(compile(ast.Module(body=keep, type_ignores=[]), "bad_input_test.py", "exec"), namespace)
    return (namespace["BAD"], namespace["RECOVERED"], namespace["BAD_BOUNDS"],
            namespace["generate_bad"])


BAD, RECOVERED, BAD_BOUNDS, generate_bad = corpus_tables()


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    folder = tmp_path_factory.mktemp("generated")
    generate_bad(str(folder))
    return folder


def source(name, generated):
    path = BAD_INPUT / name
    return path if path.exists() else generated / name


def located(name, message):
    return re.escape(name) + ":" + message


# The content bombs (BAD_BOUNDS: seconds each, building up to the element
# limit) run in the CLI's test only: through Python they add time, not cover.
@pytest.mark.parametrize("name", sorted(set(BAD) - set(BAD_BOUNDS)))
def test_refused_with_the_cli_message(name, generated, tmp_path):
    src = source(name, generated)
    where = located(os.path.basename(src), BAD[name])
    if name.endswith(PATCH_EXTENSIONS):
        for method in ("adaptive", "uniform"):
            with pytest.raises(ValueError) as e:
                casteljau.tessellate(src, method=method)
            assert re.search(where, str(e.value)), str(e.value)
        return
    with pytest.raises(ValueError) as e:
        casteljau.render_svg(src)
    assert re.search(where, str(e.value)), str(e.value)
    # The same document as text and as bytes (the name is then <string> or <bytes>).
    data = src.read_bytes()
    if len(data) < (1 << 20):
        with pytest.raises(ValueError, match=BAD[name]):
            casteljau.render_svg(data)
    out = tmp_path / "kept.png"
    out.write_text("precious")
    with pytest.raises(ValueError) as e:
        casteljau.render_file(src, out)
    assert re.search(where, str(e.value)), str(e.value)
    assert out.read_text() == "precious"
    assert not [f for f in os.listdir(tmp_path) if ".tmp-" in f]


@pytest.mark.parametrize("name", sorted(RECOVERED))
def test_recovered_with_one_warning(name, generated, tmp_path):
    src = source(name, generated)
    where = located(str(src), RECOVERED[name])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        image = casteljau.render_svg(src)
    assert image.ndim == 3 and image.shape[2] == 4
    assert len(caught) == 1, [str(w.message) for w in caught]
    assert caught[0].category is casteljau.SvgWarning
    assert re.search(where, str(caught[0].message)), str(caught[0].message)
    stats = casteljau.render_file(src, tmp_path / "drawn.png")
    assert len(stats["warnings"]) == 1 and re.search(where, stats["warnings"][0])
    assert (tmp_path / "drawn.png").stat().st_size > 0
    # With strict=True, that problem is the error.
    with pytest.raises(ValueError) as e:
        casteljau.render_svg(src, strict=True)
    assert re.search(where, str(e.value)), str(e.value)
    with pytest.raises(ValueError):
        casteljau.render_file(src, tmp_path / "strict.png", strict=True)
    assert not (tmp_path / "strict.png").exists()


@pytest.mark.parametrize("name", sorted(f for f in os.listdir(BAD_INPUT)
                                         if f.endswith((".svg",) + PATCH_EXTENSIONS)))
def test_every_corpus_file_gives_a_result_or_an_error(name):
    """Every file in the folder, in the tables or not: a result or ValueError."""
    src = BAD_INPUT / name
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if name.endswith(PATCH_EXTENSIONS):
                vertices, triangles, st = casteljau.tessellate(src, width=200, height=150)
                assert vertices.shape[1] == 3 and triangles.shape[1] == 3
            else:
                assert casteljau.render_svg(src).ndim == 3
    except ValueError as e:
        assert str(e).startswith(str(src) + ":"), str(e)


def test_unreadable_input_is_an_os_error(tmp_path):
    missing = tmp_path / "missing.svg"
    with pytest.raises(OSError):
        casteljau.render_svg(missing)
    with pytest.raises(OSError):
        casteljau.render_file(missing, tmp_path / "x.png")
    with pytest.raises(OSError):
        casteljau.tessellate(tmp_path / "missing.bpt")
    with pytest.raises(OSError):
        casteljau.render_svg(tmp_path)  # a folder


def test_hostile_text_never_crashes():
    """Truncations of a valid document at every 7th byte, and garbage."""
    text = (BAD_INPUT.parent.parent / "examples" / "svg" / "gradients.svg").read_bytes()
    for n in range(0, len(text), 7):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                casteljau.render_svg(text[:n])
        except ValueError:
            pass
    for junk in (b"", b"\x00\xff" * 100, "<svg>\u2603</svg>", b"<svg width='1e999'/>",
                 b"<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><path d='M0 0 "
                 b"L1e308 1e308 L-1e308 1 Z' stroke='red' stroke-width='3'/></svg>"):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                casteljau.render_svg(junk)
        except ValueError:
            pass


def test_bad_patch_arrays():
    grid = np.zeros((4, 4, 3))
    grid[..., 0], grid[..., 1] = np.meshgrid(np.arange(4), np.arange(4))
    with pytest.raises(ValueError, match="no patches"):
        casteljau.tessellate([])
    with pytest.raises(ValueError, match=r"patches\[1\]: expected"):
        casteljau.tessellate([grid, np.zeros((5, 4, 3))])
    bad = grid.copy()
    bad[0, 0, 2] = np.nan
    with pytest.raises(ValueError, match="finite"):
        casteljau.tessellate([bad])
    with pytest.raises(ValueError, match="tolerance 0.001"):
        casteljau.tessellate([grid], tolerance=0.001)
    with pytest.raises(ValueError, match="steps 2000"):
        casteljau.tessellate([grid], method="uniform", steps=2000)
    with pytest.raises(ValueError, match="steps: only with method='uniform'"):
        casteljau.tessellate([grid], steps=4)
    with pytest.raises(TypeError):
        casteljau.tessellate(42)
