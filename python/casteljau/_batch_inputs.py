"""Inputs of casteljau.batch: listing, output paths, resume, grouping (client side only).

Every function streams: a folder is walked, a list read, line by line, twice (once to count,
once to render), so millions of files cost no memory beyond the resume set (8 bytes of hash
per logged file)."""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import shutil
import sys
import tempfile


class UsageError(Exception):
    """The command line names no usable input."""


def _is_svg(name):
    return name.lower().endswith(".svg")


class _Folder:
    """Every *.svg below a folder, recursively: a folder's files in name order, then its
    sub-folders in name order."""

    def __init__(self, top):
        self.base = os.path.abspath(top)

    def __iter__(self):
        for folder, dirs, files in os.walk(self.base):
            dirs.sort()
            for name in sorted(files):
                if _is_svg(name):
                    path = os.path.join(folder, name)
                    yield path, os.path.relpath(path, self.base)


class _List:
    """One path a line; relative paths against ``base``; blank and '#' lines ignored."""

    def __init__(self, path, base):
        self.path, self.base = path, os.path.abspath(base)

    def __iter__(self):
        with open(self.path, encoding="utf-8", errors="surrogateescape") as f:
            for line in f:
                entry = line.strip()
                if not entry or entry.startswith("#"):
                    continue
                path = os.path.normpath(os.path.join(self.base, os.path.expanduser(entry)))
                rel = os.path.relpath(path, self.base)
                if rel == os.pardir or rel.startswith(os.pardir + os.sep):
                    rel = path.lstrip(os.sep)  # outside the list's folder: its absolute path
                yield path, rel


class _Single:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.base = os.path.dirname(self.path)

    def __iter__(self):
        yield self.path, os.path.basename(self.path)


@contextlib.contextmanager
def iter_inputs(spec):
    """Yields an iterable (iterable again and again) of (absolute input, relative path)."""
    if spec != "-" and os.path.isdir(spec):
        yield _Folder(spec)
    elif spec != "-" and os.path.isfile(spec):
        base = os.path.dirname(os.path.abspath(spec))
        yield _Single(spec) if _is_svg(spec) else _List(spec, base)
    elif spec == "-" or os.path.exists(spec):
        # Standard input or a pipe (bash's <(find ...)) can be read once: spooled to a
        # temporary file, so that the list can be read twice in flat memory. Relative paths
        # are against the current folder.
        base = os.getcwd()
        with tempfile.NamedTemporaryFile(prefix="casteljau-batch-", suffix=".txt") as tmp:
            if spec == "-" and hasattr(sys.stdin, "buffer"):
                shutil.copyfileobj(sys.stdin.buffer, tmp)
            elif spec == "-":  # a text stream put in its place (a test, an embedding)
                for line in sys.stdin:
                    tmp.write(line.encode("utf-8", "surrogateescape"))
            else:
                with open(spec, "rb") as f:
                    shutil.copyfileobj(f, tmp)
            tmp.flush()
            yield _List(tmp.name, base)
    else:
        raise UsageError(f"{spec}: no such folder or list file")


def count_inputs(source):
    return sum(1 for _ in source)


def output_path(out_dir, rel, fmt):
    return os.path.join(os.path.abspath(out_dir), os.path.splitext(rel)[0] + "." + fmt)


def _key(rel):
    return int.from_bytes(hashlib.blake2b(os.fsencode(rel), digest_size=8).digest(), "little")


def load_done(log_path):
    """The files whose last record in the log says "ok", as a set of 64-bit hashes of their
    relative paths; None when there is no log. Unreadable lines (a run killed mid-write) are
    skipped."""
    try:
        f = open(log_path, encoding="utf-8", errors="surrogateescape")
    except FileNotFoundError:
        return None
    done = set()
    with f:
        for line in f:
            try:
                record = json.loads(line)
                rel, ok = record["file"], record["status"] == "ok"
            except (ValueError, KeyError, TypeError):
                continue
            (done.add if ok else done.discard)(_key(rel))
    return done


def _up_to_date(source, output):
    try:
        return os.stat(output).st_mtime_ns > os.stat(source).st_mtime_ns
    except OSError:
        return False


def make_groups(source, out_dir, fmt, group_bytes, max_files, resume, done, on_skip):
    """Yields lists of (input, output, relative path): consecutive files until their sizes
    reach ``group_bytes`` or their number ``max_files``. With ``resume``, files whose output
    is newer than the input (and, with a ``done`` set, logged as ok) are left out and
    reported to ``on_skip()``."""
    group, size = [], 0
    for path, rel in source:
        output = output_path(out_dir, rel, fmt)
        if resume and _up_to_date(path, output) and (done is None or _key(rel) in done):
            on_skip()
            continue
        try:
            size += os.stat(path).st_size
        except OSError:
            pass  # the worker reports it
        group.append((path, output, rel))
        if size >= group_bytes or len(group) >= max_files:
            yield group
            group, size = [], 0
    if group:
        yield group
