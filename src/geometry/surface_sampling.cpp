/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/surface_sampling.h>

#include "edge_records.h"
#include "point_bounds.h"
#include "point_grid.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <array>
#include <cmath>

namespace segmat {
namespace {
/** Lexicographic order of positions: fill points are made from geometry alone, so that vertex
 * numbering and face orientation (an unwelded or flipped copy of the mesh) do not change them. */
bool
lexLess(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

bool
validFace(const TriangleMesh& mesh, const Eigen::Vector3i& f)
{
  const int n = static_cast<int>(mesh.vertices.size());
  return f.minCoeff() >= 0 && f.maxCoeff() < n;
}
} // namespace

double
estimateSurfaceSampleCount(const TriangleMesh& mesh, double max_spacing)
{
  double count = static_cast<double>(mesh.vertices.size());
  const double h = max_spacing;
  if (!(h > 0.0) || !std::isfinite(h))
    return count;
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (!validFace(mesh, f))
      continue;
    const Eigen::Vector3d &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]],
                          &c = mesh.vertices[f[2]];
    // Each edge is shared by about two faces: half of its points per face.
    count += 0.5 * ((b - a).norm() + (c - b).norm() + (a - c).norm()) / h;
    count += 0.5 * (b - a).cross(c - a).norm() / (h * h * std::sqrt(3.0) / 2.0);
  }
  return count;
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
    const bool forward = !lexLess(mesh.vertices[e[1]], mesh.vertices[e[0]]);
    const Eigen::Vector3d& a = mesh.vertices[forward ? e[0] : e[1]];
    const Eigen::Vector3d& b = mesh.vertices[forward ? e[1] : e[0]];
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
    // The lattice frame: the longest side (ties: the lexicographically smaller one), from its
    // lexicographically smaller end; independent of corner order and orientation.
    const Eigen::Vector3d* corner[3] = {&mesh.vertices[f[0]], &mesh.vertices[f[1]],
                                        &mesh.vertices[f[2]]};
    const Eigen::Vector3d *a = nullptr, *b = nullptr, *c = nullptr;
    double longest_length = -1.0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d* p = corner[k];
      const Eigen::Vector3d* q = corner[(k + 1) % 3];
      if (lexLess(*q, *p))
        std::swap(p, q);
      const double l = (*q - *p).norm();
      const bool tie_wins =
          l == longest_length && (lexLess(*p, *a) || (*p == *a && lexLess(*q, *b)));
      if (l > longest_length || tie_wins) {
        longest_length = l;
        a = p;
        b = q;
        c = corner[(k + 2) % 3];
      }
    }
    const double base = longest_length;
    if (!(base > 0.0) || !std::isfinite(base))
      continue;
    const Eigen::Vector3d u = (*b - *a) / base;
    const Eigen::Vector3d w = (*c - *a) - u * u.dot(*c - *a);
    const double height = w.norm();
    if (!(height > 2.0 * margin))
      continue; // a sliver: its sides are sampled already
    const Eigen::Vector3d v = w / height;
    const double cx = u.dot(*c - *a); // apex (cx, height), base from (0,0) to (base,0)
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
          samples.push_back(*a + x * u + y * v);
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
  // Cells of size `radius`: a conflicting point is in the same or an adjacent cell.
  detail::PointGrid grid(points, radius);
  const double radius2 = radius * radius;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!p.allFinite())
      continue;
    if (grid.findNear(p, [&](int j) { return (points[j] - p).squaredNorm() < radius2; }))
      continue;
    grid.insert(static_cast<int>(i));
    kept.push_back(static_cast<int>(i));
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
  // Secant steps on log(count) against log(radius), starting from the surface law
  // count ∝ radius⁻², kept inside the bracket (count(low) > max_count ≥ count(high)) and
  // replaced by bisection when they would leave it. A handful of passes; stops within 15 % below
  // the target (the cap bounds cost, it need not be met exactly).
  double low = 0.0, high = diagonal;
  double radius = 0.5 * diagonal / std::sqrt(static_cast<double>(max_count));
  double previous_radius = 0.0, previous_count = 0.0;
  bool have_high = false;
  const double target = static_cast<double>(max_count) * 0.92;
  for (int pass = 0; pass < 30; ++pass) {
    std::vector<int> kept = thinPoints(points, radius);
    const double count = std::max(1.0, static_cast<double>(kept.size()));
    if (kept.size() <= max_count) {
      high = radius;
      have_high = true;
      best.swap(kept);
      if (best.size() >= max_count - (3 * max_count) / 20)
        break;
    }
    else
      low = radius;
    if (high - low <= 1e-3 * high)
      break;
    double slope = -2.0; // d log(count) / d log(radius)
    if (previous_radius > 0.0 && previous_count != count && previous_radius != radius)
      slope = std::min(-0.5, std::log(count / previous_count) / std::log(radius / previous_radius));
    previous_radius = radius;
    previous_count = count;
    double guess = radius * std::exp(std::log(target / count) / slope);
    if (!have_high)
      guess = std::min(high, std::max(guess, 1.1 * radius));
    else if (!(guess > low && guess < high))
      guess = low > 0.0 ? std::sqrt(low * high) : 0.5 * high;
    radius = guess;
  }
  if (!have_high)
    best = thinPoints(points, high);
  return best;
}

} // namespace segmat
