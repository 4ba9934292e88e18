#!/usr/bin/env python3
# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""Quality against the orientation a PSB folder's meshes are given in: 1 - Rand index
(segmat_eval --psb) of segmat_mesh in its default principal-axes frame and with --input-axes, on the
meshes as stored and on copies turned by bench/shape_variants.h's someRotation(); overall and on
the two halves ids % 20 == 1 and ids % 20 == 6.
    python3 bench/psb_orientation.py [PSB_DIR] [OUT_DIR]
Uses build/bin/segmat_mesh and build/bin/segmat_eval; OUT_DIR (default out/psb-orientation)
receives the turned meshes and the predictions."""
import math
import os
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
psb = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "..", "shared", "data", "psb-dev")
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "out", "psb-orientation")
bin_dir = os.path.join(root, "build", "bin")


def axis_angle(angle, axis):
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s = math.cos(angle), math.sin(angle)
    t = 1 - c
    return [[c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t]]


def product(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


# someRotation() of bench/shape_variants.h.
rotation = product(axis_angle(0.7, (1, 2, 3)), axis_angle(-1.9, (0, 0, 1)))


def write_turned(source, target):
    lines = [l for l in open(source).read().split("\n") if l.strip() and not l.startswith("#")]
    nv, nf = map(int, lines[1].split()[:2])
    text = ["OFF", f"{nv} {nf} 0"]
    for line in lines[2:2 + nv]:
        v = [float(t) for t in line.split()[:3]]
        text.append(" ".join(repr(sum(rotation[r][k] * v[k] for k in range(3))) for r in range(3)))
    text += lines[2 + nv:2 + nv + nf]
    with open(target, "w") as f:
        f.write("\n".join(text) + "\n")


turned = os.path.join(out, "turned")
os.makedirs(os.path.join(turned, "off"), exist_ok=True)
if not os.path.exists(os.path.join(turned, "seg")):
    os.symlink(os.path.abspath(os.path.join(psb, "seg")), os.path.join(turned, "seg"))
models = sorted(int(f[:-4]) for f in os.listdir(os.path.join(psb, "off")) if f.endswith(".off"))
for m in models:
    write_turned(os.path.join(psb, "off", f"{m}.off"), os.path.join(turned, "off", f"{m}.off"))


def scores(folder, flags, name):
    pred = os.path.join(out, name)
    os.makedirs(pred, exist_ok=True)
    for m in models:
        subprocess.run([os.path.join(bin_dir, "segmat_mesh"), os.path.join(folder, "off", f"{m}.off"),
                        "-o", os.path.join(pred, str(m)), "--quiet"] + flags,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    text = subprocess.run([os.path.join(bin_dir, "segmat_eval"), "--psb", folder, "--pred", pred],
                          capture_output=True, text=True, check=True).stdout
    header = None
    ri = {}
    for line in text.splitlines():
        fields = line.split()
        if fields[:1] == ["model"]:
            header = fields
        elif header and fields and fields[0].isdigit():
            ri[int(fields[0])] = float(fields[header.index("RI")])
    mean = lambda ids: sum(ri[i] for i in ids) / len(ids)
    return (mean(models), mean([i for i in models if i % 20 == 1]),
            mean([i for i in models if i % 20 == 6]))


print(f"{len(models)} models; 1 - RI (lower is better)")
print(f"{'frame':<16} {'meshes':<8} {'all':>8} {'id%20=1':>8} {'id%20=6':>8}")
for frame, flags in (("principal axes", []), ("input axes", ["--input-axes"])):
    for meshes, folder in (("stored", psb), ("turned", turned)):
        name = f"{frame.replace(' ', '_')}_{meshes}"
        print(f"{frame:<16} {meshes:<8} " + " ".join(f"{v:8.4f}" for v in scores(folder, flags, name)))
        sys.stdout.flush()
