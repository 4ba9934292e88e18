# Bad arrays and bad keywords raise clear Python exceptions; nothing crashes.
import numpy as np
import pytest

import segmat

# A tetrahedron: valid arrays that are cheap to check (the checks come before any computation).
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)


@pytest.mark.parametrize("vertices, message", [
    (V[:, :2], r"vertices: shape \(4, 2\) is not \(n, 3\)"),
    (V.ravel(), r"vertices: shape \(12,\) is not \(n, 3\)"),
    (V.astype(np.int64), "vertices: dtype int64 is not a floating-point type"),
    (np.zeros((0, 3)), "vertices: is empty"),
    (np.where(np.arange(12).reshape(4, 3) == 7, np.nan, V), "vertices: row 2 has a non-finite"),
    (np.where(np.arange(12).reshape(4, 3) == 0, np.inf, V), "vertices: row 0 has a non-finite"),
    (None, "vertices: expected an array, got None"),
    (np.array([["a", "b", "c"]]), "vertices: dtype <U1 is not a floating-point type"),
])
def test_bad_vertices(vertices, message):
    for call in (lambda: segmat.segment_mesh(vertices, F), lambda: segmat.MeshSegmenter(vertices, F),
                 lambda: segmat.medial_mesh(vertices, F)):
        with pytest.raises(ValueError, match=message):
            call()


@pytest.mark.parametrize("faces, message", [
    (F.astype(np.float64), "faces: dtype float64 is not an integer type"),
    (F[:, :2], r"faces: shape \(4, 2\) is not \(n, 3\)"),
    (np.where(F == 3, 4, F), r"faces: face 1 has vertex index 4, not in \[0, 4\)"),
    (np.where(F == 3, -1, F), r"faces: face 1 has vertex index -1, not in \[0, 4\)"),
    (np.zeros((0, 3), dtype=np.int32), "faces: is empty"),
])
def test_bad_faces(faces, message):
    with pytest.raises(ValueError, match=message):
        segmat.segment_mesh(V, faces)
    with pytest.raises(ValueError, match=message):
        segmat.psb_metrics(V, faces, np.zeros(4, dtype=np.int32), [np.zeros(4, dtype=np.int32)])


def test_layouts_that_need_a_conversion_are_accepted():
    # float32, Fortran order and a strided view all pass the checks (the mesh is read as doubles).
    for vertices in (V.astype(np.float32), np.asfortranarray(V), np.hstack([V, V])[:, ::2][:, :3]):
        scores = segmat.psb_metrics(vertices, F, np.arange(4), [np.arange(4)])
        assert scores["RI"] == 0


def test_bad_clouds():
    points = np.random.default_rng(0).random((50, 3))
    with pytest.raises(ValueError, match="normals: 49 rows for 50 points"):
        segmat.segment_cloud(points, points[:49])
    with pytest.raises(ValueError, match="normals: row 3 has a non-finite"):
        segmat.segment_cloud(points, np.where(np.arange(150).reshape(50, 3) == 9, np.nan, points))
    with pytest.raises(ValueError, match=r"points: shape \(50, 2\)"):
        segmat.CloudSegmenter(points[:, :2])


def test_bad_keywords():
    with pytest.raises(TypeError, match="unexpected keyword argument 'delta'"):
        segmat.segment_mesh(V, F, delta=0.1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'lambda'"):
        segmat.segment_cloud(V, **{"lambda": 1.0})
    with pytest.raises(TypeError, match="'threads' must be an integer"):
        segmat.segment_mesh(V, F, threads=1.5)
    with pytest.raises(TypeError, match="'delta0' must be a real number"):
        segmat.segment_mesh(V, F, delta0="0.1")
    with pytest.raises(TypeError, match="'reference_crease' must be True or False"):
        segmat.segment_mesh(V, F, reference_crease=1)
    with pytest.raises(ValueError, match="threads=-1 is out of range"):
        segmat.segment_mesh(V, F, threads=-1)
    with pytest.raises(ValueError, match="seed=1000000000000000000000000000000 is out of range"):
        segmat.segment_mesh(V, F, seed=10**30)
    # The library's own rules: δ0 > 0, η in [0, 1], bend angle in (0, 90].
    for name, value in (("delta0", -0.5), ("eta", 2.0), ("max_bend", 120.0), ("delta0", float("nan"))):
        with pytest.raises(ValueError, match=name):
            segmat.segment_mesh(V, F, **{name: value})
    segmenter = segmat.MeshSegmenter(V, F, threads=2)
    with pytest.raises(TypeError, match="'base_spheres' changes the medial step"):
        segmenter.segment(base_spheres=100)
    with pytest.raises(TypeError, match="'delta0' is a segment\\(\\) argument"):
        segmat.MeshSegmenter(V, F, delta0=0.1)
    with pytest.raises(ValueError, match="kind is 'mesh' or 'cloud'"):
        segmat.default_parameters("volume")


def test_bad_labels():
    with pytest.raises(ValueError, match="labels: 3 labels, expected 4"):
        segmat.psb_metrics(V, F, np.zeros(3, dtype=np.int32), [np.zeros(4, dtype=np.int32)])
    with pytest.raises(ValueError, match="human_labels_list is empty"):
        segmat.psb_metrics(V, F, np.zeros(4, dtype=np.int32), [])
    with pytest.raises(ValueError, match="labels: dtype float64 is not an integer type"):
        segmat.labels_to_colors(np.zeros(4))
    with pytest.raises(ValueError, match=r"labels: shape \(2, 2\) is not \(n,\)"):
        segmat.labels_to_colors(np.zeros((2, 2), dtype=np.int32))


def test_failures_of_the_library_raise_its_error(tmp_path):
    # One triangle encloses no volume: no medial axis.
    with pytest.raises(segmat.Error, match="segment_mesh\\(\\): the segmentation failed"):
        segmat.segment_mesh(V, F[:1])
    with pytest.raises(segmat.Error, match="medial mesh cannot be computed"):
        segmat.medial_mesh(V, F[:1])
    missing = tmp_path / "missing.off"
    with pytest.raises(segmat.Error, match=str(missing)):
        segmat.load_mesh(str(missing))
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(segmat.Error, match="bad.off"):
        segmat.load_mesh(str(bad))
    assert issubclass(segmat.Error, RuntimeError)
