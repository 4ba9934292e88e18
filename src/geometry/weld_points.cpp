/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/weld_points.h>

#include "point_bounds.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace segmat {
namespace {
struct CellHash
{
  std::size_t
  operator()(const Eigen::Matrix<std::int64_t, 3, 1>& c) const noexcept
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (int k = 0; k < 3; ++k) {
      h ^= static_cast<std::uint64_t>(c[k]) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};
struct CellEqual
{
  bool
  operator()(const Eigen::Matrix<std::int64_t, 3, 1>& a,
             const Eigen::Matrix<std::int64_t, 3, 1>& b) const noexcept
  {
    return a == b;
  }
};
} // namespace

std::vector<int>
weldPoints(const std::vector<Eigen::Vector3d>& points, double tolerance)
{
  const int n = static_cast<int>(points.size());
  std::vector<int> rep(n);
  for (int i = 0; i < n; ++i)
    rep[i] = i;
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    return rep;

  using Cell = Eigen::Matrix<std::int64_t, 3, 1>;
  // Exact welding hashes the coordinates themselves; otherwise cells of size `tolerance` counted
  // from the lowest corner (so far-off meshes do not overflow), and a partner within tolerance is
  // in the same or an adjacent cell. Cells are clamped to stay in int64 range (clamped points
  // merely share a cell and are compared exactly).
  const Eigen::Vector3d origin = detail::lowestCorner(points);
  const double inv = tolerance > 0.0 ? 1.0 / tolerance : 0.0;
  const double limit = 4.0e18;
  auto cellOf = [&](const Eigen::Vector3d& p) {
    Cell c;
    for (int k = 0; k < 3; ++k) {
      if (tolerance > 0.0)
        c[k] = static_cast<std::int64_t>(
            std::max(-limit, std::min(limit, std::floor((p[k] - origin[k]) * inv))));
      else {
        double v = p[k] == 0.0 ? 0.0 : p[k]; // -0 and +0 are equal
        std::int64_t bits;
        static_assert(sizeof(bits) == sizeof(v), "double is 64-bit");
        std::memcpy(&bits, &v, sizeof(v));
        c[k] = bits;
      }
    }
    return c;
  };

  std::unordered_map<Cell, std::vector<int>, CellHash, CellEqual> grid;
  grid.reserve(static_cast<std::size_t>(n));
  const double tol2 = tolerance * tolerance;
  const int reach = tolerance > 0.0 ? 1 : 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!p.allFinite())
      continue;
    const Cell c = cellOf(p);
    int best = -1;
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          auto it = grid.find(c + Cell(dx, dy, dz));
          if (it == grid.end())
            continue;
          for (int j : it->second)
            if ((points[j] - p).squaredNorm() <= tol2 && (best < 0 || j < best))
              best = j;
        }
    if (best >= 0)
      rep[i] = best;
    else
      grid[c].push_back(i);
  }
  return rep;
}

} // namespace segmat
