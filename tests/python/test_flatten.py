"""flatten: the measured error within the tolerance, and the CLI's points."""
import json

import numpy as np
import pytest

import casteljau
from conftest import run_cli

PATHS = [
    "M0 0 C 50 100 150 -100 200 0",
    "M10 10 Q 100 200 190 10 T 370 10",
    "M50 50 A 40 20 30 1 1 120 90 Z M0 0 L 10 0 L 10 10",
    "M0 0 C 100 0 0 100 100 100 S 0 200 0 100 z",
]
METHODS = ["integral", "guided", "adaptive", "uniform", "halving"]


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("tolerance", [1.0, 0.25, 0.01])
def test_measured_error_within_tolerance(method, tolerance):
    for d in PATHS:
        points, info = casteljau.flatten(d, tolerance=tolerance, method=method)
        assert points.dtype == np.float64 and points.shape[1] == 2
        assert 0 <= info["max_error_px"] <= tolerance * (1 + 1e-9), (d, info)
        assert info["segments"] == len(points) - len(info["subpaths"])
        assert sum(s["count"] for s in info["subpaths"]) == len(points)
        assert info["method"] == method and info["tolerance"] == tolerance


@pytest.mark.parametrize("method", METHODS)
def test_points_equal_the_cli(method, cli):
    for d, tolerance in zip(PATHS, (0.5, 0.1, 0.25, 0.05)):
        out = run_cli(cli, "flatten", "--path", d, "--tolerance", tolerance, "--flatten",
                      method, "--json").stdout
        expected = json.loads(out)
        points, info = casteljau.flatten(d, tolerance=tolerance, method=method)
        assert np.array_equal(points, np.array(expected["points"], dtype=np.float64))
        assert info["segments"] == expected["segments"]
        assert info["max_error_px"] == expected["max_error_px"]
        assert info["subpaths"] == expected["subpaths"]


def test_path_and_data_agree_and_transform():
    d = PATHS[2]
    a, ia = casteljau.flatten(d)
    b, ib = casteljau.flatten(casteljau.Path.from_svg_d(d))
    assert np.array_equal(a, b) and ia == ib
    scaled, info = casteljau.flatten(d, transform=casteljau.Affine.scale(10), tolerance=0.25)
    assert info["max_error_px"] <= 0.25 and len(scaled) > len(a)


def test_uniform_segments():
    points, info = casteljau.flatten(PATHS[0], method="uniform", segments=7)
    assert info["segments"] == 7 and len(points) == 8
    with pytest.raises(ValueError, match="segments: only with method='uniform'"):
        casteljau.flatten(PATHS[0], segments=7)
    with pytest.raises(ValueError, match="segments 0"):
        casteljau.flatten(PATHS[0], method="uniform", segments=0)


def test_errors():
    with pytest.raises(ValueError, match="path data: at offset"):
        casteljau.flatten("M0 0 L 1")
    with pytest.raises(ValueError, match="tolerance 0: must be a number of device pixels"):
        casteljau.flatten(PATHS[0], tolerance=0)
    with pytest.raises(ValueError, match="method 'best'"):
        casteljau.flatten(PATHS[0], method="best")
    with pytest.raises(TypeError):
        casteljau.flatten(42)
    points, info = casteljau.flatten("")
    assert points.shape == (0, 2) and info["segments"] == 0
