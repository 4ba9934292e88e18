# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""segmat_batch's command line: a run over a collection (or one shard of it), or a merge of shard
outputs."""
import argparse
import concurrent.futures
import ctypes
import json
import os
import shutil
import signal
import subprocess
import sys
import time

from . import inputs, progress, report, summary, worker

USAGE = """segmat_batch INPUT -o OUT [--jobs N] [--timeout SECONDS] [--max-memory MB]
                    [--shard K/N] [--no-png] [--png-size WxH] [--retry-failed] [--no-resume]
       segmat_batch --merge -o OUT SHARD_OUT..."""

DESCRIPTION = """Segments every shape of INPUT (a folder of meshes and clouds, a list file with
one PATH [TRUTH.seg ...] per line, or a PSB folder: off/N.off + seg/Benchmark/N/N_k.seg), each in
its own processes (segmat_mesh or segmat_cloud, segmat_render, segmat_eval), and writes into OUT:
NAME.seg (mesh) or NAME.labels + NAME.pcd (cloud), NAME.ply, NAME.png, shapes/NAME.json, and
summary.json, summary.csv and report.html. A rerun skips the shapes finished before (resume).
A picture that cannot be drawn does not fail its shape (the summary says why it is missing).
Exit status: 0 every shape segmented, 1 some failed (see the summary), 2 bad usage or input."""


def _parser():
    p = argparse.ArgumentParser(prog="segmat_batch", usage=USAGE, description=DESCRIPTION)
    p.add_argument("inputs", nargs="+", metavar="INPUT",
                   help="the collection; with --merge, the shard outputs")
    p.add_argument("-o", "--out", required=True, metavar="OUT", help="output folder")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                   help="shapes run at once (default: the number of cores)")
    p.add_argument("--timeout", type=float, metavar="SECONDS",
                   help="a shape still running after this fails (its programs are killed)")
    p.add_argument("--max-memory", type=float, metavar="MB",
                   help="address-space limit of each segmentation process")
    p.add_argument("--shard", metavar="K/N",
                   help="run only shapes K, K+N, K+2N, ... of the sorted collection (0 <= K < N)")
    p.add_argument("--no-png", action="store_true", help="no pictures (no segmat_render)")
    p.add_argument("--png-size", default="480x360", metavar="WxH", help="picture size")
    p.add_argument("--retry-failed", action="store_true",
                   help="run again the shapes that failed before, and those whose picture "
                        "could not be drawn (finished ones are kept)")
    p.add_argument("--no-resume", action="store_true", help="run every shape again")
    p.add_argument("--merge", action="store_true",
                   help="combine shard outputs (INPUT... are their OUT folders) into OUT")
    return p


def main(argv, bin_dir):
    args = _parser().parse_args(argv)
    try:
        if args.merge:
            return merge(args.inputs, args.out)
        if len(args.inputs) != 1:
            raise inputs.InputError("give one INPUT (several only with --merge)")
        if args.jobs < 1:
            raise inputs.InputError("--jobs must be at least 1")
        for name, value in (("--timeout", args.timeout), ("--max-memory", args.max_memory)):
            if value is not None and not value > 0:
                raise inputs.InputError(f"{name} must be > 0")
        return run(args, bin_dir)
    except inputs.InputError as e:
        print(f"segmat_batch: {e}", file=sys.stderr)
        return 2


def _programs(bin_dir, png):
    programs = {name: worker.find_program(name, bin_dir) for name in worker.PROGRAM_OVERRIDES}
    for name in ("segmat_mesh", "segmat_cloud", "segmat_eval"):
        if not programs[name]:
            raise inputs.InputError(f"{name} not found beside segmat_batch ({bin_dir}) nor on "
                                    "PATH")
    if png and not programs["segmat_render"]:
        print("segmat_batch: segmat_render not found (built only when VTK is found): no "
              "pictures", file=sys.stderr)
    return programs


def _start_xvfb():
    """With no DISPLAY, one virtual X server for every picture of the run (segmat_render would
    otherwise start one per shape); returns the process, or None. -noreset: a server that resets
    when its last client leaves drops the connections that arrive meanwhile (the next shape's)."""
    if os.environ.get("DISPLAY") or not shutil.which("Xvfb"):
        return None
    read_end, write_end = os.pipe()
    server = subprocess.Popen(
        ["Xvfb", "-displayfd", str(write_end), "-screen", "0", "2048x2048x24", "-nolisten", "tcp",
         "-noreset"],
        pass_fds=(write_end,), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL, start_new_session=True, preexec_fn=_die_with_parent)
    os.close(write_end)
    with os.fdopen(read_end) as f:
        display = f.readline().strip()
    if not display.isdigit():
        server.kill()
        server.wait()
        return None
    os.environ["DISPLAY"] = ":" + display
    return server


def _die_with_parent():
    """In the child: SIGTERM when segmat_batch dies (even killed), so no Xvfb is left behind.
    (Called before any worker thread exists.)"""
    PR_SET_PDEATHSIG = 1
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def _parse_size(text):
    w, _, h = text.partition("x")
    if not (w.isdigit() and h.isdigit() and 16 <= int(w) <= 8192 and 16 <= int(h) <= 8192):
        raise inputs.InputError(f"--png-size wants WxH (e.g. 480x360), not '{text}'")
    return text


def run(args, bin_dir):
    shapes = inputs.collect(args.inputs[0])
    shard_text = None
    if args.shard:
        k, n = inputs.parse_shard(args.shard)
        shapes = inputs.shard(shapes, k, n)
        shard_text = f"{k}/{n}"
    out = args.out
    os.makedirs(os.path.join(out, worker.RECORDS), exist_ok=True)
    worker.remove_stale_work(out)
    programs = _programs(bin_dir, not args.no_png)
    png = not args.no_png and programs["segmat_render"] is not None
    options = worker.Options(programs, args.timeout, args.max_memory, png,
                             _parse_size(args.png_size))

    todo, kept = [], []
    for shape in shapes:
        record = None if args.no_resume else worker.read_record(out, shape.name)
        redo = record and args.retry_failed and (record["status"] != "ok"
                                                 or record.get("picture_error"))
        if record and not redo:
            kept.append(record)
        else:
            todo.append(shape)

    start = time.monotonic()
    bar = progress.Progress(sys.stderr, len(shapes), len(kept))
    bar.start_message()
    runner = worker.Runner(out, options)
    xvfb = _start_xvfb() if png and todo else None
    records = list(kept)
    previous = signal.signal(signal.SIGTERM, _raise_interrupt)
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            futures = [pool.submit(runner.run_shape, s) for s in todo]
            try:
                for future in concurrent.futures.as_completed(futures):
                    record = future.result()
                    if record is not None:
                        records.append(record)
                        bar.finished(record)
            except KeyboardInterrupt:
                for f in futures:
                    f.cancel()
                runner.stop()
                bar.close()
                print(f"segmat_batch: stopped; {len(records)} of {len(shapes)} shapes finished "
                      "(run again to finish the rest)", file=sys.stderr)
                return 130
    finally:
        signal.signal(signal.SIGTERM, previous)
        if xvfb:
            xvfb.kill()
            xvfb.wait()
    bar.close()
    run_facts = {"input": os.path.abspath(args.inputs[0]), "shard": shard_text,
                 "jobs": args.jobs, "ran": len(todo), "kept": len(kept),
                 "wall_seconds": round(time.monotonic() - start, 3),
                 "finished_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
    return _finish(out, records, run_facts)


def _raise_interrupt(signum, frame):
    raise KeyboardInterrupt


def _finish(out, records, run_facts):
    result = summary.build(records, run_facts)
    summary.write(out, result)
    report.write(out, result)
    counts = result["counts"]
    if counts["pictures_failed"]:
        first = next(r for r in result["shapes"]
                     if r["status"] == "ok" and r.get("picture_error"))
        print(f"segmat_batch: {counts['pictures_failed']} segmented shapes have no picture "
              f"(first: {first['name']}: {first['picture_error']}); --retry-failed draws them "
              "again", file=sys.stderr)
    print(f"segmat_batch: {counts['ok']} of {counts['shapes']} shapes segmented, "
          f"{counts['failed']} failed; {os.path.join(out, 'report.html')}", file=sys.stderr)
    return 0 if counts["failed"] == 0 else 1


def merge(shard_dirs, out):
    """Copies every shard's per-shape outputs into OUT and writes one summary and report."""
    records = {}
    shards = []
    for shard_dir in shard_dirs:
        path = os.path.join(shard_dir, "summary.json")
        try:
            with open(path, encoding="utf-8") as f:
                shard_summary = json.load(f)
        except (OSError, ValueError) as e:
            raise inputs.InputError(f"{path}: not a finished shard output ({e})")
        shards.append({"dir": os.path.abspath(shard_dir), **shard_summary.get("run", {})})
        for record in shard_summary["shapes"]:
            if record["name"] in records:
                raise inputs.InputError(f"{shard_dir}: shape {record['name']} is also in another "
                                        "shard (shards of different splits?)")
            records[record["name"]] = record
            _copy_outputs(shard_dir, out, record)
    run_facts = {"merged": len(shard_dirs), "shards": shards,
                 "wall_seconds": max((s.get("wall_seconds") or 0) for s in shards),
                 "finished_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
    return _finish(out, list(records.values()), run_facts)


def _copy_outputs(shard_dir, out, record):
    """Copies the shape's files and record (each whole: copy to a temporary name, then rename);
    nothing to do when the shard wrote into OUT itself."""
    names = list(record.get("outputs", [])) + [os.path.join(worker.RECORDS,
                                                            record["name"] + ".json")]
    for name in names:
        source, target = os.path.join(shard_dir, name), os.path.join(out, name)
        if os.path.exists(target) and os.path.samefile(source, target):
            continue
        os.makedirs(os.path.dirname(target), exist_ok=True)
        tmp = target + ".merging"
        shutil.copyfile(source, tmp)
        os.replace(tmp, target)
