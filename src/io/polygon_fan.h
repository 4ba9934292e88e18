/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: the one polygon triangulation every mesh reader uses.

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace io {
namespace detail {

/** \brief Appends the fan (c0, c_{k-1}, c_k), k = 2..n-1, of polygon \a corners to \a faces.
 *
 * The PSB reader triangulates this way, so a triangle-only file keeps its face order and
 * per-face `.seg` labels line up; an n-gon gives n - 2 triangles in order.
 */
template <typename Corners>
void
appendFan(std::vector<Eigen::Vector3i>& faces, const Corners& corners)
{
  for (std::size_t k = 2; k < corners.size(); ++k)
    faces.emplace_back(static_cast<int>(corners[0]), static_cast<int>(corners[k - 1]),
                       static_cast<int>(corners[k]));
}

} // namespace detail
} // namespace io
} // namespace segmat
