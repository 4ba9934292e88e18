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
measureSideCurvatures(std::vector<BoundaryEdge>& edges, const std::vector<int>& labels,
                      const std::vector<Eigen::Vector3d>& positions,
                      const std::vector<Eigen::Vector3d>& normals)
{
  const int n = static_cast<int>(labels.size());
  // Adjacency in CSR form.
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
  for (const BoundaryEdge& e : edges) {
    ++start[e.a + 1];
    ++start[e.b + 1];
  }
  for (int i = 0; i < n; ++i)
    start[i + 1] += start[i];
  std::vector<int> adjacent(start.back()), cursor(start.begin(), start.end() - 1);
  for (const BoundaryEdge& e : edges) {
    adjacent[cursor[e.a]++] = e.b;
    adjacent[cursor[e.b]++] = e.a;
  }
  std::vector<int> seen(n, -1), frontier, next;
  int stamp = 0;
  // Mean position and summed normal of the elements of \a from's label within kSideSteps,
  // through elements that turn less than a crease from \a from.
  const double crease_cosine = std::cos(kSideCreaseDegrees * M_PI / 180.0);
  const auto side = [&](int from, Eigen::Vector3d& centre, Eigen::Vector3d& normal) {
    ++stamp;
    seen[from] = stamp;
    frontier.assign(1, from);
    centre = positions[from];
    normal = normals[from];
    const double length = normal.norm();
    int count = 1;
    for (int step = 0; step < kSideSteps && length > 0.0; ++step) {
      next.clear();
      for (int i : frontier)
        for (int k = start[i]; k < start[i + 1]; ++k) {
          const int j = adjacent[k];
          if (seen[j] == stamp || labels[j] != labels[from] ||
              !(normals[j].dot(normals[from]) >= crease_cosine * normals[j].norm() * length &&
                normals[j].dot(normals[from]) > 0.0))
            continue;
          seen[j] = stamp;
          next.push_back(j);
          centre += positions[j];
          normal += normals[j];
          ++count;
        }
      frontier.swap(next);
    }
    centre /= double(count);
  };
  for (BoundaryEdge& e : edges) {
    if (labels[e.a] == labels[e.b])
      continue;
    Eigen::Vector3d ca, na, cb, nb;
    side(e.a, ca, na);
    side(e.b, cb, nb);
    e.curvature = crossingCurvature(ca, na, cb, nb);
  }
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
