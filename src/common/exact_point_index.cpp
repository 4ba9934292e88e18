/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "exact_point_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace segmat {
namespace detail {

ExactPointIndex::ExactPointIndex(const std::vector<Eigen::Vector3d>& points) : points_(points)
{
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z())));
    if (p.allFinite()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  cloud->is_dense = false; // the tree leaves non-finite points out
  tree_.setSortedResults(false);
  tree_.setInputCloud(cloud);
  // Float rounding moves a coordinate by up to ~6e-8 of its magnitude; the extent term covers
  // the tree's own float distance arithmetic.
  if (hi.allFinite() && lo.allFinite() && (hi - lo).minCoeff() >= 0.0)
    margin_ = 1e-5 * (hi - lo).norm() +
              1e-6 * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) + 1e-12;
}

void
ExactPointIndex::within(const Eigen::Vector3d& q, double radius, std::vector<int>& out) const
{
  out.clear();
  if (!(radius > 0.0) || !std::isfinite(radius) || !q.allFinite() || points_.empty())
    return; // a non-finite ball contains nothing (and PCL asserts on NaN queries)
  const pcl::PointXYZ p(static_cast<float>(q.x()), static_cast<float>(q.y()),
                        static_cast<float>(q.z()));
  tree_.radiusSearch(p, radius * (1.0 + 1e-6) + margin_, found_, sq_distances_);
  for (const int s : found_)
    if ((points_[std::size_t(s)] - q).norm() < radius)
      out.push_back(s);
}

int
ExactPointIndex::nearest(const Eigen::Vector3d& q) const
{
  if (!q.allFinite() || points_.empty())
    return -1;
  const pcl::PointXYZ p(static_cast<float>(q.x()), static_cast<float>(q.y()),
                        static_cast<float>(q.z()));
  const bool searched = tree_.nearestKSearch(p, 1, found_, sq_distances_) > 0 &&
                        std::isfinite(sq_distances_[0]);
  if (searched) {
    // The float nearest bounds the exact distance; every point that may beat it lies within.
    const double bound = std::sqrt(double(sq_distances_[0])) * (1.0 + 1e-5) + margin_;
    tree_.radiusSearch(p, bound, found_, sq_distances_);
  }
  else { // beyond float's range: every point is a candidate
    found_.resize(points_.size());
    for (std::size_t s = 0; s < points_.size(); ++s)
      found_[s] = int(s);
  }
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (const int s : found_) {
    const double d = (points_[std::size_t(s)] - q).squaredNorm();
    if (d < best_d || (d == best_d && s < best)) {
      best_d = d;
      best = s;
    }
  }
  return best;
}

} // namespace detail
} // namespace segmat
