/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/structure_tags.h>

#include "../common/exact_point_index.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace segmat {
namespace {

// Constants of the authors' `StructureDecompose`.
constexpr double kThinRatio = 8.0;          // ρ above this: thin part
constexpr double kDroppedLineRatio = 100.0; // line components above this take no part
constexpr double kCollinearBranch = 0.95;   // |cos| joining two lines through a branch point
constexpr int kDensifySteps = 13;

// Ours (a deviation from the reference; see computeStructureTags):
// A thin part with more of the base nodes than this must clear the thin ratio by a margin to
// count (a dumbbell's sheet: ρ ≈ 13, a cup's wall: 24–34); a noisy bird's merged
// body-and-wings sheet has ρ = 8.2–8.3.
constexpr double kWholeShapeFraction = 0.85;
constexpr double kWholeShapeThinRatio = 10.0;

/** A node of the structured MAT: a triangle or a pure edge (second sphere in v[1], v[2] = -1). */
struct StructureNode
{
  Eigen::Vector3i v;
  bool is_line;
};

std::vector<StructureNode>
structureNodes(const MedialMesh& s)
{
  std::vector<StructureNode> nodes;
  for (const Eigen::Vector3i& t : s.triangles())
    nodes.push_back({t, false});
  for (std::size_t e = 0; e < s.numEdges(); ++e)
    if (s.isPureEdge(static_cast<int>(e)))
      nodes.push_back({Eigen::Vector3i(s.edges()[e][0], s.edges()[e][1], -1), true});
  return nodes;
}

/** Spheres of node b that node a also has, in a's order. */
std::vector<int>
sharedSpheres(const StructureNode& a, const StructureNode& b)
{
  std::vector<int> shared;
  const int na = a.is_line ? 2 : 3, nb = b.is_line ? 2 : 3;
  for (int k = 0; k < na; ++k)
    for (int l = 0; l < nb; ++l)
      if (a.v[k] == b.v[l])
        shared.push_back(a.v[k]);
  return shared;
}

/** checkMATtriangleStructureConnect: lines continue through a simple joint, or through a branch
 * point when nearly collinear; sheets continue across a manifold edge; line–sheet never. */
bool
structurallyConnected(const MedialMesh& s, const std::vector<int>& point_share,
                      const StructureNode& a, const StructureNode& b)
{
  if (a.is_line != b.is_line)
    return false;
  const std::vector<int> shared = sharedSpheres(a, b);
  if (a.is_line) {
    if (shared.empty())
      return false;
    const int p = shared.back();
    if (point_share[p] == 2)
      return true;
    const Eigen::Vector3d da = s.centers()[a.v[1]] - s.centers()[a.v[0]];
    const Eigen::Vector3d db = s.centers()[b.v[1]] - s.centers()[b.v[0]];
    const double len = da.norm() * db.norm();
    return len > 0.0 && std::abs(da.dot(db)) / len > kCollinearBranch;
  }
  if (shared.size() < 2)
    return false;
  return s.edgeTriangleCount(s.findEdge(shared[0], shared[1])) <= 2;
}

/** ρ of a component, or NaN when the component takes no part (dropped line, zero radius). */
double
slendernessRatio(const MedialMesh& s, const std::vector<int>& point_share,
                 const std::vector<StructureNode>& nodes, const std::vector<int>& component,
                 bool& is_manifold_sheet)
{
  const auto& c = s.centers();
  const auto& r = s.radii();
  const bool is_line = nodes[component.front()].is_line;
  double r_max = 0.0, r_max_inner = 0.0, measure = 0.0;
  is_manifold_sheet = !is_line;
  std::vector<std::pair<int, int>> sides; // sheet edges, to find one used >= 3 times
  for (int i : component) {
    const Eigen::Vector3i& v = nodes[i].v;
    const int n = is_line ? 2 : 3;
    for (int k = 0; k < n; ++k) {
      r_max = std::max(r_max, r[v[k]]);
      if (point_share[v[k]] <= 2)
        r_max_inner = std::max(r_max_inner, r[v[k]]);
    }
    if (is_line) {
      measure += (c[v[1]] - c[v[0]]).norm();
    }
    else {
      measure += 0.5 * (c[v[1]] - c[v[0]]).cross(c[v[2]] - c[v[0]]).norm();
      for (int k = 0; k < 3; ++k)
        sides.emplace_back(std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]));
    }
  }
  // A zero radius makes ρ infinite: such a component has no meaningful thickness (guard).
  if (!(r_max > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  if (is_line) {
    // Deviation from the reference (r_max over all endpoints): a line's branch-point spheres
    // (shared by 3+ structure nodes) sit where it joins the body, so their radius measures the
    // body's thickness, not the appendage's. Counting them made fingers, legs and fins "bulky"
    // (ρ < 8) on our structured MATs; r_max is taken over the line's own spheres when it has any.
    const double rho = measure / (r_max_inner > 0.0 ? r_max_inner : r_max);
    return rho > kDroppedLineRatio ? std::numeric_limits<double>::quiet_NaN() : rho;
  }
  std::sort(sides.begin(), sides.end());
  for (std::size_t k = 0; k + 2 < sides.size(); ++k)
    if (sides[k] == sides[k + 2])
      is_manifold_sheet = false; // an edge shared by >= 3 triangles inside the component
  return std::sqrt(measure) / r_max;
}

/** Densified points of a component (MAT::densify with 13 steps; integer steps replace the
 * reference's float accumulation, which made the sample count depend on rounding). */
void
densify(const MedialMesh& s, const std::vector<StructureNode>& nodes,
        const std::vector<int>& component, std::vector<Eigen::Vector3d>& points,
        std::vector<Eigen::Vector3d>& axes)
{
  const auto& c = s.centers();
  for (int i : component) {
    const Eigen::Vector3i& v = nodes[i].v;
    if (nodes[i].is_line) {
      const Eigen::Vector3d d = c[v[1]] - c[v[0]];
      const Eigen::Vector3d axis = d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : d;
      for (int k = 0; k <= kDensifySteps; ++k) {
        const double a = static_cast<double>(k) / kDensifySteps;
        points.push_back(a * c[v[0]] + (1.0 - a) * c[v[1]]);
        axes.push_back(axis);
      }
      continue;
    }
    for (int k = 0; k < kDensifySteps; ++k)
      for (int l = 0; k + l < kDensifySteps; ++l) {
        const double a = static_cast<double>(k) / kDensifySteps;
        const double b = static_cast<double>(l) / kDensifySteps;
        points.push_back(a * c[v[0]] + b * c[v[1]] + (1.0 - a - b) * c[v[2]]);
        axes.push_back(Eigen::Vector3d::Zero());
      }
  }
}

} // namespace

StructureTags
computeStructureTags(const MedialMesh& structured, const MatGraph& base)
{
  StructureTags tags;
  tags.node_tag.assign(base.numNodes(), 0);
  const std::vector<StructureNode> nodes = structureNodes(structured);
  if (nodes.empty())
    return tags;

  std::vector<int> point_share(structured.numVertices(), 0);
  std::vector<std::vector<int>> sphere_nodes(structured.numVertices());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int k = 0; k < (nodes[i].is_line ? 2 : 3); ++k) {
      ++point_share[nodes[i].v[k]];
      sphere_nodes[nodes[i].v[k]].push_back(static_cast<int>(i));
    }

  // Components (BFS in node order) over the structural connections.
  std::vector<std::vector<int>> thin, normal;
  std::vector<char> visited(nodes.size(), 0);
  for (std::size_t seed = 0; seed < nodes.size(); ++seed) {
    if (visited[seed])
      continue;
    std::vector<int> component{static_cast<int>(seed)};
    visited[seed] = 1;
    for (std::size_t head = 0; head < component.size(); ++head) {
      const StructureNode& a = nodes[component[head]];
      for (int k = 0; k < (a.is_line ? 2 : 3); ++k)
        for (int j : sphere_nodes[a.v[k]])
          if (!visited[j] && structurallyConnected(structured, point_share, a, nodes[j])) {
            visited[j] = 1;
            component.push_back(j);
          }
    }
    bool manifold_sheet = false;
    const double rho = slendernessRatio(structured, point_share, nodes, component, manifold_sheet);
    if (std::isnan(rho))
      continue;
    const bool is_line = nodes[component.front()].is_line;
    if (rho > kThinRatio && (is_line || manifold_sheet)) {
      thin.push_back(component);
      tags.tag_ratio.push_back(std::log2(rho));
    }
    else {
      normal.push_back(component);
    }
  }

  // Densified points, thin parts first: a tie goes to the first thin part (strict <).
  std::vector<Eigen::Vector3d> points, axes;
  std::vector<int> point_tag;
  for (std::size_t k = 0; k < thin.size(); ++k) {
    densify(structured, nodes, thin[k], points, axes);
    point_tag.resize(points.size(), static_cast<int>(k) + 1);
  }
  for (const auto& component : normal)
    densify(structured, nodes, component, points, axes);
  point_tag.resize(points.size(), 0);
  // Nothing to transfer without a thin part or a bulky line (e.g. a structured MAT of sheets).
  const bool any_line = std::any_of(normal.begin(), normal.end(), [&](const auto& component) {
    return nodes[component.front()].is_line;
  });
  if (points.empty() || (thin.empty() && !any_line))
    return tags;
  tags.node_axis.assign(base.numNodes(), Eigen::Vector3d::Zero());

  // The densified points run to tens of thousands on a structured MAT of many sheet triangles
  // (a noisy cup's wall), so the search goes through a kd-tree, exact in double with ties to the
  // lowest index, as a scan in point order would be.
  const detail::ExactPointIndex index(points);
  for (std::size_t i = 0; i < base.numNodes(); ++i) {
    // A non-finite centroid is nearest to nothing: it takes the first point.
    const std::size_t nearest =
        std::size_t(std::max(0, index.nearest(base.node(static_cast<int>(i)).centroid)));
    tags.node_tag[i] = point_tag[nearest];
    // Only bulky lines carry a direction: a thin part already has its own tag and threshold,
    // and humans keep a long curling limb (a tentacle) whole.
    if (point_tag[nearest] == 0)
      tags.node_axis[i] = axes[nearest];
  }
  // A thin part is thin against the rest of the shape. One that covers nearly all of it while
  // barely slender (a noisy bird whose body and wings merged into one manifold sheet) would only
  // raise the threshold everywhere and let growth cross the part boundaries it should find.
  std::vector<std::size_t> members(thin.size() + 1, 0);
  for (int t : tags.node_tag)
    ++members[t];
  for (int& t : tags.node_tag)
    if (t > 0 && double(members[t]) > kWholeShapeFraction * double(tags.node_tag.size()) &&
        tags.tag_ratio[t] <= std::log2(kWholeShapeThinRatio))
      t = 0;
  return tags;
}

} // namespace segmat
