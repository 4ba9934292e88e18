/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "spanning_spheres.h"

#include "../common/point_kd_tree.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <memory>

namespace segmat {
namespace detail {

std::vector<char>
spheresSpanningRightAngle(const std::vector<Eigen::Vector3d>& centers,
                          const std::vector<double>& radii,
                          const std::vector<Eigen::Vector3d>& samples, double tolerance)
{
  std::vector<char> spanning(centers.size(), 1);
  if (samples.empty() || !(tolerance > 0.0) || !std::isfinite(tolerance))
    return spanning;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(samples.size());
  bool finite = true;
  for (const Eigen::Vector3d& p : samples) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z())));
    finite = finite && p.allFinite();
  }
  cloud->is_dense = finite; // the tree leaves non-finite samples out
  PointKdTree tree;
  tree.setInputCloud(cloud);
  const double max_mean = std::cos(M_PI / 4.0);
  pcl::Indices touching;
  std::vector<float> sq_distances;
  for (std::size_t s = 0; s < centers.size() && s < radii.size(); ++s) {
    const Eigen::Vector3d& c = centers[s];
    if (!c.allFinite() || !std::isfinite(radii[s]) || !(radii[s] >= 0.0))
      continue;
    tree.radiusSearch(pcl::PointXYZ(static_cast<float>(c.x()), static_cast<float>(c.y()),
                                    static_cast<float>(c.z())),
                      radii[s] + tolerance, touching, sq_distances);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    for (const int i : touching) {
      const Eigen::Vector3d d = samples[i] - c;
      const double length = d.norm();
      if (length > 0.0) {
        sum += d / length;
        ++count;
      }
    }
    if (count > 0 && sum.norm() > max_mean * static_cast<double>(count))
      spanning[s] = 0;
  }
  return spanning;
}

} // namespace detail
} // namespace segmat
