/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "flat_boundaries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace segmat {
namespace detail {

double
crossingCurvature(const Eigen::Vector3d& centre_a, const Eigen::Vector3d& normal_a,
                  const Eigen::Vector3d& centre_b, const Eigen::Vector3d& normal_b)
{
  constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d step = centre_b - centre_a;
  const double distance = step.norm();
  const double la = normal_a.norm(), lb = normal_b.norm();
  if (!(distance > 0.0) || !(la > 0.0) || !(lb > 0.0))
    return kUnknown;
  const double cosine = std::clamp(normal_a.dot(normal_b) / (la * lb), -1.0, 1.0);
  const double angle = std::acos(cosine) / distance;
  if (!std::isfinite(angle))
    return kUnknown;
  // The concavity test of computeCreaseCost(), on unit normals.
  const bool concave = step.dot(normal_a / la - normal_b / lb) > 1e-6 * distance;
  return concave ? angle : -angle;
}

std::vector<int>
joinFlatBoundaries(const std::vector<int>& labels, int num_labels,
                   const std::vector<BoundaryEdge>& edges, double diagonal)
{
  // root[l]: the lowest label of l's group. Labels are few (the parts of one shape), so a
  // join simply renames the joined group.
  std::vector<int> root(std::max(num_labels, 0));
  std::iota(root.begin(), root.end(), 0);
  if (num_labels < 2 || !(diagonal > 0.0))
    return root;
  // Joining only removes boundaries: the edges between different labels are all there is.
  std::vector<BoundaryEdge> crossing;
  // An edge whose curvature is unknown (a degenerate face) tells nothing either way.
  for (const BoundaryEdge& e : edges)
    if (labels[e.a] != labels[e.b] && std::isfinite(e.curvature) && e.weight > 0.0)
      crossing.push_back(e);
  // Per pair of groups, (|curvature| × diagonal, weight) of the edges between them.
  std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> boundaries;
  for (;;) {
    boundaries.clear();
    for (const BoundaryEdge& e : crossing) {
      const int ga = root[labels[e.a]], gb = root[labels[e.b]];
      if (ga != gb)
        boundaries[{std::min(ga, gb), std::max(ga, gb)}].emplace_back(
            std::abs(e.curvature) * diagonal, e.weight);
    }
    double flattest = kFlatBoundaryCurvature;
    std::pair<int, int> join{-1, -1};
    for (auto& [pair, values] : boundaries) { // map order: ties go to the lowest pair
      std::sort(values.begin(), values.end());
      double total = 0.0;
      for (const auto& v : values)
        total += v.second;
      double below = 0.0, median = values.back().first;
      for (const auto& v : values) {
        below += v.second;
        if (below >= 0.5 * total) {
          median = v.first;
          break;
        }
      }
      if (median <= flattest && (join.first < 0 || median < flattest)) {
        flattest = median;
        join = pair;
      }
    }
    if (join.first < 0)
      break;
    std::replace(root.begin(), root.end(), join.second, join.first);
  }
  // Dense group numbers, in the order of each group's lowest label.
  std::vector<int> dense(root.size(), -1), group(root.size());
  int count = 0;
  for (int l = 0; l < num_labels; ++l) {
    if (dense[root[l]] < 0)
      dense[root[l]] = count++;
    group[l] = dense[root[l]];
  }
  return group;
}

void
indexNeighbours(BoundaryGraph& graph, int num_elements)
{
  std::vector<int>& offsets = graph.offsets;
  offsets.assign(static_cast<std::size_t>(num_elements) + 1, 0);
  for (const BoundaryEdge& e : graph.edges) {
    ++offsets[e.a + 1];
    ++offsets[e.b + 1];
  }
  for (int i = 0; i < num_elements; ++i)
    offsets[i + 1] += offsets[i];
  graph.neighbours.resize(offsets.back());
  std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
  for (const BoundaryEdge& e : graph.edges) {
    graph.neighbours[cursor[e.a]++] = e.b;
    graph.neighbours[cursor[e.b]++] = e.a;
  }
}

std::vector<BoundaryEdge>
measureSideCurvatures(const BoundaryGraph& graph, const std::vector<int>& labels,
                      const std::vector<Eigen::Vector3d>& positions)
{
  const int n = static_cast<int>(labels.size());
  const std::vector<int>& offsets = graph.offsets;
  const std::vector<Eigen::Vector3d>& normals = graph.normals;
  std::vector<BoundaryEdge> measured;
  // An element on several boundary edges has one side: it is walked once.
  std::vector<int> side_of(n, -1);
  std::vector<Eigen::Vector3d> centres, sums;
  std::vector<int> seen(n, -1), frontier, next;
  const double crease_cosine = std::cos(kSideCreaseDegrees * M_PI / 180.0);
  // Mean position and summed normal of the elements of \a from's label within kSideSteps,
  // through elements that turn less than a crease from \a from.
  const auto side = [&](int from) {
    if (side_of[from] >= 0)
      return side_of[from];
    const int stamp = side_of[from] = static_cast<int>(centres.size());
    seen[from] = stamp;
    frontier.assign(1, from);
    Eigen::Vector3d centre = positions[from], normal = normals[from];
    const double length = normal.norm();
    int count = 1;
    for (int step = 0; step < kSideSteps && length > 0.0; ++step) {
      next.clear();
      for (int i : frontier)
        for (int k = offsets[i]; k < offsets[i + 1]; ++k) {
          const int j = graph.neighbours[k];
          if (seen[j] == stamp || labels[j] != labels[from])
            continue;
          const double cosine = normals[j].dot(normals[from]);
          if (!(cosine > 0.0 && cosine >= crease_cosine * normals[j].norm() * length))
            continue;
          seen[j] = stamp;
          next.push_back(j);
          centre += positions[j];
          normal += normals[j];
          ++count;
        }
      frontier.swap(next);
    }
    centres.push_back(centre / double(count));
    sums.push_back(normal);
    return stamp;
  };
  for (const BoundaryEdge& e : graph.edges) {
    if (labels[e.a] == labels[e.b])
      continue;
    const int sa = side(e.a), sb = side(e.b);
    measured.push_back(e);
    measured.back().curvature = crossingCurvature(centres[sa], sums[sa], centres[sb], sums[sb]);
  }
  return measured;
}

pcl::PointIndices
joinParts(const std::vector<pcl::PointIndices>& parts, const std::vector<int>& members)
{
  pcl::PointIndices joined;
  for (int p : members)
    joined.indices.insert(joined.indices.end(), parts[p].indices.begin(),
                          parts[p].indices.end());
  if (members.size() > 1)
    std::sort(joined.indices.begin(), joined.indices.end());
  return joined;
}

} // namespace detail
} // namespace segmat
