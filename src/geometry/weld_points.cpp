/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/weld_points.h>

#include "point_bounds.h"
#include "point_grid.h"

#include <cmath>

namespace segmat {

std::vector<int>
weldPoints(const std::vector<Eigen::Vector3d>& points, double tolerance)
{
  const int n = static_cast<int>(points.size());
  std::vector<int> rep(n);
  for (int i = 0; i < n; ++i)
    rep[i] = i;
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance) || n == 0)
    return rep;
  // Cells of size `tolerance` (a partner is in the same or an adjacent cell); for exact welding
  // any size works, one near a millionth of the extent keeps cells small.
  double cell = tolerance;
  if (!(cell > 0.0)) {
    const double extent = detail::finiteBounds(points).sizes().maxCoeff();
    cell = extent > 0.0 && std::isfinite(extent) ? 1e-6 * extent : 1.0;
  }
  detail::PointGrid grid(points, cell);
  const double tol2 = tolerance * tolerance;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!p.allFinite())
      continue;
    int best = -1;
    grid.findNear(p, [&](int j) {
      if ((points[j] - p).squaredNorm() <= tol2 && (best < 0 || j < best))
        best = j;
      return false; // visit all candidates: the lowest index wins
    });
    if (best >= 0)
      rep[i] = best;
    else
      grid.insert(i);
  }
  return rep;
}

} // namespace segmat
