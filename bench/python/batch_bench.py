#!/usr/bin/env python3
"""Files per second of `python3 -m casteljau.batch` against the CLI and rsvg-convert.

Generates two seeded corpora (1,000 icon-sized SVGs, 24-64 px, a few shapes each; 100
drawings the size of examples/svg/dense.svg, 1024 x 768 with 3,000 shapes each) and renders
each to PNG with:

  - the batch on a LocalCluster of 1 and of 2 worker processes (one thread each, one render
    thread each): wall time of the whole command, cluster start included, and the rate the
    batch reports for its rendering alone (start-up excluded);
  - the CLI's many-files mode, one process: `casteljau render a.svg b.svg ... -o DIR/`, with
    `--threads 1` and with its default (every core renders bands of rows);
  - a shell loop of `rsvg-convert IN -o OUT`, one file after the other, and the same loop as
    `xargs -P 2` (two at a time, as two workers).

Prints a Markdown table. Every output folder is checked to hold one PNG per input.

    PYTHONPATH=build/python python3 bench/python/batch_bench.py --cli build/cli/casteljau
    ... --group-sweep      # also: icons on 2 workers for several --group-bytes/--group-files
"""

import argparse
import math
import os
import random
import re
import shutil
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "svg"))
import make_dense  # noqa: E402  (the dense scene's generator, shared)
import tempfile
import time


def icon_svg(r):
    size = r.randrange(24, 65)
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" '
             'viewBox="0 0 24 24">']
    for _ in range(r.randrange(2, 6)):
        col = "#%02x%02x%02x" % (r.randrange(256), r.randrange(256), r.randrange(256))
        kind = r.randrange(5)
        if kind == 0:
            parts.append(f'<circle cx="{r.uniform(4, 20):.2f}" cy="{r.uniform(4, 20):.2f}" '
                         f'r="{r.uniform(2, 8):.2f}" fill="{col}"/>')
        elif kind == 1:
            w, h = r.uniform(4, 16), r.uniform(4, 16)
            parts.append(f'<rect x="{r.uniform(0, 24 - w):.2f}" y="{r.uniform(0, 24 - h):.2f}" '
                         f'width="{w:.2f}" height="{h:.2f}" rx="{r.uniform(0, 3):.2f}" '
                         f'fill="{col}" fill-opacity="{r.uniform(0.5, 1):.2f}"/>')
        elif kind == 2:
            pts = " ".join(f"{r.uniform(0, 24):.2f}" for _ in range(6))
            parts.append(f'<path d="M{r.uniform(0, 24):.2f} {r.uniform(0, 24):.2f} C{pts} Z" '
                         f'fill="{col}"/>')
        elif kind == 3:
            cx, cy, ro = r.uniform(8, 16), r.uniform(8, 16), r.uniform(4, 8)
            radii = [ro if i % 2 == 0 else ro / 2.5 for i in range(10)]
            pts = " ".join(f"{cx + q * math.cos(i * math.pi / 5):.2f},"
                           f"{cy + q * math.sin(i * math.pi / 5):.2f}" for i, q in enumerate(radii))
            parts.append(f'<polygon points="{pts}" fill="{col}"/>')
        else:
            parts.append(f'<path d="M{r.uniform(2, 8):.2f} {r.uniform(2, 22):.2f} '
                         f'Q{r.uniform(0, 24):.2f} {r.uniform(0, 24):.2f} '
                         f'{r.uniform(16, 22):.2f} {r.uniform(2, 22):.2f}" fill="none" '
                         f'stroke="{col}" stroke-width="2" stroke-linecap="round"/>')
    parts.append("</svg>\n")
    return "\n".join(parts)


def drawing_svg(r):
    """The dense example scene (examples/svg/make_dense.py) from this generator."""
    return make_dense.dense_svg(r, title=False)


def generate(folder, count, make, seed, per_folder=100):
    """count files in sub-folders of per_folder; returns the sorted list of paths."""
    r = random.Random(seed)
    paths = []
    for i in range(count):
        sub = os.path.join(folder, f"{i // per_folder:03d}")
        os.makedirs(sub, exist_ok=True)
        path = os.path.join(sub, f"f{i:05d}.svg")
        with open(path, "w", encoding="utf-8") as f:
            f.write(make(r))
        paths.append(path)
    return paths


def count_pngs(folder):
    return sum(1 for _, _, files in os.walk(folder) for f in files if f.endswith(".png"))


def timed(cmd, **kw):
    start = time.perf_counter()
    run = subprocess.run(cmd, capture_output=True, text=True, **kw)
    return time.perf_counter() - start, run


class Bench:
    def __init__(self, args, work):
        self.args, self.work, self.rows = args, work, {}

    def row(self, corpus, method, files, wall, steady=None, note=""):
        entry = self.rows.setdefault((corpus, method), [files, [], []])
        entry[1].append(wall)
        if steady:
            entry[2].append(steady)
        rate = files / wall
        extra = f"  ({steady:.1f} files/s rendering)" if steady else ""
        extra += f"  {note}" if note else ""
        print(f"  {corpus:8} {method:44} {files:5} files {wall:7.2f} s {rate:8.1f} files/s{extra}",
              file=sys.stderr, flush=True)

    def fresh(self, name):
        out = os.path.join(self.work, "out", name)
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        return out

    def check(self, out, n, what):
        got = count_pngs(out)
        if got != n:
            raise SystemExit(f"{what}: {got} PNGs written, {n} expected")

    def batch(self, corpus, src, n, workers, extra=(), label=None):
        out = self.fresh(f"{corpus}-batch-{workers}-{'-'.join(extra)}")
        cmd = [sys.executable, "-m", "casteljau.batch", src, out, "--workers", str(workers),
               *extra]
        wall, run = timed(cmd)
        if run.returncode != 0:
            raise SystemExit(f"batch failed ({run.returncode}): {run.stderr}")
        self.check(out, n, "batch")
        m = re.search(r"\(([\d.]+) files/s\)", run.stderr)
        steady = float(m.group(1)) if m else None
        ready = re.search(r"ready in ([\d.]+) s", run.stderr)
        note = f"cluster ready in {ready.group(1)} s" if ready else ""
        self.row(corpus, label or f"casteljau.batch, {workers} worker{'s' if workers > 1 else ''}",
                 n, wall, steady, note)

    def cli(self, corpus, paths, threads):
        out = self.fresh(f"{corpus}-cli-{threads}")
        cmd = [self.args.cli, "render", *paths, "-o", out + "/"]
        if threads:
            cmd += ["--threads", str(threads)]
        wall, run = timed(cmd)
        if run.returncode != 0:
            raise SystemExit(f"CLI failed ({run.returncode}): {run.stderr[-2000:]}")
        self.check(out, len(paths), "CLI")
        self.row(corpus, f"casteljau render (many files), --threads {threads or 'default'}",
                 len(paths), wall)

    def rsvg(self, corpus, paths, parallel):
        out = self.fresh(f"{corpus}-rsvg-{parallel}")
        listing = os.path.join(self.work, f"{corpus}-list.txt")
        with open(listing, "w", encoding="utf-8") as f:
            f.write("\n".join(paths) + "\n")
        convert = 'rsvg-convert "$1" -o "$0/$(basename "$1" .svg).png"'
        if parallel == 1:
            loop_body = convert.replace("$0", "$OUT")
            script = f'while read -r f; do set -- "$f"; {loop_body}; done < "$LIST"'
            cmd = ["bash", "-c", script]
        else:
            cmd = ["bash", "-c", f'xargs -P {parallel} -n 1 bash -c \'{convert}\' "$OUT" < "$LIST"']
        wall, run = timed(cmd, env=dict(os.environ, OUT=out, LIST=listing))
        if run.returncode != 0:
            raise SystemExit(f"rsvg-convert failed ({run.returncode}): {run.stderr[-2000:]}")
        self.check(out, len(paths), "rsvg-convert")
        self.row(corpus, "rsvg-convert, shell loop" if parallel == 1 else
                 f"rsvg-convert, xargs -P {parallel}", len(paths), wall)

    def table(self):
        """Medians over the rounds."""
        lines = ["| corpus | method | files | wall s | files/s (wall) | files/s (rendering) |",
                 "| --- | --- | ---: | ---: | ---: | ---: |"]
        for (corpus, method), (files, walls, steadies) in self.rows.items():
            wall = statistics.median(walls)
            steady = f"{statistics.median(steadies):.1f}" if steadies else "-"
            lines.append(f"| {corpus} | {method} | {files} | {wall:.2f} | {files / wall:.1f} | "
                         f"{steady} |")
        return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--cli", default=os.environ.get("CASTELJAU_CLI", "build/cli/casteljau"),
                   help="the casteljau executable (default: $CASTELJAU_CLI or build/cli/casteljau)")
    p.add_argument("--icons", type=int, default=1000)
    p.add_argument("--drawings", type=int, default=100)
    p.add_argument("--workers", default="1,2", help="worker counts for the batch (default 1,2)")
    p.add_argument("--work", help="folder for the corpora and outputs (default: a temporary one)")
    p.add_argument("--group-sweep", action="store_true",
                   help="also run the icons on 2 workers for several group sizes")
    p.add_argument("--only", choices=("icons", "drawings"), help="one corpus only")
    p.add_argument("--repeat", type=int, default=1, help="rounds; the table gives medians")
    args = p.parse_args()
    if not os.access(args.cli, os.X_OK):
        raise SystemExit(f"{args.cli}: not an executable (--cli)")
    try:
        import casteljau  # noqa: F401
    except ImportError as e:
        raise SystemExit(f"cannot import casteljau ({e}): set PYTHONPATH to build/python")
    if not shutil.which("rsvg-convert"):
        raise SystemExit("rsvg-convert is not installed (librsvg2-bin)")

    work = args.work or tempfile.mkdtemp(prefix="casteljau-batch-bench-")
    try:
        bench = Bench(args, work)
        corpora = []
        if args.only in (None, "icons"):
            corpora.append(("icons", generate(os.path.join(work, "icons"), args.icons,
                                              icon_svg, 1)))
        if args.only in (None, "drawings"):
            corpora.append(("drawings", generate(os.path.join(work, "drawings"), args.drawings,
                                                 drawing_svg, 2, per_folder=25)))
        for corpus, paths in corpora:
            size = sum(os.path.getsize(x) for x in paths)
            print(f"{corpus}: {len(paths)} files, {size / len(paths) / 1024:.1f} KiB each on "
                  "average", file=sys.stderr)
        for round_ in range(args.repeat):  # interleaved, so that drifting load hits all alike
            print(f"round {round_ + 1} of {args.repeat}", file=sys.stderr)
            for corpus, paths in corpora:
                src = os.path.join(work, corpus)
                for w in (int(x) for x in args.workers.split(",")):
                    bench.batch(corpus, src, len(paths), w)
                bench.cli(corpus, paths, 1)
                bench.cli(corpus, paths, 0)
                bench.rsvg(corpus, paths, 1)
                bench.rsvg(corpus, paths, 2)
                if corpus == "icons" and args.group_sweep:
                    for extra in (("--group-bytes", "0"),
                                  ("--group-bytes", "4096", "--group-files", "1000000"),
                                  ("--group-bytes", "16384", "--group-files", "1000000"),
                                  ("--group-bytes", "65536", "--group-files", "1000000"),
                                  ("--group-bytes", "262144", "--group-files", "1000000")):
                        bench.batch(corpus, src, len(paths), 2, extra,
                                    label="batch, 2 workers, " + " ".join(extra))
        load = os.getloadavg()
        print(f"\nMachine: {os.cpu_count()} cores, {platform_name()}; load average "
              f"{load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} at the end; "
              f"{time.strftime('%Y-%m-%d')}; medians of {args.repeat} round(s)\n")
        print(bench.table())
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


def platform_name():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    import platform
    return platform.processor() or platform.machine()


if __name__ == "__main__":
    main()
