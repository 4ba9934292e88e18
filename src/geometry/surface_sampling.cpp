/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/surface_sampling.h>

#include "edge_records.h"
#include "point_bounds.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <array>
#include <cmath>

namespace segmat {
namespace {
bool
validFace(const TriangleMesh& mesh, const Eigen::Vector3i& f)
{
  const int n = static_cast<int>(mesh.vertices.size());
  return f.minCoeff() >= 0 && f.maxCoeff() < n;
}
} // namespace

double
surfaceArea(const TriangleMesh& mesh)
{
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (validFace(mesh, mesh.faces[f]))
      area += mesh.faceArea(static_cast<int>(f));
  return area;
}

std::vector<Eigen::Vector3d>
sampleSurface(const TriangleMesh& mesh, double max_spacing)
{
  std::vector<Eigen::Vector3d> samples;
  std::vector<char> used(mesh.vertices.size(), 0);
  std::vector<std::array<int, 2>> edges;
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (!validFace(mesh, f))
      continue;
    for (int k = 0; k < 3; ++k) {
      used[f[k]] = 1;
      const int a = f[k], b = f[(k + 1) % 3];
      if (a != b)
        edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (used[v])
      samples.push_back(mesh.vertices[v]);
  const double h = max_spacing;
  if (!(h > 0.0) || !std::isfinite(h))
    return samples;

  detail::sortEdgeRecords(edges, static_cast<int>(mesh.vertices.size()));
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& e : edges) {
    const Eigen::Vector3d& a = mesh.vertices[e[0]];
    const Eigen::Vector3d& b = mesh.vertices[e[1]];
    const double length = (b - a).norm();
    if (!(length > h))
      continue;
    const int parts = static_cast<int>(std::ceil(length / h));
    for (int i = 1; i < parts; ++i)
      samples.push_back(a + (b - a) * (static_cast<double>(i) / parts));
  }

  // Triangular lattice in each face's plane: rows parallel to the longest side, spacing h,
  // alternate rows shifted by h/2; keep points at least h/2 inside every side.
  const double margin = 0.5 * h;
  const double row_step = h * std::sqrt(3.0) / 2.0;
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (!validFace(mesh, f))
      continue;
    int longest = 0;
    double longest_length = -1.0;
    for (int k = 0; k < 3; ++k) {
      const double l = (mesh.vertices[f[(k + 1) % 3]] - mesh.vertices[f[k]]).norm();
      if (l > longest_length)
        longest_length = l, longest = k;
    }
    const Eigen::Vector3d& a = mesh.vertices[f[longest]];
    const Eigen::Vector3d& b = mesh.vertices[f[(longest + 1) % 3]];
    const Eigen::Vector3d& c = mesh.vertices[f[(longest + 2) % 3]];
    const double base = longest_length;
    if (!(base > 0.0) || !std::isfinite(base))
      continue;
    const Eigen::Vector3d u = (b - a) / base;
    const Eigen::Vector3d w = (c - a) - u * u.dot(c - a);
    const double height = w.norm();
    if (!(height > 2.0 * margin))
      continue; // a sliver: its sides are sampled already
    const Eigen::Vector3d v = w / height;
    const double cx = u.dot(c - a); // apex (cx, height), base from (0,0) to (base,0)
    // Inward-negative unit normals of the two slanted sides through the apex (cx, height).
    const Eigen::Vector2d n_left = Eigen::Vector2d(-height, cx).normalized();         // side a→c
    const Eigen::Vector2d n_right = Eigen::Vector2d(height, base - cx).normalized(); // side b→c
    for (int row = 1;; ++row) {
      const double y = row * row_step;
      if (y > height - margin)
        break;
      const double shift = (row % 2) ? 0.5 * h : 0.0;
      for (int col = 0;; ++col) {
        const double x = shift + col * h;
        if (x > base)
          break;
        const Eigen::Vector2d p(x, y);
        // Distance to side a→c (inside is where n_left·p ≤ 0) and to side b→c.
        const double d_left = -n_left.dot(p);
        const double d_right = -n_right.dot(p - Eigen::Vector2d(base, 0.0));
        if (d_left >= margin && d_right >= margin)
          samples.push_back(a + x * u + y * v);
      }
    }
  }
  return samples;
}

std::vector<int>
thinPoints(const std::vector<Eigen::Vector3d>& points, double radius)
{
  std::vector<int> kept;
  kept.reserve(points.size());
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].allFinite())
        kept.push_back(static_cast<int>(i));
    return kept;
  }
  // Cells of size `radius` (a conflicting point is in the same or an adjacent cell), in a flat
  // open-addressing table: cell key → first kept point, kept points chained through `next`.
  std::size_t capacity = 64;
  while (capacity < 2 * points.size())
    capacity *= 2;
  const std::uint64_t empty = ~std::uint64_t(0);
  std::vector<std::uint64_t> keys(capacity, empty);
  std::vector<int> heads(capacity, -1);
  std::vector<int> next(points.size(), -1);
  auto cellKey = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    // 21 bits per axis, wrapping around: cells that share a key only add candidates, which the
    // distance test rejects, so the key need not be unique.
    const std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return ((static_cast<std::uint64_t>(x) & mask) << 42) |
           ((static_cast<std::uint64_t>(y) & mask) << 21) | (static_cast<std::uint64_t>(z) & mask);
  };
  auto slotOf = [&](std::uint64_t key) {
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & (capacity - 1);
    while (keys[slot] != empty && keys[slot] != key)
      slot = (slot + 1) & (capacity - 1);
    return slot;
  };
  // Cell coordinates from the lowest corner, clamped into int64 range.
  const Eigen::Vector3d origin = detail::lowestCorner(points);
  const double inv = 1.0 / radius, radius2 = radius * radius;
  auto cell = [&](double v, double o) {
    return static_cast<std::int64_t>(std::min(4.0e18, std::floor((v - o) * inv)));
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!p.allFinite())
      continue;
    const std::int64_t cx = cell(p.x(), origin.x());
    const std::int64_t cy = cell(p.y(), origin.y());
    const std::int64_t cz = cell(p.z(), origin.z());
    bool free = true;
    for (std::int64_t dx = -1; dx <= 1 && free; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && free; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && free; ++dz)
          for (int j = heads[slotOf(cellKey(cx + dx, cy + dy, cz + dz))]; j >= 0; j = next[j])
            if ((points[j] - p).squaredNorm() < radius2) {
              free = false;
              break;
            }
    if (free) {
      const std::uint64_t key = cellKey(cx, cy, cz);
      const std::size_t slot = slotOf(key);
      keys[slot] = key;
      next[i] = heads[slot];
      heads[slot] = static_cast<int>(i);
      kept.push_back(static_cast<int>(i));
    }
  }
  return kept;
}

std::vector<int>
thinPointsToCount(const std::vector<Eigen::Vector3d>& points, std::size_t max_count)
{
  std::vector<int> best = thinPoints(points, 0.0);
  if (best.size() <= max_count || max_count == 0)
    return best;
  const double diagonal = detail::finiteBounds(points).diagonal().norm();
  // First radius from the surface law count ∝ radius⁻²; then false position in log-log between
  // the bracket ends (count(low) > max_count ≥ count(high)), kept off the ends so it cannot
  // stall. A handful of passes; stops within 5 % below the target.
  double low = 0.0, high = diagonal;
  double low_count = static_cast<double>(best.size()), high_count = 1.0;
  double radius = 0.5 * diagonal / std::sqrt(static_cast<double>(max_count));
  bool have_high = false;
  const double target = static_cast<double>(max_count) * 0.975;
  for (int pass = 0; pass < 30; ++pass) {
    std::vector<int> kept = thinPoints(points, radius);
    const double count = static_cast<double>(kept.size());
    if (kept.size() <= max_count) {
      high = radius;
      high_count = std::max(count, 1.0);
      have_high = true;
      best.swap(kept);
      if (best.size() >= max_count - max_count / 20)
        break;
    }
    else {
      low = radius;
      low_count = count;
    }
    if (high - low <= 1e-3 * high)
      break;
    if (!have_high) {
      radius = std::min(high, radius * std::max(1.1, std::sqrt(count / target)));
      continue;
    }
    if (low == 0.0) {
      radius = radius * std::sqrt(count / target);
      continue;
    }
    const double t = std::log(low_count / target) / std::log(low_count / high_count);
    const double step = std::max(0.1, std::min(0.9, std::isfinite(t) ? t : 0.5));
    radius = std::exp(std::log(low) + step * (std::log(high) - std::log(low)));
  }
  if (!have_high)
    best = thinPoints(points, high);
  return best;
}

} // namespace segmat
