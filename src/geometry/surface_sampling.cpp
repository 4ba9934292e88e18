/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/surface_sampling.h>

#include <Eigen/Geometry>

#include <algorithm>
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

  std::sort(edges.begin(), edges.end());
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

} // namespace segmat
