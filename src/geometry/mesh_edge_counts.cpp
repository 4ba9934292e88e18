/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/mesh_edge_counts.h>
#include <segmat/geometry/weld_points.h>

#include <algorithm>
#include <array>
#include <vector>

namespace segmat {

MeshEdgeCounts
countMeshEdges(const TriangleMesh& mesh)
{
  const std::vector<int> same = weldPoints(mesh.vertices, 1e-9 * mesh.boundingBoxDiagonal());
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * mesh.faces.size());
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (f.minCoeff() < 0 || f.maxCoeff() >= n)
      continue;
    const int a = same[f[0]], b = same[f[1]], c = same[f[2]];
    if (a == b || b == c || a == c)
      continue;
    for (const auto& [u, v] : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)})
      edges.push_back({std::min(u, v), std::max(u, v)});
  }
  std::sort(edges.begin(), edges.end());
  MeshEdgeCounts counts;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    ++counts.edges;
    if (j - i == 1)
      ++counts.boundary;
    else if (j - i > 2)
      ++counts.non_manifold;
    i = j;
  }
  return counts;
}

} // namespace segmat
