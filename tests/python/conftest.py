"""Shared by the tests of the casteljau Python package (test_*.py here).

They need the package on PYTHONPATH (ctest sets it to the build tree's
python folder) and, for the comparisons with the command-line tool, the CLI
in CASTELJAU_CLI; tests that need what is missing are skipped, saying which.

    PYTHONPATH=build-py/python CASTELJAU_CLI=build-py/cli/casteljau \\
        /usr/bin/python3 -m pytest tests/python
"""
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
BAD_INPUT = ROOT / "tests" / "bad_input"


@pytest.fixture(scope="session")
def cli():
    """The casteljau executable (CASTELJAU_CLI), or skip."""
    path = os.environ.get("CASTELJAU_CLI", "")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("CASTELJAU_CLI does not name the casteljau executable (the reference)")
    return path


def run_cli(cli, *args, check=True):
    """Runs the CLI; returns the CompletedProcess (text)."""
    return subprocess.run([cli, *map(str, args)], capture_output=True, text=True, check=check,
                          timeout=300)


def decode_png(path):
    """An (H, W, 4) uint8 array of a PNG's straight RGBA pixels (PIL: python3-pil).
    An opaque image is written as RGB: its alpha is 255."""
    import numpy as np
    Image = pytest.importorskip("PIL.Image", reason="PIL is not installed (python3-pil)")
    with Image.open(path) as im:
        assert im.mode in ("RGBA", "RGB"), im.mode
        return np.asarray(im.convert("RGBA")).copy()
