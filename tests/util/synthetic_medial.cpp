/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "synthetic_medial.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace segmat {
namespace test {

MedialMesh
planarSheet(int n, double size, double radius)
{
  std::vector<Eigen::Vector3d> centers;
  std::vector<Eigen::Vector3i> triangles;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      centers.emplace_back(size * i / n, size * j / n, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      triangles.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  std::vector<double> radii(centers.size(), radius);
  return MedialMesh(std::move(centers), std::move(radii), {}, triangles);
}

MedialMesh
annulusSheet(int segments, int rings, double inner, double outer, double radius)
{
  const double pi = std::acos(-1.0);
  std::vector<Eigen::Vector3d> centers;
  std::vector<Eigen::Vector3i> triangles;
  for (int k = 0; k <= rings; ++k) {
    const double rho = inner + (outer - inner) * k / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      centers.emplace_back(rho * std::cos(phi), rho * std::sin(phi), 0.0);
    }
  }
  auto id = [segments](int k, int s) { return k * segments + (s % segments); };
  for (int k = 0; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      triangles.emplace_back(id(k, s), id(k, s + 1), id(k + 1, s + 1));
      triangles.emplace_back(id(k, s), id(k + 1, s + 1), id(k + 1, s));
    }
  std::vector<double> radii(centers.size(), radius);
  return MedialMesh(std::move(centers), std::move(radii), {}, triangles);
}

MedialMesh
pureEdgeLoop(int n, double loop_radius, double radius)
{
  const double pi = std::acos(-1.0);
  std::vector<Eigen::Vector3d> centers;
  std::vector<Eigen::Vector2i> edges;
  for (int s = 0; s < n; ++s) {
    const double phi = 2.0 * pi * s / n;
    centers.emplace_back(loop_radius * std::cos(phi), loop_radius * std::sin(phi), 0.0);
    edges.emplace_back(s, (s + 1) % n);
  }
  std::vector<double> radii(centers.size(), radius);
  return MedialMesh(std::move(centers), std::move(radii), edges, {});
}

namespace {
/// Rank over GF(2) of the given rows (each a sorted list of column indices).
int
rankMod2(const std::vector<std::vector<int>>& rows, std::size_t columns)
{
  const std::size_t words = (columns + 63) / 64;
  std::vector<std::vector<std::uint64_t>> pivot_row(columns);
  int rank = 0;
  for (const auto& r : rows) {
    std::vector<std::uint64_t> v(words, 0);
    for (int c : r)
      v[c / 64] ^= std::uint64_t(1) << (c % 64);
    for (std::size_t w = words; w-- > 0;) {
      while (v[w]) {
        const std::size_t bit = w * 64 + 63 - __builtin_clzll(v[w]);
        if (pivot_row[bit].empty()) {
          pivot_row[bit] = v;
          ++rank;
          v.assign(words, 0);
          break;
        }
        for (std::size_t k = 0; k < words; ++k)
          v[k] ^= pivot_row[bit][k];
      }
    }
  }
  return rank;
}
} // namespace

Betti
bettiNumbers(const MedialMesh& mat)
{
  const int v = static_cast<int>(mat.numVertices());
  const int e = static_cast<int>(mat.numEdges());
  const int f = static_cast<int>(mat.numTriangles());
  std::vector<std::vector<int>> d1, d2;
  for (const Eigen::Vector2i& ed : mat.edges())
    d1.push_back({ed[0], ed[1]});
  for (const Eigen::Vector3i& t : mat.triangles()) {
    std::vector<int> row;
    for (int k = 0; k < 3; ++k)
      row.push_back(mat.findEdge(t[k], t[(k + 1) % 3]));
    d2.push_back(row);
  }
  const int r1 = rankMod2(d1, static_cast<std::size_t>(v));
  const int r2 = rankMod2(d2, static_cast<std::size_t>(e));
  return {v - r1, e - r1 - r2, f - r2};
}

} // namespace test
} // namespace segmat
