# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""What the batch and picture tests share: the build's programs, the bundled PSB meshes, colours
of a coloured PLY, and a picture's pixels sorted by part colour."""
import os
import subprocess

from png_pixels import read_png

BIN = os.environ["SEGMAT_BIN_DIR"]
DATA = os.environ["SEGMAT_DATA_DIR"]
# Three small bundled PSB meshes (glasses, bird, bearing), with their human segmentations.
MODELS = ["41", "246", "346"]


def program(name):
    return os.path.join(BIN, name)


def run(cmd, env=None, timeout=600):
    """Runs cmd; (exit status, stdout, stderr)."""
    full_env = dict(os.environ, **(env or {}))
    p = subprocess.run(cmd, capture_output=True, text=True, env=full_env, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def make_psb_layout(folder, models=MODELS):
    """FOLDER/off/N.off and FOLDER/seg/Benchmark/N/N_k.seg, linked to data/psbN."""
    os.makedirs(os.path.join(folder, "off"))
    for n in models:
        os.symlink(os.path.join(DATA, f"psb{n}", f"{n}.off"), os.path.join(folder, "off", f"{n}.off"))
        seg = os.path.join(folder, "seg", "Benchmark", n)
        os.makedirs(seg)
        for f in sorted(os.listdir(os.path.join(DATA, f"psb{n}", "seg"))):
            os.symlink(os.path.join(DATA, f"psb{n}", "seg", f), os.path.join(seg, f))
    return folder


def read_labels(path):
    with open(path) as f:
        return [int(line) for line in f if line.strip()]


def ply_face_colors(path):
    """The face colours of an ASCII coloured PLY (segmat_mesh's), in face order."""
    with open(path) as f:
        lines = f.read().splitlines()
    end = lines.index("end_header")
    vertices = faces = 0
    for line in lines[:end]:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            vertices = int(words[2])
        elif words[:2] == ["element", "face"]:
            faces = int(words[2])
    rows = lines[end + 1 + vertices:end + 1 + vertices + faces]
    return [tuple(int(v) for v in row.split()[-3:]) for row in rows]


def label_colors(seg_path, ply_path):
    """label -> colour, as the coloured PLY paints each face of the labelling."""
    colors = {}
    for label, color in zip(read_labels(seg_path), ply_face_colors(ply_path)):
        colors.setdefault(label, color)
    return colors


def pixels_by_color(png_path, colors, background=(255, 255, 255)):
    """(width, height, shape share, {colour: pixels}): a pixel counts for colour c when it is c
    times a shade in [0.2, 1] (the renderer lights with one white light, no specular)."""
    width, height, rows = read_png(png_path)
    counts = {c: 0 for c in colors}
    covered = 0
    for row in rows:
        for p in row:
            if p == background:
                continue
            covered += 1
            for c in colors:
                top = max(c)
                shade = max(p) / top if top else 0.0
                if 0.2 <= shade <= 1.0 and all(abs(p[i] - c[i] * shade) <= 3 for i in range(3)):
                    counts[c] += 1
    return width, height, covered / (width * height), counts
