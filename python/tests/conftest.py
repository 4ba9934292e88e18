# Shared fixtures: the bundled teddy, the command-line programs, a cloud sampled from a psb-dev mesh.
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import segmat

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "data"
PSB_DEV = ROOT.parent / "shared" / "data" / "psb-dev"
BIN = Path(os.environ.get("SEGMAT_BIN_DIR", ROOT / "build" / "bin"))


def program(name):
    path = BIN / name
    if not path.exists():
        pytest.skip(f"{path} is not built (SEGMAT_BUILD_EXAMPLES=OFF?)")
    return path


def run_program(name, *args):
    """Runs a command-line program; returns its --json output as a dict."""
    out = subprocess.run([str(program(name)), *map(str, args), "--json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def read_labels(path):
    """A .seg / .labels file: one integer per line."""
    return np.loadtxt(path, dtype=np.int64, ndmin=1)


@pytest.fixture(scope="session")
def teddy():
    return segmat.load_mesh(str(DATA / "teddy" / "teddy.off"))


@pytest.fixture(scope="session")
def teddy_cli(tmp_path_factory):
    """segmat_mesh on teddy: (labels, --json output, output prefix)."""
    prefix = tmp_path_factory.mktemp("teddy") / "teddy"
    info = run_program("segmat_mesh", DATA / "teddy" / "teddy.off", "-o", prefix)
    return read_labels(f"{prefix}.seg"), info, prefix


@pytest.fixture(scope="session")
def teddy_segmenter(teddy):
    """A MeshSegmenter on teddy that has segmented once with the defaults: (segmenter, labels,
    the info of that first call)."""
    segmenter = segmat.MeshSegmenter(*teddy)
    assert segmenter.info is None and segmenter.base_mat is None
    labels = segmenter.segment()
    return segmenter, labels, segmenter.info


def sample_surface(vertices, faces, count, seed):
    """count points uniformly on the surface (area-weighted), with their faces' unit normals."""
    rng = np.random.default_rng(seed)
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    cross = np.cross(b - a, c - a)
    area = np.linalg.norm(cross, axis=1)
    chosen = rng.choice(len(faces), size=count, p=area / area.sum())
    u, v = rng.random(count), rng.random(count)
    flip = u + v > 1.0
    u[flip], v[flip] = 1.0 - u[flip], 1.0 - v[flip]
    points = a[chosen] + u[:, None] * (b - a)[chosen] + v[:, None] * (c - a)[chosen]
    normals = cross[chosen] / area[chosen, None]
    return points, normals


@pytest.fixture(scope="session")
def psb_cloud(tmp_path_factory):
    """A cloud with normals sampled from psb-dev 341 (the smallest mesh), its .xyz file, and
    segmat_cloud's labels and --json output for that file."""
    mesh = PSB_DEV / "off" / "341.off"
    if not mesh.exists():
        pytest.skip(f"{mesh} is missing (../shared/data beside the clone)")
    points, normals = sample_surface(*segmat.load_mesh(str(mesh)), count=6000, seed=341)
    directory = tmp_path_factory.mktemp("cloud")
    xyz = directory / "341.xyz"
    # repr-exact text: the program reads the very numbers the module gets
    np.savetxt(xyz, np.hstack([points, normals]), fmt="%.17g")
    info = run_program("segmat_cloud", xyz, "-o", directory / "341")
    return points, normals, read_labels(directory / "341.labels"), info, directory
