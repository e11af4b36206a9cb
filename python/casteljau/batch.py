"""Render many SVG files to images on a Dask cluster.

Usage::

    python3 -m casteljau.batch IN_DIR_OR_LIST OUT_DIR [--workers N] [--threads-per-worker T]
        [--scheduler ADDRESS] [--resume] [--log FILE.jsonl] [--group-bytes B] [--group-files N]
        [--width W | --height H | --scale S] [--tolerance PX]
        [--flatten guided|integral|adaptive|uniform|halving] [--segments N] [--antialias on|off]
        [--gradient-interpolation srgb|linear] [--color-scheme light|dark]
        [--background COLOR] [--pixels auto|float|u8]
        [--strict] [--format png|tif|exr|jpg] [--render-threads N]

The same render as ``casteljau render IN.svg -o OUT.png`` (same options, same pixels: every
file goes through ``casteljau.render_file``), spread over the workers of a Dask distributed
cluster. Nothing here draws: the batch only lists, schedules, logs and reports.

Inputs
    ``IN_DIR_OR_LIST`` is a folder (every ``*.svg`` below it, recursively: a folder's files
    in name order, then its sub-folders), a list file (one path a line; blank lines and lines
    starting with ``#`` are ignored; relative paths are taken against the list file's
    folder), ``-`` (the list on standard input) or a pipe such as bash's ``<(find ...)``
    (relative paths against the current folder for both), or a single ``.svg`` file.

Outputs
    ``OUT_DIR/<relative path>.<format>``: the input's path relative to the folder (or to the
    list's folder), with its extension replaced; sub-folders are created as needed. A list
    entry outside the list's folder (absolute, or starting with ``..``) keeps its absolute
    path below ``OUT_DIR`` (``/data/a/b.svg`` -> ``OUT_DIR/data/a/b.png``). Each image is
    written atomically by ``render_file`` (a temporary file renamed into place): an existing
    output is only ever replaced by a complete new one.

Scheduling
    By default a ``distributed.LocalCluster`` of ``--workers N`` processes (default: the
    number of cores) with ``--threads-per-worker`` threads each (default 1), every socket
    bound to 127.0.0.1, its scratch space in a temporary folder removed at the end.
    ``--scheduler tcp://HOST:8786`` uses an existing cluster instead (``dask-scheduler`` on
    one machine, ``dask-worker tcp://HOST:8786`` on each of the others): the same command
    then runs on many machines. Tasks carry paths, not bytes: every worker must see the
    inputs and OUT_DIR under the same paths (a shared file system) and must be able to
    ``import casteljau``. Consecutive files are grouped into one task until their sizes add
    up to ``--group-bytes`` (default 256 KiB), so that thousands of icons do not each pay
    Dask's per-task cost (a few ms); a group also holds at most ``--group-files`` files
    (default: 1/16 of a worker thread's share of all the files), so that the work stays
    balanced to the end. At most 4 groups a worker thread are in flight at a time: memory
    stays flat for millions of files. Each render uses ``--render-threads`` threads
    (default 1: the parallelism comes from the workers).

Failures
    A file that cannot be drawn (``ValueError``: ``file:line: <element>: what``) or that
    cannot be read or written (``OSError``) is reported on standard error and in the log;
    the other files go on. A group whose worker died (a crash in a render) is retried file
    by file, and a file whose own task died is rerun alone at the end, so a crashing file
    takes no neighbour with it. Exit status, as the CLI's: 0 when every file was rendered,
    2 when any file could not be drawn (and for bad usage), 1 for I/O and other failures
    (2 wins over 1); 130 when interrupted. A Ctrl-C stops the run in order (the local
    workers ignore it and are closed by the client); every image written so far is
    complete, and ``--resume`` goes on from there.

Resume
    ``--resume`` skips every file whose output exists and is newer than the input and, when
    the log exists, whose last record in it says ``"ok"``; new records are appended to the
    log. When nothing is left to render, no cluster is started. Without ``--resume`` the log
    is started afresh. Render options are not compared: use a new OUT_DIR after changing
    them.

Progress and log
    On a terminal, standard error shows files done / total, files/s and the time left;
    otherwise (and at the end) one summary line. ``--log FILE`` (default
    ``OUT_DIR/batch-log.jsonl``) receives one JSON object a line for every file rendered or
    failed: the stats of ``render_file`` (``input``, ``output``, ``width``, ``height``,
    ``parse_ms``, ``frame_ms``, ``encode_ms``, ``total_ms``, ``warnings``, ...) plus ``file``
    (the relative path), ``status`` (``"ok"`` or ``"error"``), ``message`` (the error,
    or ``""``), ``kind`` (``"input"``, ``"io"`` or ``"internal"`` for errors), ``worker``
    (the Dask worker's address), ``seconds`` (wall time on the worker) and ``run`` (the
    batch's start time, to tell the runs of a resumed log apart).

The same functions are usable from Python: ``main(argv)`` returns the exit status.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import logging
import math
import os
import signal
import sys
import tempfile
import threading
import time

from casteljau._batch_inputs import UsageError, count_inputs, iter_inputs, load_done, make_groups
from casteljau._batch_progress import Progress, format_duration

DEFAULT_GROUP_BYTES = 256 * 1024
EXIT_OK, EXIT_FAILURE, EXIT_BAD_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130
_KIND_STATUS = {"input": EXIT_BAD_INPUT, "io": EXIT_FAILURE, "internal": EXIT_FAILURE}
_WINDOW_PER_THREAD = 4       # groups in flight per worker thread
_GROUPS_PER_THREAD = 16      # a group holds at most 1/16 of a thread's share of the files
_CONNECT_TIMEOUT_S = 60      # connecting to a scheduler, waiting for a worker, the probe
_CLOSE_TIMEOUT_S = 20


# --------------------------------------------------------------------------------------------
# Worker side. These functions run in the Dask workers: they import casteljau themselves.

_worker_name = None


def _worker_address():
    global _worker_name
    if _worker_name is None:
        try:
            from distributed import get_worker
            _worker_name = get_worker().address
        except Exception:  # not in a worker (a direct call, a test)
            import socket
            _worker_name = f"{socket.gethostname()}:{os.getpid()}"
    return _worker_name


def dask_setup(worker):
    """Preload of the local cluster's workers: they ignore SIGINT. A Ctrl-C at the terminal
    reaches the whole process group; the client then closes the cluster in order, instead of
    every worker dying on its own with a traceback."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


_PROBE_SVG = (b'<svg xmlns="http://www.w3.org/2000/svg" width="2" height="2">'
              b'<rect width="1" height="1"/></svg>\n')


def _probe(options, fmt):
    """Checks that a worker can import casteljau and render with ``options`` (a wrong
    --background, say, fails here once rather than for every file). Returns casteljau's path."""
    import shutil
    import casteljau
    if not hasattr(casteljau, "render_file"):
        raise ImportError(f"{casteljau.__file__} has no render_file")
    folder = tempfile.mkdtemp(prefix="casteljau-batch-probe-")
    try:
        source = os.path.join(folder, "probe.svg")
        with open(source, "wb") as f:
            f.write(_PROBE_SVG)
        casteljau.render_file(source, os.path.join(folder, "probe." + fmt), **options)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return casteljau.__file__


def render_group(items, options):
    """Renders ``items`` ((input, output, relative path) tuples) with ``render_file(**options)``;
    returns one log record (a dict) per item. Per-file failures become records, never
    exceptions, so the group goes on."""
    from casteljau import render_file

    worker = _worker_address()
    records = []
    for source, output, rel in items:
        start = time.perf_counter()
        try:
            folder = os.path.dirname(output)
            try:
                os.makedirs(folder, exist_ok=True)
            except OSError as e:  # named as render_file names its own I/O failures
                raise OSError(f"{output}: cannot write: cannot create {folder}: "
                              f"{e.strerror or e}") from None
            record = dict(render_file(source, output, **options))
            record.update(status="ok", message="")
        except ValueError as e:
            record = {"input": source, "output": output, "status": "error", "kind": "input",
                      "message": str(e)}
        except OSError as e:
            record = {"input": source, "output": output, "status": "error", "kind": "io",
                      "message": str(e) or repr(e)}
        except Exception as e:  # a bug, not the input's fault: report it, go on
            record = {"input": source, "output": output, "status": "error", "kind": "internal",
                      "message": f"{type(e).__name__}: {e}"}
        record.update(file=rel, worker=worker, seconds=round(time.perf_counter() - start, 6))
        records.append(record)
    return records


# --------------------------------------------------------------------------------------------
# Client side.

def _int_at_least(low):
    def parse(text):
        value = int(text)
        if value < low:
            raise argparse.ArgumentTypeError(f"must be at least {low}, not {value}")
        return value
    parse.__name__ = "int"
    return parse


def _ranged(kind, low, high):
    def parse(text):
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"{text} is not in [{low:g}, {high:g}]")
        return value
    parse.__name__ = kind.__name__
    return parse


def build_parser():
    summary, _usage, _synopsis, details = __doc__.split("\n\n", 3)
    p = argparse.ArgumentParser(
        prog="python3 -m casteljau.batch", description=summary, epilog=details,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("inputs", metavar="IN_DIR_OR_LIST",
                   help="a folder of SVG files, a list file (one path a line), '-' (the "
                   "list on stdin) or one .svg file")
    p.add_argument("out_dir", metavar="OUT_DIR", help="folder receiving the images")
    g = p.add_argument_group("scheduling")
    g.add_argument("--workers", type=_int_at_least(1), default=None, metavar="N",
                   help="worker processes of the local cluster (default: the number of cores; "
                   "ignored with --scheduler)")
    g.add_argument("--threads-per-worker", type=_int_at_least(1), default=1, metavar="T",
                   help="threads per worker process of the local cluster (default 1; ignored "
                   "with --scheduler)")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="an existing Dask scheduler (tcp://host:8786) instead of a local cluster")
    g.add_argument("--group-bytes", type=_int_at_least(0), default=DEFAULT_GROUP_BYTES,
                   metavar="B", help="group consecutive files into one task up to B bytes of "
                   f"input (default {DEFAULT_GROUP_BYTES}; 0: one task a file)")
    g.add_argument("--group-files", type=_int_at_least(0), default=0, metavar="N",
                   help="at most N files a task (default 0: automatic, 1/16 of a worker "
                   "thread's share)")
    g.add_argument("--resume", action="store_true",
                   help="skip files whose output is newer than the input (and logged as ok)")
    g.add_argument("--log", metavar="FILE", help="JSON Lines log (default OUT_DIR/batch-log.jsonl)")
    r = p.add_argument_group("rendering (as casteljau render)")
    size = r.add_mutually_exclusive_group()
    size.add_argument("--width", type=_ranged(float, 1, 16384), metavar="W",
                      help="output width in px (keeps the aspect ratio)")
    size.add_argument("--height", type=_ranged(float, 1, 16384), metavar="H",
                      help="output height in px (keeps the aspect ratio)")
    size.add_argument("--scale", type=_ranged(float, 1e-6, 1e6), metavar="S",
                      help="scale factor from the document size")
    r.add_argument("--tolerance", type=_ranged(float, 1e-4, 1), default=0.25, metavar="PX",
                   help="flatness bound in device pixels, in [1e-4, 1] (default 0.25)")
    r.add_argument("--flatten", choices=("guided", "integral", "adaptive", "uniform", "halving"),
                   help="flattening method (default guided)")
    r.add_argument("--segments", type=_ranged(int, 1, 1048576), metavar="N",
                   help="uniform only: segments per curve")
    r.add_argument("--antialias", choices=("on", "off"), help="on (default) or off")
    r.add_argument("--gradient-interpolation", choices=("srgb", "linear"),
                   help="srgb (default) or linear")
    r.add_argument("--color-scheme", choices=("light", "dark"),
                   help="what @media (prefers-color-scheme) sees: light (default) or dark")
    r.add_argument("--background", metavar="COLOR", help="background color (default transparent)")
    r.add_argument("--pixels", choices=("auto", "float", "u8"), default="auto",
                   help="the canvas: auto (default: u8 for 8-bit formats, float for exr and "
                        "tif), float (exact) or u8 (8 bits a channel)")
    r.add_argument("--strict", action="store_true",
                   help="the first problem in a file is an error (no image)")
    r.add_argument("--format", choices=("png", "tif", "exr", "jpg"), default="png",
                   help="output format (default png)")
    r.add_argument("--render-threads", type=_ranged(int, 1, 1024), default=1, metavar="N",
                   help="threads per render (default 1: the workers are the parallelism)")
    return p


def _render_options(args):
    """render_file's keyword arguments; those left at the CLI's default are not passed."""
    options = {"tolerance": args.tolerance, "threads": args.render_threads,
               "pixels": args.pixels, "strict": args.strict}
    for name in ("width", "height", "scale", "background", "segments"):
        value = getattr(args, name)
        if value is not None:
            options[name] = value
    if args.flatten is not None:
        options["method"] = args.flatten
    if args.antialias is not None:
        options["antialias"] = args.antialias == "on"
    if args.gradient_interpolation is not None:
        options["gradient_interpolation"] = args.gradient_interpolation
    if args.color_scheme is not None:
        options["color_scheme"] = args.color_scheme
    return options


@contextlib.contextmanager
def _connect(args):
    """Yields a connected distributed.Client; closes it (and the local cluster) on the way out."""
    import dask
    from distributed import Client, LocalCluster

    cluster = client = scratch = None
    try:
        if args.scheduler:
            client = Client(args.scheduler, timeout=_CONNECT_TIMEOUT_S)
            client.wait_for_workers(1, timeout=_CONNECT_TIMEOUT_S)
        else:
            # Every socket on the loopback interface; the workers' scratch space in a folder
            # of this run's own; the workers' log quiet but for errors (set before they start).
            scratch = tempfile.TemporaryDirectory(prefix="casteljau-batch-")
            with dask.config.set({"distributed.nanny.pre-spawn-environ.DASK_LOGGING__DISTRIBUTED":
                                  "error"}):
                cluster = LocalCluster(
                    n_workers=args.workers or os.cpu_count() or 1,
                    threads_per_worker=args.threads_per_worker, processes=True,
                    host="127.0.0.1", dashboard_address="127.0.0.1:0",
                    worker_dashboard_address="127.0.0.1:0", silence_logs=logging.ERROR,
                    local_directory=scratch.name, preload=["casteljau.batch"])
            client = Client(cluster, timeout=_CONNECT_TIMEOUT_S)
        yield client
    finally:
        if client is not None:
            with contextlib.suppress(Exception):
                client.close(timeout=_CLOSE_TIMEOUT_S)
        if cluster is not None:
            with contextlib.suppress(Exception):
                cluster.close(timeout=_CLOSE_TIMEOUT_S)
        if scratch is not None:
            with contextlib.suppress(OSError):
                scratch.cleanup()


def _check_workers(client, options, fmt):
    """Runs _probe on a worker: the package is there, the options are good."""
    try:
        client.submit(_probe, options, fmt, pure=False).result(timeout=_CONNECT_TIMEOUT_S)
        return EXIT_OK
    except ImportError as e:
        print(f"error: the workers cannot import casteljau ({e}); set PYTHONPATH for them or "
              "install the package", file=sys.stderr)
        return EXIT_FAILURE
    except ValueError as e:  # an option the library refuses: bad usage
        print(f"error: render options: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except Exception as e:
        print(f"error: the workers cannot render ({type(e).__name__}: {e})", file=sys.stderr)
        return EXIT_FAILURE


def _thread_count(client):
    return max(1, sum(client.nthreads().values()))


class _Run:
    """The client's loop: submits groups in a bounded window, collects records."""

    def __init__(self, client, options, log, progress):
        self.client, self.options, self.log, self.progress = client, options, log, progress
        self.status = EXIT_OK
        self.run_id = time.strftime("%Y-%m-%dT%H:%M:%S")
        self.serial = 0

    def _submit(self, groups):
        keys = []
        for _ in groups:
            self.serial += 1
            keys.append(f"casteljau-render-{self.run_id}-{os.getpid()}-{self.serial}")
        return self.client.map(render_group, groups, options=self.options, key=keys, pure=False)

    def _record(self, record):
        record["run"] = self.run_id
        self.log.write(_json_line(record))
        ok = record["status"] == "ok"
        if not ok:
            self.status = max(self.status, _KIND_STATUS.get(record.get("kind"), EXIT_FAILURE))
            self.progress.message(f"error: {record['message']}")
        self.progress.add(ok=ok, warnings=len(record.get("warnings", ())))

    def _failure(self, item, error):
        source, output, rel = item
        return {"input": source, "output": output, "file": rel, "status": "error",
                "kind": "internal", "worker": "", "seconds": 0.0,
                "message": f"{source}: task failed: {type(error).__name__}: {error}"}

    def _check_connected(self):
        if self.client.status != "running":
            raise ConnectionError(f"lost the Dask scheduler (client {self.client.status})")

    def _collect(self, records):
        for record in records:
            self._record(record)
        self.log.flush()

    def run(self, groups):
        from distributed import as_completed

        groups = iter(groups)
        threads = _thread_count(self.client)
        checked = time.monotonic()
        pending = {}   # future -> its items, to retry a group whose worker died
        suspects = []  # files whose task died: rerun alone at the end
        ac = as_completed()

        def refill():
            window = _WINDOW_PER_THREAD * threads
            batch = []
            while len(pending) + len(batch) < window:
                group = next(groups, None)
                if group is None:
                    break
                batch.append(group)
            if batch:
                for future, group in zip(self._submit(batch), batch):
                    pending[future] = group
                    ac.add(future)

        refill()
        while not ac.is_empty():
            future = next(ac)
            items = pending.pop(future)
            try:
                records = future.result()
            except Exception:  # the worker died (a crash in a render), or the scheduler went
                records = None
                self._check_connected()
                if len(items) > 1:  # isolate the culprit: one task a file
                    for f, item in zip(self._submit([[i] for i in items]), items):
                        pending[f] = [item]
                        ac.add(f)
                else:  # it, or a neighbour on the same worker: tell them apart at the end
                    suspects.extend(items)
            finally:
                future.release()
            if records is not None:
                self._collect(records)
            if time.monotonic() - checked > 10:  # an adaptive cluster may grow or shrink
                threads, checked = _thread_count(self.client), time.monotonic()
            if len(pending) <= _WINDOW_PER_THREAD * threads // 2:
                refill()
        for item in suspects:  # one at a time, alone on the cluster: no neighbour to kill
            future = self._submit([[item]])[0]
            try:
                records = future.result()
            except Exception as e:
                self._check_connected()
                records = [self._failure(item, e)]
            finally:
                future.release()
            self._collect(records)


def _open_log(path, append):
    """Opens the log; appending, first ends a line cut short by a killed run."""
    log = open(path, "a" if append else "w", encoding="utf-8", errors="surrogateescape")
    if append and log.tell() > 0:
        with open(path, "rb") as f:
            f.seek(-1, os.SEEK_END)
            if f.read(1) != b"\n":
                log.write("\n")
    return log


def _json_line(record):
    return json.dumps(record, separators=(", ", ": ")) + "\n"


def main(argv=None):
    args = build_parser().parse_args(argv)
    options = _render_options(args)
    log_path = args.log or os.path.join(args.out_dir, "batch-log.jsonl")
    started = time.monotonic()
    progress = None
    try:
        with contextlib.ExitStack() as stack:
            source = stack.enter_context(iter_inputs(args.inputs))
            total = count_inputs(source)
            done = load_done(log_path) if args.resume else None  # None: no log to consult
            os.makedirs(args.out_dir, exist_ok=True)
            if os.path.dirname(log_path):
                os.makedirs(os.path.dirname(log_path), exist_ok=True)
            log = stack.enter_context(_open_log(log_path, args.resume))
            if total == 0:
                print(f"batch: no SVG files in {args.inputs}", file=sys.stderr)
                return EXIT_OK
            if args.resume and next(make_groups(source, args.out_dir, args.format, 0, 1, True,
                                                done, lambda: None), None) is None:
                print(f"batch: {total} files, all up to date; log {log_path}", file=sys.stderr)
                return EXIT_OK  # without starting a cluster
            client = stack.enter_context(_connect(args))
            status = _check_workers(client, options, args.format)
            if status != EXIT_OK:
                return status
            threads = _thread_count(client)
            progress = Progress(total, sys.stderr)
            progress.note = (f"{threads} worker thread{'s' if threads != 1 else ''}, ready in "
                             f"{format_duration(time.monotonic() - started)}")
            per_group = args.group_files or max(1, math.ceil(total / (_GROUPS_PER_THREAD
                                                                      * threads)))
            groups = make_groups(source, args.out_dir, args.format, args.group_bytes, per_group,
                                 args.resume, done, progress.skip)
            run = _Run(client, options, log, progress)
            progress.start()
            run.run(groups)
            progress.finish(log_path)
            return run.status
    except UsageError as e:  # no such input, an empty list: as argparse's own errors
        print(f"error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        if progress is not None:
            progress.finish(log_path, stopped="interrupted")
        else:
            print("interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except (OSError, ValueError) as e:  # unreadable list, unwritable OUT_DIR or log, no scheduler
        if progress is not None:
            progress.finish(log_path, stopped="stopped")
        print(f"error: {e}", file=sys.stderr)
        return EXIT_FAILURE


if __name__ == "__main__":
    # Run the importable module's main, so that tasks name casteljau.batch.render_group
    # (pickled by reference, found by the workers) rather than __main__'s copy.
    from casteljau.batch import main as _main
    sys.exit(_main())
