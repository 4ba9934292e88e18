# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""Progress on stderr: a bar redrawn in place on a terminal, one line per finished shape
otherwise (logs, Slurm output files)."""
import threading
import time


def _duration(seconds):
    seconds = int(round(seconds))
    if seconds >= 3600:
        return f"{seconds // 3600}h{seconds % 3600 // 60:02d}m"
    if seconds >= 60:
        return f"{seconds // 60}m{seconds % 60:02d}s"
    return f"{seconds}s"


class Progress:
    """done / total, failures, rate and ETA of the shapes this run segments (shapes finished by
    an earlier run count as done from the start and are left out of the rate)."""

    def __init__(self, stream, total, already_done, width=30):
        self.stream = stream
        self.total = total
        self.done = already_done
        self.already_done = already_done
        self.failed = 0
        self.width = width
        self.start = time.monotonic()
        self.tty = hasattr(stream, "isatty") and stream.isatty()
        self._lock = threading.Lock()

    def _status(self):
        elapsed = time.monotonic() - self.start
        ran = self.done - self.already_done
        rate = ran / elapsed if elapsed > 0 else 0.0
        left = self.total - self.done
        eta = _duration(left / rate) if rate > 0 else "?"
        return (f"{self.done}/{self.total} done, {self.failed} failed, "
                f"{rate * 60:.1f} shapes/min, ETA {eta}")

    def start_message(self):
        with self._lock:
            if self.already_done:
                self._line(f"segmat_batch: {self.already_done} of {self.total} shapes already "
                           "finished (kept)")

    def finished(self, record):
        with self._lock:
            self.done += 1
            if record["status"] != "ok":
                self.failed += 1
            if self.tty:
                filled = int(self.width * self.done / max(1, self.total))
                bar = "#" * filled + "-" * (self.width - filled)
                self.stream.write(f"\r[{bar}] {self._status()}\033[K")
                if record["status"] != "ok":
                    self.stream.write(f"\n  {record['name']}: {record['error']}\n")
                elif record.get("picture_error"):
                    self.stream.write(f"\n  {record['name']}: no picture: "
                                      f"{record['picture_error']}\n")
            else:
                what = "ok" if record["status"] == "ok" else "FAILED: " + record["error"]
                if record["status"] == "ok" and record.get("picture_error"):
                    what += ", no picture: " + record["picture_error"]
                self._line(f"[{self.done}/{self.total}] {record['name']} {what} "
                           f"({record['seconds']:.1f} s) | {self._status()}")
            self.stream.flush()

    def close(self):
        with self._lock:
            if self.tty:
                self.stream.write("\n")
                self.stream.flush()

    def _line(self, text):
        self.stream.write(text + "\n")
        self.stream.flush()
