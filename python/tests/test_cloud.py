# The cloud path from Python against segmat_cloud on a cloud sampled from a psb-dev mesh.
import numpy as np
import pytest

import segmat


def test_labels_equal_the_programs_on_a_psb_dev_cloud(psb_cloud):
    points, normals, cli_labels, cli_info, _ = psb_cloud
    segmenter = segmat.CloudSegmenter(points, normals)
    labels = segmenter.segment()
    assert labels.dtype == np.int32 and labels.shape == (len(points),)
    np.testing.assert_array_equal(labels, cli_labels)
    info = segmenter.info
    for key in ("parts", "point_counts", "samples", "initial_spheres", "base_spheres",
                "structured_spheres"):
        assert info[key] == cli_info[key], key
    for key in ("sigma", "spacing", "remaining_sigma", "passes"):
        assert info["noise"][key] == pytest.approx(cli_info["noise"][key], rel=1e-8), key
    assert list(info["seconds"]) == [k for k in cli_info["seconds"] if k not in ("load", "write")]
    assert info["parts"] > 1 and segmenter.base_mat[0].shape[1] == 3


def test_other_parameters_and_the_colours(psb_cloud):
    points, normals, cli_labels, _, directory = psb_cloud
    segmenter = segmat.CloudSegmenter(points, normals)
    coarse = segmenter.segment(delta0=1.0)
    assert coarse.max() < cli_labels.max()
    # The parameters of one call do not stay for the next.
    np.testing.assert_array_equal(segmenter.segment(), cli_labels)
    # Only the first call computed the preprocessing, the medial axis and the graph.
    assert segmenter.mat_computations == 1
    # segmat_cloud's PLY: "x y z r g b" per point.
    lines = (directory / "341.ply").read_text().splitlines()
    rgb = np.array([l.split()[3:6] for l in lines[lines.index("end_header") + 1:]], dtype=float)
    np.testing.assert_array_equal(np.rint(segmat.labels_to_colors(cli_labels) * 255), rgb)


def test_segmenter_reuses_its_medial_axis(psb_cloud):
    points, normals, cli_labels, _, _ = psb_cloud
    segmenter = segmat.CloudSegmenter(points, normals)
    segmenter.segment()
    first = segmenter.info
    assert first["seconds"]["medial"] > 0 and first["seconds"]["preprocessing"] > 0
    base = segmenter.base_mat
    labels = segmenter.segment(delta0=0.03, eta=0.004, omega=0.5, visibility=False)
    again = segmenter.info
    assert segmenter.mat_computations == 1
    for stage in ("preprocessing", "medial", "graph"):
        assert again["seconds"][stage] == 0, stage
    np.testing.assert_array_equal(segmenter.base_mat[0], base[0])
    # The same labels as a fresh segmenter with those parameters.
    fresh = segmat.CloudSegmenter(points, normals)
    np.testing.assert_array_equal(
        labels, fresh.segment(delta0=0.03, eta=0.004, omega=0.5, visibility=False))
    assert fresh.info["seconds"]["medial"] > 0
