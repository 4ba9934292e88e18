/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Internal helpers shared by the point-set kernels of src/geometry (not installed).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace segmat {
namespace detail {

/** Axis-aligned box of the finite points (empty when there are none). */
inline Eigen::AlignedBox3d
finiteBounds(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite())
      box.extend(p);
  return box;
}

/** Lowest corner of the finite points (origin when there are none): the origin of hash cells,
 * so that meshes far from (0, 0, 0) do not overflow cell indices. */
inline Eigen::Vector3d
lowestCorner(const std::vector<Eigen::Vector3d>& points)
{
  const Eigen::AlignedBox3d box = finiteBounds(points);
  return box.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(box.min());
}

/** Starts a Delaunay call: clears the output and the message, then checks that there are at
 * least 4 points, all finite (otherwise says why). */
template <typename Output>
inline bool
startDelaunay(const std::vector<Eigen::Vector3d>& points, Output& output,
              std::string& error_message)
{
  output = Output();
  error_message.clear();
  if (points.size() < 4) {
    error_message = "fewer than 4 points";
    return false;
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) {
      error_message = "non-finite point " + std::to_string(i);
      return false;
    }
  return true;
}

} // namespace detail
} // namespace segmat
