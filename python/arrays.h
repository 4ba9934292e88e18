/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// numpy arrays in and out: checks that turn bad arrays into ValueError, and outputs that hand
// their C++ storage to numpy without a copy.

#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

namespace segmat_python {

namespace py = pybind11;

/** An (n, 3) array of finite reals, n > 0, as double rows (one copy at most: a C-contiguous
 * float64 array is copied as one block). \throws py::value_error naming \a what */
std::vector<Eigen::Vector3d>
toRows3d(const py::handle& array, const char* what);

/** An (m, 3) integer array of vertex indices in [0, \a num_vertices), m > 0.
 * \throws py::value_error naming \a what */
std::vector<Eigen::Vector3i>
toFaces(const py::handle& array, std::size_t num_vertices, const char* what);

/** A mesh from (vertices, faces) arrays. */
segmat::TriangleMesh::Ptr
toMesh(const py::handle& vertices, const py::handle& faces);

/** A PCL cloud from (n, 3) points and optional (n, 3) normals (None: zero normals). */
pcl::PointCloud<pcl::PointNormal>::Ptr
toCloud(const py::handle& points, const py::handle& normals);

/** A 1-D integer array (labels) of length \a expected (0: any length > 0). */
std::vector<int>
toLabels(const py::handle& array, std::size_t expected, const char* what);

/** A 1-D int32 array that owns \a values (no copy). */
py::array_t<int>
toArray(std::vector<int>&& values);

/** (centers (n,3), radii (n,), edges (e,2), triangles (t,3)) viewing \a mat's storage, read-only;
 * the arrays keep \a mat alive. */
py::tuple
toArrays(const segmat::MedialMesh::ConstPtr& mat);

} // namespace segmat_python
