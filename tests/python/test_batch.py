"""Tests of casteljau.batch: python3 -m casteljau.batch on a local Dask cluster.

Needs the package on PYTHONPATH (ctest sets it to the build tree's python folder), the CLI in
CASTELJAU_CLI (the reference: the batch must write the CLI's pixels), Dask distributed and PIL
(to decode the PNGs). Skips, saying which, when one is missing. About 20 s: each batch run
starts and stops a local cluster.

    PYTHONPATH=build/python CASTELJAU_CLI=build/cli/casteljau \\
        python3 -m pytest tests/python/test_batch.py
"""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "svg"
BAD = ROOT / "tests" / "bad_input" / "truncated_xml.svg"
TIMEOUT_S = 180  # one batch run; they take seconds

pytest.importorskip("distributed", reason="Dask distributed is not installed (python3-distributed)")
Image = pytest.importorskip("PIL.Image", reason="PIL is not installed (python3-pil)")
try:
    import casteljau
    from casteljau import _batch_inputs as inputs
except ImportError as e:
    pytest.skip(f"the casteljau package is not importable ({e}); set PYTHONPATH to the build "
                "tree's python folder", allow_module_level=True)
if not hasattr(casteljau, "render_file"):
    pytest.skip(f"{casteljau.__file__} has no render_file (the extension is not built)",
                allow_module_level=True)
CLI = os.environ.get("CASTELJAU_CLI", "")
if not CLI or not os.access(CLI, os.X_OK):
    pytest.skip("CASTELJAU_CLI does not name the casteljau executable (the reference renderer)",
                allow_module_level=True)


def batch(*args, cwd=None, stdin=None):
    """Runs python3 -m casteljau.batch (same interpreter, same PYTHONPATH)."""
    return subprocess.run([sys.executable, "-m", "casteljau.batch", *map(str, args)], cwd=cwd,
                          input=stdin, capture_output=True, text=True, timeout=TIMEOUT_S)


def read_log(path, lenient=False):
    records = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            try:
                records.append(json.loads(line))
            except ValueError:
                if not lenient:
                    raise
    return records


def decode(png):
    with Image.open(png) as im:
        return im.mode, im.size, im.tobytes()


def cli_pixels(svg, tmp_path):
    """The CLI's rendering of svg, decoded."""
    out = tmp_path / "reference" / (svg.stem + ".png")
    out.parent.mkdir(exist_ok=True)
    subprocess.run([CLI, "render", str(svg), "-o", str(out)], check=True, timeout=TIMEOUT_S)
    return decode(out)


def make_tree(root, layout):
    """Copies layout's sources (relative path -> source file) below root; returns root."""
    for rel, src in layout.items():
        dest = root / rel
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, dest)
    return root


def png_of(rel):
    return rel[:-len(".svg")] + ".png"


LAYOUT = {
    "curves.svg": EXAMPLES / "curves.svg",
    "a/stars.svg": EXAMPLES / "stars.svg",
    "a/b/strokes.svg": EXAMPLES / "strokes.svg",
    "a/b/gradients.svg": EXAMPLES / "gradients.svg",
    "c/broken.svg": BAD,                          # cannot be drawn: status 2
    "c/notes.txt": EXAMPLES / "make_dense.py",    # not an SVG: ignored
    "d/blocked.svg": EXAMPLES / "holes.svg",      # OUT/d is a file: cannot be written
}
GOOD = ["curves.svg", "a/stars.svg", "a/b/strokes.svg", "a/b/gradients.svg"]


def test_folder_on_two_workers_matches_cli_and_reports_failures(tmp_path):
    src = make_tree(tmp_path / "in", LAYOUT)
    out = tmp_path / "out"
    out.mkdir()
    (out / "d").write_text("in the way\n")
    run = batch(src, out, "--workers", "2")
    # A file that cannot be drawn (2) and one that cannot be written (1): 2 wins, as the CLI.
    assert run.returncode == 2, run.stderr
    assert "broken.svg:1" in run.stderr and "blocked.png" in run.stderr, run.stderr
    assert "6 files: 4 rendered, 2 failed" in run.stderr, run.stderr

    for rel in GOOD:
        png = out / png_of(rel)
        assert png.is_file(), rel
        assert decode(png) == cli_pixels(src / rel, tmp_path), f"{rel}: not the CLI's pixels"
    # Nothing else: no image for the broken file nor for notes.txt.
    assert sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()) == sorted(
        [png_of(rel) for rel in GOOD] + ["batch-log.jsonl", "d"])

    log = read_log(out / "batch-log.jsonl")
    by_file = {r["file"]: r for r in log}
    assert len(log) == 6 and sorted(by_file) == sorted(GOOD + ["c/broken.svg", "d/blocked.svg"])
    bad = by_file["c/broken.svg"]
    assert bad["status"] == "error" and bad["kind"] == "input", bad
    assert "broken.svg:1" in bad["message"] and bad["input"] == str(src / "c" / "broken.svg")
    blocked = by_file["d/blocked.svg"]
    assert blocked["status"] == "error" and blocked["kind"] == "io", blocked
    for rel in GOOD:
        r = by_file[rel]
        assert r["status"] == "ok" and r["message"] == "", r
        assert r["input"] == str(src / rel) and r["output"] == str(out / png_of(rel))
        assert r["width"] > 0 and r["height"] > 0 and r["total_ms"] > 0 and r["seconds"] > 0
        assert isinstance(r["warnings"], list)
        assert r["worker"].startswith("tcp://127.0.0.1:"), r["worker"]  # loopback only


def test_resume_skips_done_files(tmp_path):
    names = ["one.svg", "two.svg", "sub/three.svg", "sub/four.svg"]
    src = make_tree(tmp_path / "in", {n: EXAMPLES / "holes.svg" for n in names})
    out = tmp_path / "out"
    log = out / "batch-log.jsonl"
    first = batch(src, out, "--workers", "1")
    assert first.returncode == 0, first.stderr
    assert len(read_log(log)) == 4

    again = batch(src, out, "--workers", "1", "--resume")
    assert again.returncode == 0, again.stderr
    assert len(read_log(log)) == 4, "a resumed run rendered files already done"
    assert "4 files, all up to date" in again.stderr, again.stderr

    # Rendered again: an input newer than its output, a missing output, a file whose last
    # record in the log is an error. Skipped: the fourth.
    stat = os.stat(src / "one.svg")
    os.utime(src / "one.svg", ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**10))
    (out / "two.png").unlink()
    with open(log, "a", encoding="utf-8") as f:
        f.write(json.dumps({"file": "sub/three.svg", "status": "error"}) + "\n")
        f.write('{"file": "sub/fo')  # a line cut short by a killed run: ignored
    third = batch(src, out, "--workers", "1", "--resume")
    assert third.returncode == 0, third.stderr
    assert "3 rendered" in third.stderr and "1 skipped" in third.stderr, third.stderr
    records = read_log(log, lenient=True)
    assert len(records) == 4 + 1 + 3
    assert sorted(r["file"] for r in records[5:]) == ["one.svg", "sub/three.svg", "two.svg"]
    assert (out / "two.png").is_file()


def test_list_file_and_stdin(tmp_path):
    make_tree(tmp_path, {"job/x.svg": EXAMPLES / "stars.svg",
                         "job/deep/y.svg": EXAMPLES / "curves.svg",
                         "elsewhere/z.svg": EXAMPLES / "opacity.svg"})
    outside = tmp_path / "elsewhere" / "z.svg"
    listing = tmp_path / "job" / "list.txt"
    listing.write_text(f"# a comment\nx.svg\n\ndeep/y.svg\n{outside}\n", encoding="utf-8")
    out = tmp_path / "out-list"
    run = batch(listing, out, "--workers", "1", "--scale", "0.5")
    assert run.returncode == 0, run.stderr
    # Relative to the list's folder; outside it, the absolute path below OUT_DIR.
    for png in (out / "x.png", out / "deep" / "y.png",
                out / str(outside.with_suffix(".png")).lstrip(os.sep)):
        assert png.is_file(), png
    with Image.open(out / "x.png") as im:
        assert im.size == (210, 110)  # stars.svg is 420 x 220: --scale reached render_file

    out = tmp_path / "out-stdin"
    run = batch("-", out, "--workers", "1", cwd=tmp_path / "job", stdin="x.svg\ndeep/y.svg\n")
    assert run.returncode == 0, run.stderr
    assert (out / "x.png").is_file() and (out / "deep" / "y.png").is_file()
    reference = cli_pixels(tmp_path / "job" / "deep" / "y.svg", tmp_path)
    assert decode(out / "deep" / "y.png") == reference
    assert sorted(r["file"] for r in read_log(out / "batch-log.jsonl")) == ["deep/y.svg", "x.svg"]


def test_bad_usage_exits_2(tmp_path):
    run = batch(tmp_path / "nothing-here", tmp_path / "out")
    assert run.returncode == 2 and "nothing-here" in run.stderr, run.stderr
    run = batch(tmp_path, tmp_path / "out", "--tolerance", "5")
    assert run.returncode == 2 and "--tolerance" in run.stderr, run.stderr


def test_help_documents_the_options():
    run = batch("--help")
    assert run.returncode == 0
    for option in ("--workers", "--scheduler", "--resume", "--log", "--group-bytes", "--pixels",
                   "dask-worker"):
        assert option in run.stdout, option


def test_render_options_are_render_files():
    from casteljau import batch as b
    args = b.build_parser().parse_args(["in", "out", "--color-scheme", "dark", "--antialias", "off"])
    options = b._render_options(args)
    assert options["color_scheme"] == "dark" and options["antialias"] is False
    assert "color_scheme" not in b._render_options(b.build_parser().parse_args(["in", "out"]))


def test_groups_follow_bytes_and_count(tmp_path):
    sizes = [100, 100, 300, 50, 50, 50, 1000]
    for i, size in enumerate(sizes):
        (tmp_path / f"f{i}.svg").write_bytes(b" " * size)
    out = tmp_path / "o"

    def group_sizes(group_bytes, max_files):
        return [len(g) for g in inputs.make_groups(source, out, "png", group_bytes, max_files,
                                                   False, None, None)]

    with inputs.iter_inputs(str(tmp_path)) as source:
        assert inputs.count_inputs(source) == len(sizes)
        assert group_sizes(200, 10) == [2, 1, 4]  # until they reach 200 bytes
        assert group_sizes(10**6, 3) == [3, 3, 1]  # at most 3 files
        assert group_sizes(0, 10) == [1] * len(sizes)  # --group-bytes 0: one a task
        first = next(inputs.make_groups(source, out, "png", 0, 1, False, None, None))
    assert first == [(str(tmp_path / "f0.svg"), str(out / "f0.png"), "f0.svg")]
