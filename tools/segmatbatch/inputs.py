# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""The shapes of a batch: from a folder, a list file or a PSB-layout folder; sorted and sharded."""
import glob
import os
import re

MESH_EXTENSIONS = {"off", "obj", "stl"}
CLOUD_EXTENSIONS = {"pcd", "xyz", "txt"}
SHAPE_EXTENSIONS = MESH_EXTENSIONS | CLOUD_EXTENSIONS | {"ply"}

# PSB categories by model id: (id - 1) // 20, in the benchmark's order (as segmat_eval names them).
PSB_CATEGORIES = ["Human", "Cup", "Glasses", "Airplane", "Ant", "Chair", "Octopus", "Table",
                  "Teddy", "Hand", "Plier", "Fish", "Bird", "Spring", "Armadillo", "Bust", "Mech",
                  "Bearing", "Vase", "FourLeg"]


class InputError(Exception):
    """A collection that cannot be read; the message names the file and what is wrong."""


class Shape:
    """One shape of the collection: its name (file name without extension, or PSB model id),
    file, kind (mesh or cloud) and human segmentations (PSB .seg files, possibly none)."""

    def __init__(self, name, path, kind, truths=()):
        self.name = name
        self.path = path
        self.kind = kind
        self.truths = list(truths)

    @property
    def category(self):
        """PSB category of a numeric name 1..400 with human segmentations, else ""."""
        if self.truths and self.name.isdigit() and 1 <= int(self.name) <= 400:
            return PSB_CATEGORIES[(int(self.name) - 1) // 20]
        return ""


def sort_key(name):
    """Numeric names in numeric order first (PSB ids), then the others alphabetically."""
    return (0, int(name), "") if name.isdigit() else (1, 0, name)


def _extension(path):
    return os.path.splitext(path)[1][1:].lower()


def _ply_has_faces(path):
    """True when the PLY header declares at least one face (a mesh), False for a cloud."""
    try:
        with open(path, "rb") as f:
            for _ in range(200):
                line = f.readline()
                if not line or line.strip() == b"end_header":
                    break
                words = line.split()
                if len(words) == 3 and words[0] == b"element" and words[1] == b"face":
                    return int(words[2]) > 0
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: cannot read the PLY header ({e})")
    return False


def _kind(path):
    ext = _extension(path)
    if ext in MESH_EXTENSIONS:
        return "mesh"
    if ext in CLOUD_EXTENSIONS:
        return "cloud"
    if ext == "ply":
        return "mesh" if _ply_has_faces(path) else "cloud"
    raise InputError(f"{path}: not a shape file (extensions: {', '.join(sorted(SHAPE_EXTENSIONS))})")


def _numbered_truths(pattern_prefix):
    """PREFIX0.seg, PREFIX1.seg, ... in numeric order."""
    found = glob.glob(glob.escape(pattern_prefix) + "*.seg")
    numbered = []
    for path in found:
        suffix = path[len(pattern_prefix):-4]
        if suffix.isdigit():
            numbered.append((int(suffix), path))
    return [path for _, path in sorted(numbered)]


def _truths_for(folder, name):
    """Human segmentations of shape NAME in FOLDER: seg/Benchmark/NAME/NAME_k.seg (PSB) or
    seg/NAME_k.seg (segmat's data/ folders)."""
    for prefix in (os.path.join(folder, "seg", "Benchmark", name, name + "_"),
                   os.path.join(folder, "seg", name + "_")):
        truths = _numbered_truths(prefix)
        if truths:
            return truths
    return []


def _from_files(paths, folder_for_truths=None):
    shapes = {}
    for path in paths:
        name = os.path.splitext(os.path.basename(path))[0]
        if name in shapes:
            raise InputError(f"{path}: same name '{name}' as {shapes[name].path} (outputs would "
                             "collide)")
        truths = _truths_for(folder_for_truths, name) if folder_for_truths else []
        shapes[name] = Shape(name, path, _kind(path), truths)
    return shapes


def _from_list(list_path):
    """A text file: one shape per line, `PATH [TRUTH.seg ...]`, paths relative to the list's
    folder; blank lines and `#` comments are skipped."""
    base = os.path.dirname(os.path.abspath(list_path))
    shapes = {}
    with open(list_path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            paths = [w if os.path.isabs(w) else os.path.join(base, w) for w in words]
            for p in paths:
                if not os.path.isfile(p):
                    raise InputError(f"{list_path}:{number}: no such file {p}")
            found = _from_files(paths[:1])
            (name, shape), = found.items()
            if name in shapes:
                raise InputError(f"{list_path}:{number}: same name '{name}' as "
                                 f"{shapes[name].path}")
            shape.truths = paths[1:]
            shapes[name] = shape
    return shapes


def collect(input_path):
    """Every shape of INPUT, sorted by sort_key. A PSB layout is a folder with off/ (meshes
    off/N.off; humans in seg/Benchmark/N/N_k.seg); any other folder is read flat (its shape
    files; humans in seg/); a file is a list."""
    if os.path.isfile(input_path):
        shapes = _from_list(input_path)
    elif os.path.isdir(os.path.join(input_path, "off")):
        meshes = glob.glob(os.path.join(glob.escape(input_path), "off", "*.off"))
        shapes = _from_files(sorted(meshes), input_path)
    elif os.path.isdir(input_path):
        files = [os.path.join(input_path, f) for f in sorted(os.listdir(input_path))
                 if _extension(f) in SHAPE_EXTENSIONS
                 and os.path.isfile(os.path.join(input_path, f))]
        shapes = _from_files(files, input_path)
    else:
        raise InputError(f"{input_path}: no such file or folder")
    if not shapes:
        raise InputError(f"{input_path}: no shape found (extensions: "
                         f"{', '.join(sorted(SHAPE_EXTENSIONS))})")
    return [shapes[n] for n in sorted(shapes, key=sort_key)]


def parse_shard(text):
    """'K/N' with 0 <= K < N -> (K, N)."""
    m = re.fullmatch(r"(\d+)/(\d+)", text or "")
    if not m or int(m.group(2)) < 1 or int(m.group(1)) >= int(m.group(2)):
        raise InputError(f"--shard wants K/N with 0 <= K < N (e.g. 0/4), not '{text}'")
    return int(m.group(1)), int(m.group(2))


def shard(shapes, k, n):
    """Shapes k, k + n, k + 2n, ... of the sorted list: every shape in exactly one of the n
    shards, and each shard a spread of the collection (PSB categories differ in cost)."""
    return shapes[k::n]
