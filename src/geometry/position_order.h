/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: an order of points and faces that depends on where they are, not on the
// order a file lists them in, so that re-ordered input gives the same parts.

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief The permutation that puts \a points in lexicographic order of their cell in a grid of
 * 2^-30 of their bounding box's largest side (order[k] is the input index of the k-th point).
 *
 * Cells rather than exact coordinates: points on an axis-aligned plane share a coordinate
 * exactly, and a translation or a scale rounds them apart in the last bit, which would reorder
 * them all; a cell changes only for a point within a rounding of its boundary, and the grid is
 * offset by an irrational fraction of a cell so that round coordinates (a CAD model's) are not on
 * boundaries. Points in one cell, and non-finite points (last), keep their input order.
 */
std::vector<int>
positionOrder(const std::vector<Eigen::Vector3d>& points);

/** \brief Renumbers \a mesh in position order: vertices by positionOrder(), each face's corners
 * rotated (orientation kept) to start at its smallest index, faces sorted by their corners.
 * \return face_of: face k of the result is input face face_of[k]. */
std::vector<int>
sortMeshByPosition(TriangleMesh& mesh);

} // namespace detail
} // namespace segmat
