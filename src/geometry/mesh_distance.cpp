/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/mesh_distance.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace segmat {

Eigen::Vector3d
closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       const Eigen::Vector3d& c)
{
  // Voronoi regions of the vertices, then of the edges, else the face (Ericson §5.1.5). Every
  // division is guarded so that degenerate triangles fall through to an edge or a vertex.
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0)
    return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0)
    return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Degenerate (zero-area) triangle: the nearest of its three sides.
    auto onSegment = [&p](const Eigen::Vector3d& s, const Eigen::Vector3d& t) {
      const Eigen::Vector3d st = t - s;
      const double len2 = st.squaredNorm();
      const double u = len2 > 0.0 ? std::clamp((p - s).dot(st) / len2, 0.0, 1.0) : 0.0;
      return Eigen::Vector3d(s + u * st);
    };
    Eigen::Vector3d best = onSegment(a, b);
    for (const Eigen::Vector3d& q : {onSegment(b, c), onSegment(c, a)})
      if ((q - p).squaredNorm() < (best - p).squaredNorm())
        best = q;
    return best;
  }
  const double v = vb / sum, w = vc / sum;
  return a + v * ab + w * ac;
}

MeshDistance::MeshDistance(const TriangleMesh& mesh)
{
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<Eigen::Vector3d> centroids;
  for (const Eigen::Vector3i& f : mesh.faces) {
    if (f.minCoeff() < 0 || f.maxCoeff() >= n)
      continue;
    Eigen::Matrix3d t;
    for (int k = 0; k < 3; ++k)
      t.col(k) = mesh.vertices[f[k]];
    if (!t.allFinite())
      continue;
    triangles_.push_back(t);
    centroids.push_back(t.rowwise().mean());
  }
  if (!triangles_.empty())
    build(0, static_cast<int>(triangles_.size()), centroids);
}

int
MeshDistance::build(int first, int last, std::vector<Eigen::Vector3d>& centroids)
{
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3d lo = triangles_[first].rowwise().minCoeff();
  Eigen::Vector3d hi = triangles_[first].rowwise().maxCoeff();
  Eigen::Vector3d clo = centroids[first], chi = centroids[first];
  for (int i = first + 1; i < last; ++i) {
    lo = lo.cwiseMin(triangles_[i].rowwise().minCoeff());
    hi = hi.cwiseMax(triangles_[i].rowwise().maxCoeff());
    clo = clo.cwiseMin(centroids[i]);
    chi = chi.cwiseMax(centroids[i]);
  }
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  nodes_[id].first = first;
  nodes_[id].last = last;
  constexpr int kLeafSize = 4;
  if (last - first <= kLeafSize)
    return id;
  // Median split of the centroids along the widest axis; faces and centroids move together.
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int mid = (first + last) / 2;
  std::vector<int> order(last - first);
  for (int i = 0; i < last - first; ++i)
    order[i] = first + i;
  std::nth_element(order.begin(), order.begin() + (mid - first), order.end(), [&](int x, int y) {
    return centroids[x][axis] < centroids[y][axis] ||
           (centroids[x][axis] == centroids[y][axis] && x < y);
  });
  std::vector<Eigen::Matrix3d> tri(last - first);
  std::vector<Eigen::Vector3d> cen(last - first);
  for (int i = 0; i < last - first; ++i) {
    tri[i] = triangles_[order[i]];
    cen[i] = centroids[order[i]];
  }
  std::copy(tri.begin(), tri.end(), triangles_.begin() + first);
  std::copy(cen.begin(), cen.end(), centroids.begin() + first);
  const int left = build(first, mid, centroids);
  const int right = build(mid, last, centroids);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

double
MeshDistance::distance(const Eigen::Vector3d& q, Eigen::Vector3d* closest) const
{
  double best2 = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (nodes_.empty())
    return best2;
  auto boxDistance2 = [&q](const Node& node) {
    return (q - q.cwiseMax(node.lo).cwiseMin(node.hi)).squaredNorm();
  };
  // Depth is about log2(F / 4) + a few (median splits): 128 entries never overflow.
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (boxDistance2(node) >= best2)
      continue;
    if (node.left < 0) {
      for (int i = node.first; i < node.last; ++i) {
        const Eigen::Matrix3d& t = triangles_[i];
        const Eigen::Vector3d c = closestPointOnTriangle(q, t.col(0), t.col(1), t.col(2));
        const double d2 = (c - q).squaredNorm();
        if (d2 < best2) {
          best2 = d2;
          best_point = c;
        }
      }
      continue;
    }
    // Nearer child last, so it is searched first.
    const double dl = boxDistance2(nodes_[node.left]), dr = boxDistance2(nodes_[node.right]);
    stack[top++] = dl < dr ? node.right : node.left;
    stack[top++] = dl < dr ? node.left : node.right;
  }
  if (closest)
    *closest = best_point;
  return std::sqrt(best2);
}

} // namespace segmat
