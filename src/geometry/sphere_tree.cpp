/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/sphere_tree.h>

#include <algorithm>
#include <numeric>

namespace segmat {
namespace {
constexpr int kLeafSize = 4;
}

SphereTree::SphereTree(const std::vector<Eigen::Vector3d>& centers,
                       const std::vector<double>& radii)
{
  original_.resize(std::min(centers.size(), radii.size()));
  std::iota(original_.begin(), original_.end(), 0);
  init(centers, radii);
}

SphereTree::SphereTree(const std::vector<Eigen::Vector3d>& centers,
                       const std::vector<double>& radii, const std::vector<int>& indices)
{
  const int n = static_cast<int>(std::min(centers.size(), radii.size()));
  for (int i : indices)
    if (i >= 0 && i < n)
      original_.push_back(i);
  std::sort(original_.begin(), original_.end());
  original_.erase(std::unique(original_.begin(), original_.end()), original_.end());
  init(centers, radii);
}

void
SphereTree::init(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii)
{
  // original_ holds the chosen indices, ascending.
  centers_.resize(original_.size());
  radii_.resize(original_.size());
  for (std::size_t k = 0; k < original_.size(); ++k) {
    centers_[k] = centers[original_[k]];
    radii_[k] = radii[original_[k]];
  }
  position_.assign(original_.empty() ? 0 : original_.back() + 1, -1);
  if (!original_.empty())
    build(0, static_cast<int>(original_.size())); // permutes original_
  for (std::size_t k = 0; k < original_.size(); ++k)
    position_[original_[k]] = static_cast<int>(k);
}

int
SphereTree::build(int first, int last)
{
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = first;
  node.last = last;
  node.lo = node.hi = centers_[first];
  node.max_radius = radii_[first];
  for (int k = first; k < last; ++k) {
    node.lo = node.lo.cwiseMin(centers_[k]);
    node.hi = node.hi.cwiseMax(centers_[k]);
    node.max_radius = std::max(node.max_radius, radii_[k]);
  }
  if (last - first > kLeafSize) {
    // Median split on the widest axis; the permutation is applied to all three arrays, and ties
    // are broken by the original index so the tree does not depend on the sort's stability.
    int axis = 0;
    (node.hi - node.lo).maxCoeff(&axis);
    std::vector<int> order(last - first);
    std::iota(order.begin(), order.end(), first);
    const int mid = (last - first) / 2;
    std::nth_element(order.begin(), order.begin() + mid, order.end(), [&](int a, int b) {
      return centers_[a][axis] < centers_[b][axis] ||
             (centers_[a][axis] == centers_[b][axis] && original_[a] < original_[b]);
    });
    std::vector<Eigen::Vector3d> c(order.size());
    std::vector<double> r(order.size());
    std::vector<int> o(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      c[k] = centers_[order[k]];
      r[k] = radii_[order[k]];
      o[k] = original_[order[k]];
    }
    std::copy(c.begin(), c.end(), centers_.begin() + first);
    std::copy(r.begin(), r.end(), radii_.begin() + first);
    std::copy(o.begin(), o.end(), original_.begin() + first);
    node.left = build(first, first + mid);
    node.right = build(first + mid, last);
  }
  nodes_[id] = node;
  return id;
}

double
SphereTree::signedDistance(const Eigen::Vector3d& q, double stop_below, int* nearest) const
{
  double best = std::numeric_limits<double>::infinity();
  int best_pos = -1;
  if (nodes_.empty()) {
    if (nearest)
      *nearest = -1;
    return best;
  }
  // A good first guess (the previous query's sphere) makes the bound prune from the start.
  if (nearest && *nearest >= 0 && *nearest < static_cast<int>(position_.size()) &&
      position_[*nearest] >= 0) {
    best_pos = position_[*nearest];
    best = (q - centers_[best_pos]).norm() - radii_[best_pos];
  }
  const auto lower_bound = [&](const Node& node) {
    const Eigen::Vector3d gap = (node.lo - q).cwiseMax(q - node.hi).cwiseMax(0.0);
    return gap.norm() - node.max_radius;
  };
  // Median splits keep the depth <= log2(n) + 1 and the stack never holds more than depth + 1
  // entries, so 128 cannot overflow for any n that fits in memory. Each node's bound is kept
  // from when it was pushed (one square root per node, not two).
  int stack[128];
  double bounds[128];
  int top = 0;
  stack[top] = 0;
  bounds[top++] = lower_bound(nodes_[0]);
  while (top > 0 && best > stop_below) {
    --top;
    if (bounds[top] >= best)
      continue;
    const Node& node = nodes_[stack[top]];
    if (node.left < 0) {
      for (int k = node.first; k < node.last; ++k) {
        const double d = (q - centers_[k]).norm() - radii_[k];
        if (d < best) {
          best = d;
          best_pos = k;
        }
      }
      continue;
    }
    const double bl = lower_bound(nodes_[node.left]), br = lower_bound(nodes_[node.right]);
    // Push the farther child first so the nearer one is searched first.
    const bool left_first = bl <= br;
    if (std::max(bl, br) < best) {
      stack[top] = left_first ? node.right : node.left;
      bounds[top++] = left_first ? br : bl;
    }
    if (std::min(bl, br) < best) {
      stack[top] = left_first ? node.left : node.right;
      bounds[top++] = left_first ? bl : br;
    }
  }
  if (nearest)
    *nearest = best_pos >= 0 ? original_[best_pos] : -1;
  return best;
}

} // namespace segmat
