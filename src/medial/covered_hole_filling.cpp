/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "covered_hole_filling.h"

#include <algorithm>
#include <vector>

namespace segmat {
namespace detail {
namespace {

/// Follows the boundary edges from \a start and puts the vertices it passes into \a walk.
/// True when the walk comes back to \a start through at least three vertices, each with exactly
/// two boundary edges, within \a max_loop edges: \a walk is then the loop in order.
bool
traceLoop(const MedialMesh& mat, const std::vector<std::vector<int>>& boundary, int start,
          int max_loop, std::vector<int>& walk)
{
  walk.assign(1, start);
  int previous = -1, current = start;
  while (int(walk.size()) <= max_loop) {
    if (boundary[current].size() != 2)
      return false;
    int next = -1;
    for (int e : boundary[current]) {
      const Eigen::Vector2i& ab = mat.edges()[e];
      const int other = ab[0] == current ? ab[1] : ab[0];
      if (other != previous) {
        next = other;
        break;
      }
    }
    if (next < 0)
      return false;
    if (next == start)
      return walk.size() >= 3;
    walk.push_back(next);
    previous = current;
    current = next;
  }
  return false;
}

bool
insideSomeBall(const MedialMesh& mat, const std::vector<int>& loop, const Eigen::Vector3d& p)
{
  for (int v : loop)
    if ((p - mat.centers()[v]).squaredNorm() <= mat.radii()[v] * mat.radii()[v])
      return true;
  return false;
}

/// True when the one triangle of most rim edges lies on the far side of its edge from the
/// loop's centroid (a hole); an island's triangles lie on the centroid's side.
bool
trianglesOutside(const MedialMesh& mat, const std::vector<int>& loop)
{
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int v : loop)
    centroid += mat.centers()[v];
  centroid /= double(loop.size());
  int outside = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const int a = loop[k], b = loop[(k + 1) % loop.size()];
    const Eigen::Vector3d mid = 0.5 * (mat.centers()[a] + mat.centers()[b]);
    for (int t : mat.vertexTriangles(a)) {
      const Eigen::Vector3i& tri = mat.triangles()[t];
      if ((tri.array() == b).any()) {
        const int x = tri[0] != a && tri[0] != b ? tri[0] : (tri[1] != a && tri[1] != b ? tri[1]
                                                                                        : tri[2]);
        if ((mat.centers()[x] - mid).dot(centroid - mid) < 0.0)
          ++outside;
        break;
      }
    }
  }
  return 2 * outside > int(loop.size());
}

bool
fanCovered(const MedialMesh& mat, const std::vector<int>& loop)
{
  constexpr int kSteps = 8;
  const Eigen::Vector3d& o = mat.centers()[loop[0]];
  for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
    const Eigen::Vector3d& b = mat.centers()[loop[k]];
    const Eigen::Vector3d& c = mat.centers()[loop[k + 1]];
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double u = double(i) / kSteps, w = double(j) / kSteps;
        if (!insideSomeBall(mat, loop, (1.0 - u - w) * o + u * b + w * c))
          return false;
      }
  }
  return true;
}

} // namespace

int
fillCoveredHoles(MedialMesh& mat, int max_loop)
{
  const int nv = int(mat.numVertices());
  std::vector<std::vector<int>> boundary(nv);
  for (std::size_t e = 0; e < mat.numEdges(); ++e)
    if (mat.edgeTriangleCount(int(e)) == 1)
      for (int k = 0; k < 2; ++k)
        boundary[mat.edges()[e][k]].push_back(int(e));
  std::vector<char> used(nv, 0);
  std::vector<Eigen::Vector2i> edges = mat.edges();
  std::vector<Eigen::Vector3i> triangles = mat.triangles();
  int filled = 0;
  // Each walk starts at the smallest vertex not walked yet, so a loop starts at its smallest
  // vertex whatever the order of anything else. A vertex walked once, in a loop or not, would
  // only give the same walk again.
  std::vector<int> loop;
  for (int start = 0; start < nv; ++start) {
    if (used[start] || boundary[start].size() != 2)
      continue;
    const bool closed = traceLoop(mat, boundary, start, max_loop, loop);
    for (int v : loop)
      used[v] = 1;
    if (!closed || !trianglesOutside(mat, loop))
      continue;
    // The first apex whose fan adds no existing edge and stays in the balls.
    bool found = false;
    for (std::size_t apex = 0; apex < loop.size() && !found; ++apex) {
      bool fresh = true;
      for (std::size_t k = 2; k + 1 < loop.size() && fresh; ++k)
        fresh = mat.findEdge(loop[0], loop[k]) < 0;
      found = fresh && fanCovered(mat, loop);
      if (!found)
        std::rotate(loop.begin(), loop.begin() + 1, loop.end());
    }
    if (!found)
      continue;
    for (std::size_t k = 2; k + 1 < loop.size(); ++k)
      edges.emplace_back(loop[0], loop[k]);
    for (std::size_t k = 1; k + 1 < loop.size(); ++k)
      triangles.emplace_back(loop[0], loop[k], loop[k + 1]);
    ++filled;
  }
  if (filled > 0)
    mat = MedialMesh(mat.centers(), mat.radii(), edges, triangles);
  return filled;
}

} // namespace detail
} // namespace segmat
