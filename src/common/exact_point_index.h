/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private: nearest-point and radius queries on double points, answered exactly in double.

#include "point_kd_tree.h"

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** Nearest and radius queries over double points that answer as a scan in double would. The
 * kd-tree works in float: its answers bound the exact ones, so it is asked with a margin for
 * the rounding and its candidates are compared in double. Non-finite points are never found.
 * The points are referenced, not copied: they must outlive the index. */
class ExactPointIndex
{
public:
  explicit ExactPointIndex(const std::vector<Eigen::Vector3d>& points);

  /** The points strictly closer than \a radius to \a q, in no particular order (callers sort or
   * de-duplicate what they keep). Empty for a non-finite query or radius. */
  void within(const Eigen::Vector3d& q, double radius, std::vector<int>& out) const;

  /** The point nearest to \a q, ties to the lowest index; -1 when \a q is not finite or there
   * is no finite point. */
  int nearest(const Eigen::Vector3d& q) const;

private:
  /** \a q in float; false when that is not finite (a query beyond float's range). */
  static bool floatQuery(const Eigen::Vector3d& q, pcl::PointXYZ& p);
  /** Every point as a candidate, for queries the float tree cannot answer. */
  void takeAll() const;

  const std::vector<Eigen::Vector3d>& points_;
  PointKdTree tree_;
  double margin_ = 0.0; ///< float rounding of a point or a query, in absolute terms
  // Scratch of the float searches (the queries are const for their callers, not thread-safe).
  mutable pcl::Indices found_;
  mutable std::vector<float> sq_distances_;
};

} // namespace detail
} // namespace segmat
