# The mesh path from Python against segmat_mesh, and the segmenter's reuse of its medial meshes.
import numpy as np
import pytest

import segmat
from conftest import DATA, read_labels, run_program


def test_labels_equal_the_programs_on_teddy(teddy, teddy_cli, teddy_segmenter):
    cli_labels, cli_info, _ = teddy_cli
    labels = segmat.segment_mesh(*teddy)
    assert labels.dtype == np.int32 and labels.shape == (len(teddy[1]),)
    np.testing.assert_array_equal(labels, cli_labels)
    # The segmenter's first call is the same computation.
    np.testing.assert_array_equal(teddy_segmenter[1], cli_labels)


def test_info_is_the_programs_json(teddy_cli, teddy_segmenter):
    _, cli_info, _ = teddy_cli
    info = teddy_segmenter[2]
    for key in ("parts", "face_counts", "mat_computed", "samples", "initial_spheres",
                "base_spheres", "structured_spheres"):
        assert info[key] == cli_info[key], key
    # Teddy is clean: nothing smoothed, nothing left.
    assert info["noise"] == {"sigma": pytest.approx(cli_info["noise"]["sigma"], rel=1e-5),
                             "remaining_sigma": 0.0, "passes": 0}
    assert cli_info["noise"]["remaining_sigma"] == 0 and cli_info["noise"]["passes"] == 0
    # The program adds its file stages around the library's.
    assert list(info["seconds"]) == [k for k in cli_info["seconds"] if k not in ("load", "write")]
    assert info["cpp_seconds"] >= sum(info["seconds"].values())


def test_segmenter_reuses_its_medial_meshes(teddy_cli, teddy_segmenter):
    segmenter, first, first_info = teddy_segmenter
    assert first_info["mat_computations"] == 1 and first_info["seconds"]["mat"] > 0
    base = segmenter.base_mat
    coarse = segmenter.segment(delta0=1.0)
    assert segmenter.mat_computations == 1
    assert segmenter.info["seconds"]["mat"] == 0 and segmenter.info["mat_computations"] == 1
    assert segmenter.base_mat[0] is not base[0]
    np.testing.assert_array_equal(segmenter.base_mat[0], base[0])
    # A far larger growing threshold lets regions grow across parts.
    assert 1 <= coarse.max() + 1 < first.max() + 1
    # Parameters not given are the defaults again, not the previous call's.
    np.testing.assert_array_equal(segmenter.segment(), teddy_cli[0])
    assert segmenter.parameters["delta0"] == segmat.default_parameters()["delta0"]


def test_other_parameters_equal_the_programs(teddy, teddy_segmenter, tmp_path):
    segmenter = teddy_segmenter[0]
    labels = segmenter.segment(delta0=0.03, eta=0.004)
    run_program("segmat_mesh", DATA / "teddy" / "teddy.off", "-o", tmp_path / "t",
                "-g", 0.03, "-n", 0.004)
    np.testing.assert_array_equal(labels, read_labels(tmp_path / "t.seg"))


def test_min_part_drops_parts_below_its_share(teddy, teddy_segmenter):
    segmenter = teddy_segmenter[0]
    assert segmat.default_parameters()["min_part"] == 0.002
    # Teddy's head, body and limbs each hold less than a third of its area: with a minimal
    # share of a third, at most two parts can keep theirs (the largest one always stays).
    labels = segmenter.segment(min_part=0.34)
    area = np.linalg.norm(np.cross(teddy[0][teddy[1][:, 1]] - teddy[0][teddy[1][:, 0]],
                                   teddy[0][teddy[1][:, 2]] - teddy[0][teddy[1][:, 0]]), axis=1)
    shares = np.bincount(labels, weights=area) / area.sum()
    assert 1 <= len(shares) <= 2 and (shares >= 0.34).all()


def test_medial_mesh_is_the_segmenters(teddy, teddy_segmenter):
    segmenter = teddy_segmenter[0]
    centers, radii, edges, triangles = segmat.medial_mesh(*teddy)
    expected = segmenter.base_mat
    assert centers.shape == (2000, 3) and radii.shape == (2000,)
    assert edges.shape[1] == 2 and triangles.shape[1] == 3
    for got, want in zip((centers, radii, edges, triangles), expected):
        np.testing.assert_array_equal(got, want)
    assert (radii > 0).all() and edges.max() < 2000 and not centers.flags.writeable
    assert len(segmenter.structured_mat[0]) == segmenter.info["structured_spheres"]


def test_psb_metrics_equal_the_programs(teddy, teddy_cli, tmp_path):
    labels = teddy_cli[0]
    seg_dir = DATA / "teddy" / "seg"
    truths = sorted(seg_dir.glob("*.seg"))[:3]
    np.savetxt(tmp_path / "pred.seg", labels, fmt="%d")
    cli = run_program("segmat_eval", "--mesh", DATA / "teddy" / "teddy.off",
                      "--pred", tmp_path / "pred.seg", "--truth", *truths)
    scores = segmat.psb_metrics(*teddy, labels, [read_labels(t) for t in truths])
    assert scores["count"] == 3 and len(scores["per_reference"]) == 3
    flat = {k: v for k, v in cli.items() if isinstance(v, (int, float))}
    assert flat, cli
    for key, value in flat.items():
        if key in scores:
            assert scores[key] == pytest.approx(value, rel=1e-5, abs=1e-6), key
    # Against itself a segmentation scores zero everywhere.
    same = segmat.psb_metrics(*teddy, labels, [labels])
    assert same["RI"] == 0 and same["HD"] == 0 and same["GCE"] == 0 and same["CD"] == 0


def test_labels_to_colors_are_the_programs_colours(teddy, teddy_cli):
    labels, _, prefix = teddy_cli
    colors = segmat.labels_to_colors(labels)
    assert colors.shape == (len(labels), 3) and colors.dtype == np.float64
    # segmat_mesh's PLY: the vertices, then "3 a b c r g b" per face.
    lines = open(f"{prefix}.ply").read().splitlines()
    body = lines[lines.index("end_header") + 1:]
    faces = np.array([l.split() for l in body[len(teddy[0]):]], dtype=np.int64)
    np.testing.assert_array_equal(np.rint(colors * 255), faces[:, 4:7])
    assert len({tuple(c) for c in colors}) == labels.max() + 1
    assert (segmat.labels_to_colors(np.array([-1])) == 0).all()
