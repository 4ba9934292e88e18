#!/usr/bin/env python3
"""What calling segmat from Python adds to the C++ time, on the psb-dev meshes.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python_overhead.py [--psb DIR] [--models 1,21] [--threads T]

Per mesh: the wall time of a full Python call (MeshSegmenter(vertices, faces).segment():
array checks and conversion, GIL release, labels handed to numpy) against the seconds of the
C++ MeshSegmentation::segment() inside it (info["cpp_seconds"]), then the same for a second
segment() with another δ0, which reuses the medial meshes and is the cheap call. Overhead =
wall / C++ - 1; the totals sum over the meshes.
"""
import argparse
import time
from pathlib import Path

import segmat

ROOT = Path(__file__).resolve().parents[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--psb", default=str(ROOT.parent / "shared" / "data" / "psb-dev"))
    parser.add_argument("--models", help="comma-separated model numbers (default: all)")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    meshes = sorted(Path(args.psb, "off").glob("*.off"), key=lambda p: int(p.stem))
    if args.models:
        wanted = set(args.models.split(","))
        meshes = [m for m in meshes if m.stem in wanted]

    print(f"{'model':>5} {'faces':>6} | {'full call s':>11} {'C++ s':>8} {'overhead':>8} | "
          f"{'re-segment s':>12} {'C++ s':>8} {'overhead':>8}")
    totals = [0.0, 0.0, 0.0, 0.0]
    for path in meshes:
        vertices, faces = segmat.load_mesh(str(path))
        start = time.perf_counter()
        segmenter = segmat.MeshSegmenter(vertices, faces, threads=args.threads)
        segmenter.segment()
        full = time.perf_counter() - start
        full_cpp = segmenter.info["cpp_seconds"]
        start = time.perf_counter()
        segmenter.segment(delta0=0.02)
        again = time.perf_counter() - start
        again_cpp = segmenter.info["cpp_seconds"]
        for i, value in enumerate((full, full_cpp, again, again_cpp)):
            totals[i] += value
        print(f"{path.stem:>5} {len(faces):>6} | {full:>11.4f} {full_cpp:>8.4f} "
              f"{100 * (full / full_cpp - 1):>7.2f}% | {again:>12.4f} {again_cpp:>8.4f} "
              f"{100 * (again / again_cpp - 1):>7.2f}%")
    print(f"{'all':>5} {len(meshes):>6} | {totals[0]:>11.3f} {totals[1]:>8.3f} "
          f"{100 * (totals[0] / totals[1] - 1):>7.2f}% | {totals[2]:>12.3f} {totals[3]:>8.3f} "
          f"{100 * (totals[2] / totals[3] - 1):>7.2f}%")


if __name__ == "__main__":
    main()
