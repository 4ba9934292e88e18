/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/aabb_tree.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace segmat {
namespace {

constexpr int kLeafSize = 4;

/** Segment a + t·d, t ∈ [0, 1], against a box (slab test). */
bool
segmentMeetsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& d, const Eigen::Vector3d& lo,
                const Eigen::Vector3d& hi)
{
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k])
        return false;
      continue;
    }
    const double inv = 1.0 / d[k];
    double ta = (lo[k] - a[k]) * inv, tb = (hi[k] - a[k]) * inv;
    if (ta > tb)
      std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1)
      return false;
  }
  return true;
}

} // namespace

void
AabbTree::build(const TriangleMesh& mesh)
{
  triangles_.clear();
  nodes_.clear();
  std::vector<Eigen::Vector3d> centroids;
  for (std::size_t f = 0; f < mesh.numFaces(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3d& p0 = mesh.vertices[t[0]];
    const Eigen::Vector3d e1 = mesh.vertices[t[1]] - p0, e2 = mesh.vertices[t[2]] - p0;
    if (!(e1.cross(e2).squaredNorm() > 0.0)) // degenerate or NaN: never hit
      continue;
    triangles_.push_back({p0, e1, e2});
    centroids.push_back(p0 + (e1 + e2) / 3.0);
  }
  if (triangles_.empty())
    return;
  std::vector<int> ids(triangles_.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = static_cast<int>(i);
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  buildNode(ids, centroids, 0, static_cast<int>(ids.size()));
  // Store triangles in leaf order so that a leaf is a contiguous range.
  std::vector<Triangle> ordered(triangles_.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    ordered[i] = triangles_[ids[i]];
  triangles_ = std::move(ordered);
}

int
AabbTree::buildNode(std::vector<int>& ids, std::vector<Eigen::Vector3d>& centroids, int begin,
                    int end)
{
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  Eigen::Vector3d clo = lo, chi = hi;
  for (int i = begin; i < end; ++i) {
    const Triangle& t = triangles_[ids[i]];
    for (const Eigen::Vector3d& p : {t.v0, Eigen::Vector3d(t.v0 + t.e1), Eigen::Vector3d(t.v0 + t.e2)}) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    clo = clo.cwiseMin(centroids[ids[i]]);
    chi = chi.cwiseMax(centroids[ids[i]]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  // Ties broken by index: the tree (and so the query cost) is the same on every library.
  std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end, [&](int a, int b) {
    const double ca = centroids[a][axis], cb = centroids[b][axis];
    return ca < cb || (ca == cb && a < b);
  });
  buildNode(ids, centroids, begin, mid);
  const int right = buildNode(ids, centroids, mid, end);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

bool
AabbTree::segmentIntersects(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
{
  const Eigen::Vector3d d = b - a;
  if (nodes_.empty() || !(d.squaredNorm() > 0.0))
    return false;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segmentMeetsBox(a, d, node.lo, node.hi))
      continue;
    if (node.count == 0) {
      const int left = static_cast<int>(&node - nodes_.data()) + 1;
      stack[top++] = node.first;
      stack[top++] = left;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      // Möller–Trumbore with the segment parameter restricted to [0, 1].
      const Triangle& t = triangles_[i];
      const Eigen::Vector3d p = d.cross(t.e2);
      const double det = t.e1.dot(p);
      if (det == 0.0)
        continue; // segment parallel to the plane
      const double inv = 1.0 / det;
      const Eigen::Vector3d s = a - t.v0;
      const double u = s.dot(p) * inv;
      if (u < 0.0 || u > 1.0)
        continue;
      const Eigen::Vector3d q = s.cross(t.e1);
      const double v = d.dot(q) * inv;
      if (v < 0.0 || u + v > 1.0)
        continue;
      const double tt = t.e2.dot(q) * inv;
      if (tt >= 0.0 && tt <= 1.0)
        return true;
    }
  }
  return false;
}

} // namespace segmat
