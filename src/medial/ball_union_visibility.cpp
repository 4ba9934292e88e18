/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/ball_union_visibility.h>

#include <algorithm>
#include <limits>

namespace segmat {

BallUnionVisibility::BallUnionVisibility(const std::vector<Eigen::Vector3d>& centers,
                                         const std::vector<double>& radii, double inflation,
                                         double margin)
{
  std::vector<double> inflated(radii.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    inflated[i] = inflation * radii[i] + margin;
    lo = lo.cwiseMin(centers[i] - Eigen::Vector3d::Constant(inflated[i]));
    hi = hi.cwiseMax(centers[i] + Eigen::Vector3d::Constant(inflated[i]));
  }
  tree_ = std::make_shared<const SphereTree>(centers, inflated);
  min_step_ = centers.empty() ? 0.0 : 1e-3 * (hi - lo).norm();
}

bool
BallUnionVisibility::operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
{
  if (tree_->empty())
    return false;
  const double length = (b - a).norm();
  const Eigen::Vector3d direction = length > 0.0 ? Eigen::Vector3d((b - a) / length)
                                                 : Eigen::Vector3d::Zero();
  double t = 0.0;
  int deepest = -1; // consecutive queries are close: start from the previous deepest ball
  while (true) {
    const Eigen::Vector3d q = a + std::min(t, length) * direction;
    const double d = tree_->signedDistance(q, -std::numeric_limits<double>::infinity(), &deepest);
    if (!(d <= 0.0)) // outside (or NaN)
      return false;
    if (t >= length)
      return true;
    // The segment stays inside the deepest ball up to where it leaves that ball; stop half a
    // minimal step short of there, so that the minimal step still decides small gaps.
    const Eigen::Vector3d w = q - tree_->center(deepest);
    const double r = tree_->radius(deepest);
    const double along = w.dot(direction);
    const double exit =
        -along + std::sqrt(std::max(0.0, along * along - (w.squaredNorm() - r * r)));
    t += std::max({-d, exit - 0.5 * min_step_, min_step_});
  }
}

} // namespace segmat
