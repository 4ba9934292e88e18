/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace segmat {

/** \brief Groups points that lie within `tolerance` of each other (duplicated vertices of an
 * unwelded mesh, repeated samples).
 *
 * Points are visited in index order; a point joins the lowest-indexed earlier representative
 * within `tolerance` (Euclidean), otherwise it becomes a representative itself. The result is
 * deterministic and independent of threads. Uses a hash grid of cell size `tolerance`, O(n).
 * Non-finite points are never merged (each is its own representative).
 * \param[in] points the points
 * \param[in] tolerance merge distance; 0 merges exactly equal points only
 * \return for each point the index of its representative (itself for representatives)
 */
std::vector<int>
weldPoints(const std::vector<Eigen::Vector3d>& points, double tolerance);

} // namespace segmat
