/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Internal helper of src/geometry (not installed): a hash grid of "kept" points for greedy
// point-set filters (welding, Poisson-disk thinning).

#include "point_bounds.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace segmat {
namespace detail {

/** Points are inserted one by one; a query visits the inserted points in the query's cell and
 * its 26 neighbours (cells of size `cell_size` counted from the lowest corner of the set, so far
 * from the origin nothing overflows). A flat open-addressing table maps a cell to its first point
 * and points of a cell are chained; cell keys wrap at 21 bits per axis, which only adds
 * candidates that the caller's distance test rejects. O(1) per operation, no allocation per
 * cell. */
class PointGrid
{
public:
  PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_size)
  : points_(points), origin_(lowestCorner(points)), inverse_(1.0 / cell_size),
    next_(points.size(), -1)
  {
    std::size_t capacity = 64;
    while (capacity < 2 * points.size())
      capacity *= 2;
    keys_.assign(capacity, kEmpty);
    heads_.assign(capacity, -1);
  }

  /** Calls visit(j) for inserted points j near point p until visit returns true; returns
   * whether it did. */
  template <typename Visit>
  bool
  findNear(const Eigen::Vector3d& p, Visit&& visit) const
  {
    const Cell c = cellOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          for (int j = heads_[slotOf(key(c[0] + dx, c[1] + dy, c[2] + dz))]; j >= 0;
               j = next_[j])
            if (visit(j))
              return true;
    return false;
  }

  /** Inserts point i (a finite point of the set). */
  void
  insert(int i)
  {
    const Cell c = cellOf(points_[i]);
    const std::uint64_t k = key(c[0], c[1], c[2]);
    const std::size_t slot = slotOf(k);
    keys_[slot] = k;
    next_[i] = heads_[slot];
    heads_[slot] = i;
  }

private:
  using Cell = std::array<std::int64_t, 3>;
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);

  Cell
  cellOf(const Eigen::Vector3d& p) const
  {
    Cell c;
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<std::int64_t>(
          std::min(4.0e18, std::floor((p[k] - origin_[k]) * inverse_)));
    return c;
  }

  static std::uint64_t
  key(std::int64_t x, std::int64_t y, std::int64_t z)
  {
    const std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return ((static_cast<std::uint64_t>(x) & mask) << 42) |
           ((static_cast<std::uint64_t>(y) & mask) << 21) | (static_cast<std::uint64_t>(z) & mask);
  }

  std::size_t
  slotOf(std::uint64_t k) const
  {
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 20) & mask;
    while (keys_[slot] != kEmpty && keys_[slot] != k)
      slot = (slot + 1) & mask;
    return slot;
  }

  const std::vector<Eigen::Vector3d>& points_;
  Eigen::Vector3d origin_;
  double inverse_;
  std::vector<std::uint64_t> keys_;
  std::vector<int> heads_;
  std::vector<int> next_;
};

} // namespace detail
} // namespace segmat
