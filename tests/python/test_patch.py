"""tessellate: files and control grids to arrays, as `casteljau patch` tessellates."""
import json

import numpy as np
import pytest

import casteljau
from conftest import EXAMPLES, run_cli

PATCHES = sorted(p for p in (EXAMPLES / "patch").iterdir() if p.suffix in (".bpt", ".map", ".json"))


def check_mesh(vertices, triangles, st):
    assert vertices.dtype == np.float64 and vertices.shape[1] == 3
    assert triangles.dtype == np.int64 and triangles.shape[1] == 3
    assert st.dtype == np.float64 and st.shape == (len(vertices), 2)
    assert len(triangles) > 0 and triangles.min() >= 0 and triangles.max() < len(vertices)


def edge_use(triangles):
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                    triangles[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return counts


@pytest.mark.parametrize("path", PATCHES, ids=lambda p: p.name)
@pytest.mark.parametrize("method", ["adaptive", "uniform"])
def test_files_match_the_cli(path, method, cli, tmp_path):
    out = run_cli(cli, "patch", path, "-o", tmp_path / "p.png", "--tessellate", method,
                  "--width", 320, "--height", 240, "--stats", "-").stdout
    expected = json.loads(out)
    vertices, triangles, st, info = casteljau.tessellate(
        path, method=method, width=320, height=240, return_info=True)
    check_mesh(vertices, triangles, st)
    assert info["triangles"] == expected["triangles"] == len(triangles)
    assert info["vertices"] == expected["vertices"] == len(vertices)
    assert info["max_error_px"] == expected["max_error_px"]
    assert info["patches"] == expected["patches"]
    assert info["max_error_px"] <= 0.25 + 1e-9
    assert info["normals"].shape == vertices.shape


def test_control_grids():
    # A bicubic bump and a bilinear quad sharing nothing: two patches.
    u, v = np.meshgrid(np.linspace(0, 3, 4), np.linspace(0, 3, 4))
    bump = np.dstack([u, v, np.where((u % 3) * (v % 3) > 0, 2.0, 0.0)])
    quad = np.array([[[5, 0, 0, 0, 0], [6, 0, 0, 1, 0]], [[5, 1, 0, 0, 1], [6, 1, 1, 1, 1]]],
                    dtype=float)
    vertices, triangles, st, info = casteljau.tessellate([bump, quad], tolerance=0.1,
                                                         return_info=True)
    check_mesh(vertices, triangles, st)
    assert info["patches"] == 2 and info["max_error_px"] <= 0.1 + 1e-9
    # Default texture coordinates are the grid's own parameters, in [0, 1].
    assert st.min() == 0 and st.max() == 1
    # The bump's corners are on the mesh.
    for corner in ([0, 0, 0], [3, 3, 0], [6, 1, 1]):
        assert np.any(np.all(vertices == corner, axis=1)), corner


def test_uniform_steps_and_watertightness():
    path = EXAMPLES / "patch" / "wave.bpt"
    vertices, triangles, st = casteljau.tessellate(path, method="uniform", steps=8)
    check_mesh(vertices, triangles, st)
    patches = casteljau.tessellate(path, method="uniform", steps=1, return_info=True)[3]["patches"]
    assert len(triangles) == patches * 8 * 8 * 2
    # Adaptive meshes are watertight: every edge is used by one or two triangles.
    _, triangles, _ = casteljau.tessellate(path)
    assert edge_use(triangles).max() <= 2


def test_view_changes_the_adaptive_mesh():
    path = EXAMPLES / "patch" / "pipe.map"
    a = casteljau.tessellate(path)[1]
    b = casteljau.tessellate(path, view=(120, 60))[1]
    assert len(a) != len(b)
    with pytest.raises(ValueError, match="view"):
        casteljau.tessellate(path, view=(400, 0))
