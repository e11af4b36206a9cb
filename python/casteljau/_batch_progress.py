"""Progress of casteljau.batch on standard error: a live line on a terminal, a summary."""

from __future__ import annotations

import time


def format_duration(seconds):
    if seconds < 60:
        return f"{seconds:.1f} s"
    seconds = int(round(seconds))
    hours, rest = divmod(seconds, 3600)
    return f"{hours}:{rest // 60:02d}:{rest % 60:02d}"


class Progress:
    """Counts files rendered, failed and skipped. On a terminal, redraws one line (files done /
    total, files/s, time left) at most five times a second; elsewhere stays quiet until the
    summary. Messages (errors) are printed as they come, on their own lines."""

    def __init__(self, total, stream):
        self.total, self.stream = total, stream
        try:
            self.tty = stream.isatty()
        except (AttributeError, ValueError):
            self.tty = False
        self.ok = self.failed = self.skipped = self.warnings = 0
        self.note = ""
        self.started = time.monotonic()
        self._drawn = 0.0
        self._line = False

    def start(self):
        self.started = time.monotonic()

    @property
    def rendered(self):
        return self.ok + self.failed

    def rate(self):
        elapsed = time.monotonic() - self.started
        return self.rendered / elapsed if elapsed > 0 else 0.0

    def skip(self):
        self.skipped += 1
        self._maybe_draw()

    def add(self, ok, warnings=0):
        if ok:
            self.ok += 1
        else:
            self.failed += 1
        self.warnings += warnings
        self._maybe_draw()

    def message(self, text):
        self._clear()
        print(text, file=self.stream, flush=True)

    def _clear(self):
        if self._line:
            self.stream.write("\r\x1b[K")
            self._line = False

    def _maybe_draw(self):
        now = time.monotonic()
        if not self.tty or now - self._drawn < 0.2:
            return
        self._drawn = now
        done = self.rendered + self.skipped
        rate = self.rate()
        left = self.total - done
        eta = format_duration(left / rate) if rate > 0 else "?"
        line = f"{done}/{self.total} files  {rate:.1f} files/s  ETA {eta}"
        if self.failed:
            line += f"  {self.failed} failed"
        self.stream.write("\r\x1b[K" + line)
        self.stream.flush()
        self._line = True

    def summary(self, log_path, stopped=None):
        elapsed = time.monotonic() - self.started
        parts = [f"{self.ok} rendered", f"{self.failed} failed"]
        if self.skipped:
            parts.append(f"{self.skipped} skipped")
        if self.warnings:
            parts.append(f"{self.warnings} warnings")
        text = (f"batch: {self.total} files: {', '.join(parts)} in {format_duration(elapsed)} "
                f"({self.rate():.1f} files/s)")
        if self.note:
            text += f"; {self.note}"
        text += f"; log {log_path}"
        if stopped:
            text = f"{stopped}; {text}"
        return text

    def finish(self, log_path, stopped=None):
        """Prints the summary line; ``stopped`` says why the run ended early."""
        self.message(self.summary(log_path, stopped))
