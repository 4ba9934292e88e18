# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""One shape of a batch: segmat's programs in child processes (isolated: a crash, a timeout or the
memory limit fails this shape only), outputs published atomically, one record per shape."""
import json
import os
import re
import shutil
import signal
import subprocess
import tempfile
import threading
import time

RECORDS = "shapes"      # OUT/shapes/NAME.json: the record, written last (the shape is finished)
WORK = ".partial"       # OUT/.partial/NAME.PID: a shape's outputs while they are made

# Environment variables that replace a program (wrappers, and the tests' crashing stand-ins).
PROGRAM_OVERRIDES = {"segmat_mesh": "SEGMAT_MESH", "segmat_cloud": "SEGMAT_CLOUD",
                     "segmat_render": "SEGMAT_RENDER", "segmat_eval": "SEGMAT_EVAL"}


def find_program(name, bin_dir):
    """The program's path: its override variable, else beside segmat_batch, else on PATH."""
    override = os.environ.get(PROGRAM_OVERRIDES[name])
    if override:
        return override
    sibling = os.path.join(bin_dir, name)
    if os.path.isfile(sibling) and os.access(sibling, os.X_OK):
        return sibling
    return shutil.which(name)


# The parallelism is across shapes (--jobs): one thread per program (--threads, and
# OMP_NUM_THREADS for OpenMP) unless the user sets OMP_NUM_THREADS; the programs would
# otherwise take every core in every job.
# (Read at each start: the runner sets DISPLAY when it starts Xvfb.)
def _child_env():
    return dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "1"))


# Terminal colour codes, which VTK's log puts around its lines.
_TERMINAL_CODES = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")
# Messages of a program that ran out of address space (C++, the loader, glibc).
_MEMORY_SIGNS = ("bad_alloc", "memory", "failed to map", "cannot allocate")


class StepFailed(Exception):
    """A program failed: the message is the shape's error."""

    def __init__(self, message, timed_out=False):
        super().__init__(message)
        self.timed_out = timed_out


class Options:
    """What every shape is run with."""

    def __init__(self, programs, timeout=None, max_memory_mb=None, png=True, png_size="480x360"):
        self.programs = programs            # name -> path (segmat_render may be None)
        self.timeout = timeout              # seconds per shape, or None
        self.max_memory_mb = max_memory_mb  # address-space limit of the segmentation, or None
        self.png = png
        self.png_size = png_size


class Runner:
    """Runs shapes; stop() kills the programs running and makes run_shape return None."""

    def __init__(self, out_dir, options):
        self.out_dir = out_dir
        self.options = options
        self._lock = threading.Lock()
        self._running = set()   # process group ids of the programs running now
        self._stopping = False

    def stop(self):
        with self._lock:
            self._stopping = True
            groups = list(self._running)
        for group in groups:
            _kill_group(group)

    def _run(self, cmd, deadline, memory_limit=False):
        """Runs cmd; returns (stdout, seconds, peak MB) or raises StepFailed with the reason."""
        program = os.path.basename(cmd[0])
        if memory_limit and self.options.max_memory_mb:
            limit = int(self.options.max_memory_mb * 1024 * 1024)
            cmd = ["prlimit", f"--as={limit}", "--"] + cmd
        with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
            start = time.monotonic()
            with self._lock:
                if self._stopping:
                    raise StepFailed("stopped")
                proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                                        start_new_session=True, env=_child_env())
                self._running.add(proc.pid)
            timed_out = threading.Event()
            timer = None
            if deadline is not None:
                def expire():
                    timed_out.set()
                    _kill_group(proc.pid)
                timer = threading.Timer(max(0.0, deadline - time.monotonic()), expire)
                timer.start()
            _, status, usage = os.wait4(proc.pid, 0)
            proc.returncode = os.waitstatus_to_exitcode(status)
            if timer:
                timer.cancel()
            with self._lock:
                self._running.discard(proc.pid)
            seconds = time.monotonic() - start
            peak_mb = usage.ru_maxrss / 1024.0
            out.seek(0)
            err.seek(0)
            stdout = out.read().decode("utf-8", "replace")
            stderr = err.read().decode("utf-8", "replace")
        if self._stopping:
            raise StepFailed("stopped")
        if timed_out.is_set():
            raise StepFailed(f"timeout: {program} still running after the shape's "
                             f"{self.options.timeout:g} s (--timeout)", timed_out=True)
        if proc.returncode == 0:
            return stdout, seconds, peak_mb
        # The reason is the last line with text, without colour codes.
        plain = _TERMINAL_CODES.sub("", stderr)
        last = [line for line in plain.strip().splitlines() if line.strip()]
        detail = last[-1].strip() if last else "no message"
        if proc.returncode < 0:
            name = signal.Signals(-proc.returncode).name
            reason = f"{program} crashed ({name})"
        else:
            reason = f"{program} failed (exit status {proc.returncode})"
        if memory_limit and self.options.max_memory_mb and (
                proc.returncode < 0 or any(sign in stderr.lower() for sign in _MEMORY_SIGNS)):
            reason += f", likely out of memory (--max-memory {self.options.max_memory_mb:g} MB)"
        return_reason = f"{reason}: {detail}"
        raise StepFailed(return_reason)

    def run_shape(self, shape):
        """Runs one shape and writes its record; returns the record, or None when stopped."""
        start = time.monotonic()
        deadline = start + self.options.timeout if self.options.timeout else None
        work = os.path.join(self.out_dir, WORK, f"{shape.name}.{os.getpid()}")
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        record = {"name": shape.name, "input": os.path.abspath(shape.path), "kind": shape.kind,
                  "category": shape.category, "status": "ok", "error": "", "picture_error": "",
                  "parts": None, "seconds": None, "stages": {}, "peak_memory_mb": None,
                  "metrics": None, "outputs": []}
        try:
            peak = self._segment(shape, work, deadline, record)
            if self.options.png:
                self._draw(shape, work, deadline, record)
            if shape.truths and shape.kind == "mesh":
                stdout, seconds, _ = self._run(
                    [self.options.programs["segmat_eval"], "--mesh", shape.path, "--pred",
                     os.path.join(work, shape.name + ".seg"), "--truth", *shape.truths, "--json"],
                    deadline)
                record["stages"]["eval"] = round(seconds, 4)
                record["metrics"] = json.loads(stdout.strip().splitlines()[-1])
            record["peak_memory_mb"] = round(peak, 1)
        except StepFailed as e:
            if self._stopping:
                shutil.rmtree(work, ignore_errors=True)
                return None
            record["status"] = "failed"
            record["error"] = self._public(str(e), work)
        except (ValueError, IndexError, KeyError) as e:  # a program printed something unexpected
            record["status"] = "failed"
            record["error"] = f"unreadable program output: {e}"
        record["seconds"] = round(time.monotonic() - start, 4)
        record["finished_at"] = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
        if record["status"] == "ok":
            for name in sorted(os.listdir(work)):
                os.replace(os.path.join(work, name), os.path.join(self.out_dir, name))
                record["outputs"].append(name)
        write_json_atomically(os.path.join(self.out_dir, RECORDS, shape.name + ".json"), record)
        shutil.rmtree(work, ignore_errors=True)
        return record

    def _public(self, message, work):
        """A program's message with its temporary output folder named as OUT, where the
        outputs go (a failed shape's never arrive there)."""
        return message.replace(work.rstrip(os.sep) + os.sep, self.out_dir.rstrip(os.sep) + os.sep)

    def _draw(self, shape, work, deadline, record):
        """segmat_render. A picture that cannot be drawn (no usable display, say) leaves the
        shape segmented, with the reason in picture_error; a timeout or a stop still ends it."""
        try:
            _, seconds, _ = self._run(
                [self.options.programs["segmat_render"], shape.path,
                 os.path.join(work, _labels_file(shape)), "-o",
                 os.path.join(work, shape.name + ".png"), "--size", self.options.png_size],
                deadline)
        except StepFailed as e:
            if self._stopping or e.timed_out:
                raise
            record["picture_error"] = self._public(str(e), work)
            return
        record["stages"]["render"] = round(seconds, 4)

    def _segment(self, shape, work, deadline, record):
        """segmat_mesh or segmat_cloud with --json; fills parts and stage seconds; returns the
        program's peak resident memory in MB (the shape's figure: pictures and scoring are
        small beside it, except VTK's fixed cost)."""
        program = "segmat_mesh" if shape.kind == "mesh" else "segmat_cloud"
        prefix = os.path.join(work, shape.name)
        stdout, seconds, peak = self._run(
            [self.options.programs[program], shape.path, "-o", prefix, "--json", "--threads",
             os.environ.get("OMP_NUM_THREADS", "1")], deadline,
            memory_limit=True)
        result = json.loads(stdout.strip().splitlines()[-1])
        record["parts"] = result["parts"]
        record["stages"].update(result.get("seconds", {}))
        # The program's wall time, start-up included (its own stages leave that out).
        record["stages"]["segment"] = round(seconds, 4)
        return peak


def _labels_file(shape):
    return shape.name + (".seg" if shape.kind == "mesh" else ".labels")


def _kill_group(group):
    try:
        os.killpg(group, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def write_json_atomically(path, value):
    """Writes JSON whole or not at all (a temporary file in the same folder, then rename)."""
    write_text_atomically(path, json.dumps(value, indent=1, sort_keys=False) + "\n")


def write_text_atomically(path, text):
    folder = os.path.dirname(path) or "."
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".")
    try:
        os.fchmod(fd, 0o644)  # mkstemp's 0600 would hide reports from a shared group
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def read_record(out_dir, name):
    """The shape's record, or None when it has none (not finished) or it is unreadable."""
    try:
        with open(os.path.join(out_dir, RECORDS, name + ".json"), encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def remove_stale_work(out_dir):
    """Removes OUT/.partial/NAME.PID folders whose process is gone (a killed run's leftovers)."""
    folder = os.path.join(out_dir, WORK)
    if not os.path.isdir(folder):
        return
    for entry in os.listdir(folder):
        pid = entry.rsplit(".", 1)[-1]
        if pid.isdigit() and (int(pid) == os.getpid() or not os.path.exists(f"/proc/{pid}")):
            shutil.rmtree(os.path.join(folder, entry), ignore_errors=True)
