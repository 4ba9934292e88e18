/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/mat_graph.h>
#include "../geometry/point_bounds.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace segmat {

MatGraph::MatGraph(std::vector<Eigen::Vector3d> centers, std::vector<double> radii,
                   std::vector<MatNode> nodes, const std::vector<std::vector<int>>& adjacency)
: centers_(std::move(centers)), radii_(std::move(radii)), nodes_(std::move(nodes))
{
  const int n = static_cast<int>(nodes_.size());
  std::vector<std::vector<int>> sym(n);
  for (int i = 0; i < n && i < static_cast<int>(adjacency.size()); ++i)
    for (int j : adjacency[i])
      if (j != i && j >= 0 && j < n) {
        sym[i].push_back(j);
        sym[j].push_back(i);
      }
  offsets_.assign(n + 1, 0);
  adjacency_.clear();
  for (int i = 0; i < n; ++i) {
    std::sort(sym[i].begin(), sym[i].end());
    sym[i].erase(std::unique(sym[i].begin(), sym[i].end()), sym[i].end());
    adjacency_.insert(adjacency_.end(), sym[i].begin(), sym[i].end());
    offsets_[i + 1] = static_cast<int>(adjacency_.size());
  }
}

MatGraph
MatGraph::fromMedialMesh(const MedialMesh& mat, double radius_gate)
{
  const auto& c = mat.centers();
  const auto& r = mat.radii();
  std::vector<MatNode> nodes;
  nodes.reserve(mat.numTriangles() + mat.numEdges());
  for (const Eigen::Vector3i& t : mat.triangles()) {
    MatNode node;
    node.kind = MatNodeKind::Slab;
    node.v = t;
    node.mean_radius = (r[t[0]] + r[t[1]] + r[t[2]]) / 3.0;
    node.centroid = (c[t[0]] + c[t[1]] + c[t[2]]) / 3.0;
    const Eigen::Vector3d n = (c[t[1]] - c[t[0]]).cross(c[t[2]] - c[t[0]]);
    const double len = n.norm();
    node.normal = len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
    nodes.push_back(node);
  }
  for (std::size_t e = 0; e < mat.numEdges(); ++e) {
    if (!mat.isPureEdge(static_cast<int>(e)))
      continue;
    const Eigen::Vector2i& ed = mat.edges()[e];
    MatNode node;
    node.kind = MatNodeKind::Cone;
    node.v = Eigen::Vector3i(ed[0], ed[1], -1);
    node.mean_radius = 0.5 * (r[ed[0]] + r[ed[1]]);
    // The reference used (2a+b)/3 for a cone's centroid; the midpoint is meant.
    node.centroid = 0.5 * (c[ed[0]] + c[ed[1]]);
    node.normal = Eigen::Vector3d::Zero();
    nodes.push_back(node);
  }

  // Sphere → nodes incidence, then pairs sharing a sphere, gated by the radius ratio.
  std::vector<std::vector<int>> sphere_nodes(mat.numVertices());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int k = 0; k < nodes[i].size(); ++k)
      sphere_nodes[nodes[i].v[k]].push_back(static_cast<int>(i));
  std::vector<std::vector<int>> adjacency(nodes.size());
  for (const auto& incident : sphere_nodes)
    for (std::size_t a = 0; a < incident.size(); ++a)
      for (std::size_t b = a + 1; b < incident.size(); ++b) {
        const double ra = nodes[incident[a]].mean_radius, rb = nodes[incident[b]].mean_radius;
        const double lo = std::min(ra, rb), hi = std::max(ra, rb);
        // A zero mean radius is adjacent only to another zero one (guards the ratio's 0/0).
        const bool pass = lo > 0.0 ? hi / lo < radius_gate : hi == 0.0;
        if (pass)
          adjacency[incident[a]].push_back(incident[b]);
      }
  return MatGraph(c, r, std::move(nodes), adjacency);
}

bool
MatGraph::hasPrimitives() const
{
  return std::any_of(nodes_.begin(), nodes_.end(),
                     [](const MatNode& n) { return n.kind != MatNodeKind::Point; });
}

double
MatGraph::centerBoundingBoxDiagonal() const
{
  return detail::boundsDiagonal(centers_);
}

} // namespace segmat
