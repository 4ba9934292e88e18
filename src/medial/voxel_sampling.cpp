/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/voxel_sampling.h>

#include "../common/splitmix.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

namespace segmat {
namespace {

constexpr std::int64_t kCellsPerAxis = (std::int64_t(1) << 21) - 1; // 3 × 21 bits in one key

struct VoxelGrid
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double size = 1.0;

  Eigen::Array3i
  cell(const Eigen::Vector3f& p) const
  {
    const Eigen::Array3d c = ((p.cast<double>() - origin) / size).array().floor();
    return c.max(0.0).min(double(kCellsPerAxis)).cast<int>();
  }

  static std::uint64_t
  key(const Eigen::Array3i& c)
  {
    return (std::uint64_t(c[0]) << 42) | (std::uint64_t(c[1]) << 21) | std::uint64_t(c[2]);
  }
};

/// Grid anchored at the points' minimum corner; the size is raised so the key cannot overflow.
VoxelGrid
makeGrid(const std::vector<Eigen::Vector3f>& points, double voxel_size)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3f& p : points) {
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  VoxelGrid grid;
  grid.origin = lo;
  const double extent = points.empty() ? 0.0 : (hi - lo).maxCoeff();
  grid.size = std::max({voxel_size, extent / double(kCellsPerAxis - 1),
                        std::numeric_limits<double>::min()});
  return grid;
}

std::size_t
countOccupiedCells(const std::vector<Eigen::Vector3f>& points, const VoxelGrid& grid)
{
  std::vector<std::uint64_t> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    keys[i] = VoxelGrid::key(grid.cell(points[i]));
  std::sort(keys.begin(), keys.end());
  return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
}

double
boundingBoxDiagonal(const std::vector<Eigen::Vector3f>& points)
{
  if (points.empty())
    return 0.0;
  Eigen::Vector3f lo = points.front(), hi = points.front();
  for (const Eigen::Vector3f& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).cast<double>().norm();
}

} // namespace

std::vector<int>
voxelCellIndices(const std::vector<Eigen::Vector3f>& points, double voxel_size, std::size_t* cells)
{
  const VoxelGrid grid = makeGrid(points, voxel_size);
  std::vector<std::pair<std::uint64_t, int>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    keyed[i] = {VoxelGrid::key(grid.cell(points[i])), static_cast<int>(i)};
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> cell(points.size());
  int count = 0;
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    if (i > 0 && keyed[i].first != keyed[i - 1].first)
      ++count;
    cell[keyed[i].second] = count;
  }
  if (cells)
    *cells = points.empty() ? 0 : std::size_t(count) + 1;
  return cell;
}

std::vector<int>
voxelRepresentatives(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                     std::vector<int>* representative_of, VoxelPick pick)
{
  const VoxelGrid grid = makeGrid(points, voxel_size);
  struct Entry
  {
    std::uint64_t key;
    double distance; // squared distance to the cell centre
    int index;
  };
  std::vector<Entry> entries(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Array3i c = grid.cell(points[i]);
    const std::uint64_t key = VoxelGrid::key(c);
    Eigen::Array3d offset = Eigen::Array3d::Constant(0.5);
    if (pick == VoxelPick::Jittered)
      // Three draws of the splitmix stream that the cell's key seeds, each in [0, 1).
      for (int a = 0; a < 3; ++a) {
        const std::uint64_t draw =
            detail::splitmix64(key + std::uint64_t(a + 1) * detail::kSplitmixIncrement);
        offset[a] = double(draw >> 11) * 0x1.0p-53;
      }
    const Eigen::Vector3d target = grid.origin + grid.size * (c.cast<double>() + offset).matrix();
    entries[i] = {key, (points[i].cast<double>() - target).squaredNorm(), static_cast<int>(i)};
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.key, a.distance, a.index) < std::tie(b.key, b.distance, b.index);
  });
  std::vector<int> kept;
  if (representative_of)
    representative_of->assign(points.size(), -1);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].key != entries[i - 1].key)
      kept.push_back(entries[i].index);
    if (representative_of)
      (*representative_of)[entries[i].index] = kept.back();
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

double
voxelSizeForCount(const std::vector<Eigen::Vector3f>& points, std::size_t target,
                  double min_voxel_size)
{
  if (points.empty() || target == 0)
    return 0.0;
  if (points.size() <= target)
    return min_voxel_size;
  const double diagonal = boundingBoxDiagonal(points);
  if (!(diagonal > 0.0)) // every point at one place: any side gives one cell
    return std::max(min_voxel_size, 1.0);

  const double log_target = std::log(double(target));
  double h = diagonal / std::sqrt(double(target));
  double best_h = h, best_error = std::numeric_limits<double>::max();
  double prev_log_h = 0.0, prev_log_n = 0.0, slope = 2.0;
  for (int pass = 0; pass < 8; ++pass) {
    const VoxelGrid grid = makeGrid(points, std::max(h, min_voxel_size));
    h = grid.size;
    const double log_n =
        std::log(double(std::max<std::size_t>(1, countOccupiedCells(points, grid))));
    const double error = std::abs(log_n - log_target);
    if (error < best_error) {
      best_error = error;
      best_h = h;
    }
    if (error < 0.05 || (h <= min_voxel_size && log_n < log_target)) // within 5 %, or floored
      break;
    if (pass > 0 && std::abs(std::log(h) - prev_log_h) > 1e-9)
      slope = std::clamp(-(log_n - prev_log_n) / (std::log(h) - prev_log_h), 0.5, 3.0);
    prev_log_h = std::log(h);
    prev_log_n = log_n;
    h = std::exp(prev_log_h + (log_n - log_target) / slope);
  }
  return best_h;
}

std::vector<int>
voxelRepresentativesNear(const std::vector<Eigen::Vector3f>& points, std::size_t target,
                         double* voxel_size, double min_voxel_size)
{
  const double h = voxelSizeForCount(points, target, min_voxel_size);
  if (voxel_size)
    *voxel_size = h;
  if (h > 0.0)
    return voxelRepresentatives(points, h);
  std::vector<int> all(target == 0 ? 0 : points.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<int>(i);
  return all;
}

} // namespace segmat
