/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <segmat/geometry/triangle_mesh.h>

#include <pcl/PolygonMesh.h>

namespace segmat {
namespace io {

/** \brief Converts a PCL polygon mesh into a TriangleMesh.
 *
 * Reads the x, y, z fields whatever their stored type (float, double or integer), so meshes
 * written with `property double x` keep their precision. Polygons with more than three corners
 * are fan-triangulated (v0, v_{k-1}, v_k), in order, as loadOff does.
 * \throws segmat::Error (without a path) when x, y or z is missing, a coordinate is not finite, a
 *         polygon has fewer than 3 corners or an index is out of range.
 */
TriangleMesh
fromPolygonMesh(const pcl::PolygonMesh& mesh);

/** \brief Converts a TriangleMesh into a PCL polygon mesh (PointXYZ cloud: coordinates are
 * rounded to float, as PCL stores them). */
pcl::PolygonMesh
toPolygonMesh(const TriangleMesh& mesh);

} // namespace io
} // namespace segmat
