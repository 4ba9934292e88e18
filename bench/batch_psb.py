#!/usr/bin/env python3
# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""segmat_batch's wall time and overhead over a PSB folder, and its metrics against
segmat_eval --psb on the same predictions (scripts/eval_psb.sh's scoring):
    python3 bench/batch_psb.py JOBS [PSB_DIR] [OUT_DIR]
Runs `segmat_batch PSB_DIR -o OUT_DIR --jobs JOBS --no-resume` from build/bin. Prints the load
average before and after (the machine may be shared), the wall time, the sum of the per-shape
times and the runner's overhead = wall * JOBS / sum - 1 (for JOBS > 1 it also holds idle
time at the end of the run)."""
import json
import os
import subprocess
import sys
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
jobs = int(sys.argv[1])
psb = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "..", "shared", "data", "psb-dev")
out = sys.argv[3] if len(sys.argv) > 3 else os.path.join(root, "out", f"batch-psb-jobs{jobs}")
bin_dir = os.path.join(root, "build", "bin")

print(f"load average before: {open('/proc/loadavg').read().split()[:3]}")
start = time.monotonic()
status = subprocess.run([os.path.join(bin_dir, "segmat_batch"), psb, "-o", out, "--jobs",
                         str(jobs), "--no-resume"], stderr=subprocess.DEVNULL).returncode
wall = time.monotonic() - start
print(f"load average after: {open('/proc/loadavg').read().split()[:3]}")
with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f)
shapes = summary["shapes"]
per_shape = sum(s["seconds"] for s in shapes)
segment = sum(s["stages"].get("segment", 0.0) for s in shapes)
print(f"segmat_batch --jobs {jobs}: exit status {status}, {summary['counts']['ok']} of "
      f"{len(shapes)} shapes segmented")
print(f"wall time (whole command): {wall:.1f} s")
print(f"sum of per-shape times: {per_shape:.1f} s (segmentation programs alone: {segment:.1f} s)")
print(f"runner overhead (wall x jobs / sum - 1): {100 * (wall * jobs / per_shape - 1):.1f} %")

reference = json.loads(subprocess.run(
    [os.path.join(bin_dir, "segmat_eval"), "--psb", psb, "--pred", out, "--json"],
    capture_output=True, text=True, check=True).stdout)
worst = 0.0
for key in ("RI", "CD", "HD", "GCE", "LCE"):
    worst = max(worst, abs(summary["overall"][key] - reference["overall"][key]))
    for name, scores in reference["categories"].items():
        worst = max(worst, abs(summary["categories"][name][key] - scores[key]))
print("overall " + "  ".join(f"{k} {summary['overall'][k]:.4f}" for k in
                             ("RI", "CD", "HD", "GCE", "LCE")))
print(f"largest difference to segmat_eval --psb (overall and per category): {worst:.2e}")
