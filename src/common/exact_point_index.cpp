/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "exact_point_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

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

bool
ExactPointIndex::floatQuery(const Eigen::Vector3d& q, pcl::PointXYZ& p)
{
  p = pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()),
                    static_cast<float>(q.z()));
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void
ExactPointIndex::takeAll() const
{
  found_.resize(points_.size());
  std::iota(found_.begin(), found_.end(), 0);
}

void
ExactPointIndex::within(const Eigen::Vector3d& q, double radius, std::vector<int>& out) const
{
  out.clear();
  if (!(radius > 0.0) || !std::isfinite(radius) || !q.allFinite() || points_.empty())
    return; // a non-finite ball contains nothing
  pcl::PointXYZ p;
  if (floatQuery(q, p))
    tree_.radiusSearch(p, radius * (1.0 + 1e-6) + margin_, found_, sq_distances_);
  else
    takeAll(); // beyond float's range (PCL asserts on non-finite queries)
  for (const int s : found_)
    if ((points_[std::size_t(s)] - q).norm() < radius)
      out.push_back(s);
}

int
ExactPointIndex::nearest(const Eigen::Vector3d& q) const
{
  if (!q.allFinite() || points_.empty())
    return -1;
  // The float nearest bounds the exact distance, and every point that may beat it lies within
  // that bound. A query beyond float's range, or whose squared distances overflow float (the
  // tree then finds nothing), takes every point as a candidate.
  pcl::PointXYZ p;
  if (floatQuery(q, p) && tree_.nearestKSearch(p, 1, found_, sq_distances_) > 0 &&
      std::isfinite(sq_distances_[0]))
    tree_.radiusSearch(p, std::sqrt(double(sq_distances_[0])) * (1.0 + 1e-5) + margin_, found_,
                       sq_distances_);
  else
    takeAll();
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (const int s : found_) {
    if (!points_[std::size_t(s)].allFinite())
      continue;
    const double d = (points_[std::size_t(s)] - q).squaredNorm();
    if (best < 0 || d < best_d || (d == best_d && s < best)) {
      best_d = d;
      best = s;
    }
  }
  return best;
}

} // namespace detail
} // namespace segmat
