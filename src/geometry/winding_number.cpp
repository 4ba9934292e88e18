/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/face_orientation.h>
#include <segmat/geometry/winding_number.h>

#include <Eigen/Geometry>

#include <segmat/geometry/weld_points.h>

#include "edge_records.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace segmat {
namespace {
constexpr int kLeafSize = 8;
constexpr double kInvFourPi = 0.079577471545947667884; // 1 / (4π)

/** Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983):
 * tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|). Positive when the origin is
 * on the side the right-hand normal points away from. */
double
solidAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

double
triangleSolidAngle(const Eigen::Matrix3d& t, const Eigen::Vector3d& q)
{
  return solidAngle(t.col(0) - q, t.col(1) - q, t.col(2) - q);
}
} // namespace

WindingNumber::WindingNumber(const TriangleMesh& input, bool fix_orientation)
{
  // Vertices at equal positions are one vertex for orientation, closedness and edge identity:
  // work on a welded copy that keeps only usable faces (indices in range, three distinct welded
  // corners, finite coordinates), so unwelded "triangle soups" connect.
  const std::vector<int> welded = weldPoints(input.vertices, 0.0);
  const int nv = static_cast<int>(input.vertices.size());
  TriangleMesh usable;
  usable.vertices = input.vertices;
  usable.faces.reserve(input.faces.size());
  for (const Eigen::Vector3i& f : input.faces) {
    if (f.minCoeff() < 0 || f.maxCoeff() >= nv)
      continue;
    const Eigen::Vector3i id(welded[f[0]], welded[f[1]], welded[f[2]]);
    if (id[0] == id[1] || id[1] == id[2] || id[0] == id[2])
      continue;
    if (!input.vertices[f[0]].allFinite() || !input.vertices[f[1]].allFinite() ||
        !input.vertices[f[2]].allFinite())
      continue;
    usable.faces.push_back(id);
  }
  std::vector<int> sign(usable.faces.size(), 1);
  if (fix_orientation)
    sign = computeOutwardFaceSigns(usable, usable.faceAdjacency());

  std::vector<Eigen::Matrix3d> triangles;
  std::vector<Eigen::Vector3i> ids;
  std::vector<std::array<int, 3>> directed; // (lo, hi, +1 lo→hi / -1 hi→lo) of every edge
  triangles.reserve(usable.faces.size());
  ids.reserve(usable.faces.size());
  directed.reserve(usable.faces.size() * 3);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (std::size_t i = 0; i < usable.faces.size(); ++i) {
    Eigen::Vector3i id = usable.faces[i];
    if (sign[i] < 0) {
      std::swap(id[1], id[2]);
      ++num_flipped_;
    }
    Eigen::Matrix3d t;
    for (int k = 0; k < 3; ++k)
      t.col(k) = usable.vertices[id[k]];
    for (int k = 0; k < 3; ++k) {
      const int a = id[k], b = id[(k + 1) % 3];
      directed.push_back({std::min(a, b), std::max(a, b), a < b ? 1 : -1});
      lo = lo.cwiseMin(t.col(k));
      hi = hi.cwiseMax(t.col(k));
    }
    // Zero-area faces subtend no solid angle and cannot be crossed; they still count for
    // closedness above.
    if ((t.col(1) - t.col(0)).cross(t.col(2) - t.col(0)).squaredNorm() == 0.0)
      continue;
    triangles.push_back(t);
    ids.push_back(id);
  }
  const int n = static_cast<int>(triangles.size());
  if (n == 0)
    return;
  size_ = (hi - lo).norm();
  detail::sortEdgeRecords(directed, static_cast<int>(usable.vertices.size()));
  closed_ = true;
  for (std::size_t i = 0; i < directed.size() && closed_;) {
    std::size_t j = i;
    int balance = 0;
    for (; j < directed.size() && directed[j][0] == directed[i][0] &&
           directed[j][1] == directed[i][1];
         ++j)
      balance += directed[j][2];
    closed_ = balance == 0;
    i = j;
  }

  std::vector<Eigen::Vector3d> centroids(n);
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) {
    centroids[i] = triangles[i].rowwise().mean();
    order[i] = i;
  }
  nodes_.reserve(static_cast<std::size_t>(4 * n / kLeafSize + 2));
  build(0, n, centroids, order);
  triangles_.resize(n);
  corner_ids_.resize(n);
  for (int i = 0; i < n; ++i) {
    triangles_[i] = triangles[order[i]];
    corner_ids_[i] = ids[order[i]];
  }
  face_normals_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix3d& t = triangles_[i];
    const Eigen::Vector3d normal = (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
    face_normals_[i] << normal, normal.norm();
  }
  computeMoments();
  boxes_.resize(nodes_.size());
  for (std::size_t id = 0; id < nodes_.size(); ++id) {
    Box& box = boxes_[id];
    box.begin = nodes_[id].begin;
    box.end = nodes_[id].end;
    box.right = nodes_[id].right;
    box.lo = box.hi = triangles_[nodes_[id].begin].col(0);
    for (int i = nodes_[id].begin; i < nodes_[id].end; ++i) {
      box.lo = box.lo.cwiseMin(triangles_[i].rowwise().minCoeff());
      box.hi = box.hi.cwiseMax(triangles_[i].rowwise().maxCoeff());
    }
  }
}

void
WindingNumber::computeMoments()
{
  // Children come after their parent in `nodes_`, so a reverse sweep sees them first. Leaves sum
  // their faces; inner nodes shift their children's moments to their own centre, O(F) in all.
  std::vector<double> area(nodes_.size(), 0.0);
  for (int id = static_cast<int>(nodes_.size()) - 1; id >= 0; --id) {
    Node& node = nodes_[id];
    node.dipole.setZero();
    node.moment.setZero();
    for (int k = 0; k < 3; ++k)
      node.second[k].setZero();
    if (node.right < 0) {
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero(), centroid_sum = Eigen::Vector3d::Zero();
      for (int i = node.begin; i < node.end; ++i) {
        const Eigen::Matrix3d& t = triangles_[i];
        const Eigen::Vector3d area_vector =
            0.5 * (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
        const Eigen::Vector3d c = t.rowwise().mean();
        node.dipole += area_vector;
        weighted += area_vector.norm() * c;
        centroid_sum += c;
        area[id] += area_vector.norm();
      }
      node.center = area[id] > 0.0 ? Eigen::Vector3d(weighted / area[id])
                                   : Eigen::Vector3d(centroid_sum / (node.end - node.begin));
      for (int i = node.begin; i < node.end; ++i) {
        const Eigen::Matrix3d t = triangles_[i].colwise() - node.center;
        const Eigen::Vector3d area_vector =
            0.5 * (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
        const Eigen::Vector3d s = t.rowwise().sum();
        // ∫_T x dA = A·centroid and ∫_T x xᵀ dA = A/12 (Σ_a v_a v_aᵀ + s sᵀ), s = Σ_a v_a.
        node.moment += (s / 3.0) * area_vector.transpose();
        const Eigen::Matrix3d quadratic = (t * t.transpose() + s * s.transpose()) / 12.0;
        for (int k = 0; k < 3; ++k)
          node.second[k] += area_vector[k] * quadratic;
      }
    }
    else {
      const int children[2] = {id + 1, node.right};
      area[id] = area[children[0]] + area[children[1]];
      node.center = area[id] > 0.0
                        ? Eigen::Vector3d((area[children[0]] * nodes_[children[0]].center +
                                           area[children[1]] * nodes_[children[1]].center) /
                                          area[id])
                        : Eigen::Vector3d(0.5 * (nodes_[children[0]].center +
                                                 nodes_[children[1]].center));
      for (int child : children) {
        const Node& c = nodes_[child];
        // With y = x − c' and δ = c' − p̃: ∫(y + δ) nᵀ = M' + δ N'ᵀ and
        // ∫(y + δ)(y + δ)ᵀ n_k = S'_k + δ m'_kᵀ + m'_k δᵀ + δ δᵀ N'_k, m'_k = M'.col(k).
        const Eigen::Vector3d delta = c.center - node.center;
        node.dipole += c.dipole;
        node.moment += c.moment + delta * c.dipole.transpose();
        for (int k = 0; k < 3; ++k)
          node.second[k] += c.second[k] + delta * c.moment.col(k).transpose() +
                            c.moment.col(k) * delta.transpose() +
                            c.dipole[k] * delta * delta.transpose();
      }
    }
    // Exact bounding radius about the centre (a bound from the children would be looser and
    // make every query visit more nodes).
    node.radius2 = 0.0;
    for (int i = node.begin; i < node.end; ++i)
      for (int k = 0; k < 3; ++k)
        node.radius2 = std::max(node.radius2, (triangles_[i].col(k) - node.center).squaredNorm());
    for (int k = 0; k < 3; ++k)
      node.second_trace[k] = node.second[k].trace();
    node.second_diag = node.second[0].col(0) + node.second[1].col(1) + node.second[2].col(2);
  }
}

int
WindingNumber::build(int begin, int end, std::vector<Eigen::Vector3d>& centroids,
                     std::vector<int>& order)
{
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  nodes_[id].begin = begin;
  nodes_[id].end = end;
  if (end - begin <= kLeafSize)
    return id;
  Eigen::Vector3d lo = centroids[order[begin]], hi = lo;
  for (int i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(centroids[order[i]]);
    hi = hi.cwiseMax(centroids[order[i]]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  // Ties broken by face index: the hierarchy (and so every value) is deterministic.
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](int a, int b) {
                     const double ca = centroids[a][axis], cb = centroids[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  build(begin, mid, centroids, order);
  const int right = build(mid, end, centroids, order);
  nodes_[id].right = right;
  return id;
}

double
WindingNumber::operator()(const Eigen::Vector3d& q) const
{
  if (nodes_.empty() || !q.allFinite())
    return 0.0;
  const bool approximate = beta_ > 0.0 && std::isfinite(beta_);
  const double beta2 = beta_ * beta_;
  double total = 0.0; // 4π w
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const Eigen::Vector3d r = node.center - q;
    const double d2 = r.squaredNorm();
    if (approximate && d2 > beta2 * node.radius2) {
      // Taylor expansion of ∫ n·g(p) dA, g(p) = (p − q)/|p − q|³, about p̃ (Barill et al.
      // 2018): N·g + Σ ∂_j g_k M_jk + ½ Σ ∂_i∂_j g_k T_ijk with r = p̃ − q,
      // ∂_j g_k = δ_jk/|r|³ − 3 r_j r_k/|r|⁵ and
      // ∂_i∂_j g_k = −3 (δ_ij r_k + δ_ik r_j + δ_jk r_i)/|r|⁵ + 15 r_i r_j r_k/|r|⁷.
      const double inv_d2 = 1.0 / d2;
      const double inv_d3 = inv_d2 / std::sqrt(d2);
      const double cubic = r[0] * r.dot(node.second[0] * r) + r[1] * r.dot(node.second[1] * r) +
                           r[2] * r.dot(node.second[2] * r);
      const double order0 = node.dipole.dot(r);
      const double order1 = node.moment.trace() - 3.0 * inv_d2 * r.dot(node.moment * r);
      const double order2 =
          inv_d2 * (-1.5 * r.dot(node.second_trace + 2.0 * node.second_diag) +
                    7.5 * inv_d2 * cubic);
      total += inv_d3 * (order0 + order1 + order2);
      continue;
    }
    if (node.right < 0) {
      for (int i = node.begin; i < node.end; ++i)
        total += triangleSolidAngle(triangles_[i], q);
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
  return total * kInvFourPi;
}

double
WindingNumber::exact(const Eigen::Vector3d& q) const
{
  if (!q.allFinite())
    return 0.0;
  double total = 0.0;
  for (const Eigen::Matrix3d& t : triangles_)
    total += triangleSolidAngle(t, q);
  return total * kInvFourPi;
}

bool
WindingNumber::windingNumberChange(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   int& change) const
{
  change = 0;
  if (!closed_ || !from.allFinite() || !to.allFinite())
    return false;
  const Eigen::Vector3d d = to - from;
  const double length2 = d.squaredNorm();
  if (length2 == 0.0)
    return true;
  const double tolerance = 1e-10 * size_;
  const double length = std::sqrt(length2);
  // Boxes are widened by the tolerance so that near misses still reach the exact tests below.
  const Eigen::Vector3d seg_lo = from.cwiseMin(to).array() - tolerance;
  const Eigen::Vector3d seg_hi = from.cwiseMax(to).array() + tolerance;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int id = stack[--top];
    const Box& box = boxes_[id];
    // Skip nodes whose box misses the segment's box, or that the segment misses (slab test).
    if ((box.lo.array() > seg_hi.array()).any() || (box.hi.array() < seg_lo.array()).any())
      continue;
    double t_min = 0.0, t_max = 1.0;
    for (int k = 0; k < 3 && t_min <= t_max; ++k) {
      if (d[k] == 0.0)
        continue; // inside the slab already (the box test above)
      double t0 = (box.lo[k] - tolerance - from[k]) / d[k];
      double t1 = (box.hi[k] + tolerance - from[k]) / d[k];
      if (t0 > t1)
        std::swap(t0, t1);
      t_min = std::max(t_min, t0);
      t_max = std::min(t_max, t1);
    }
    if (t_min > t_max)
      continue;
    if (box.right >= 0) {
      stack[top++] = box.right;
      stack[top++] = id + 1;
      continue;
    }
    for (int i = box.begin; i < box.end; ++i) {
      const Eigen::Matrix3d& t = triangles_[i];
      const Eigen::Vector3d normal = face_normals_[i].head<3>();
      const double normal_length = face_normals_[i][3];
      // Signed distances of the end points to the face's plane.
      const double dist_from = normal.dot(from - t.col(0)) / normal_length;
      const double dist_to = normal.dot(to - t.col(0)) / normal_length;
      if ((dist_from > tolerance && dist_to > tolerance) ||
          (dist_from < -tolerance && dist_to < -tolerance))
        continue;
      // Side of the line through the segment for each edge, computed on the edge's corners in
      // ascending welded-index order so that the two faces of an edge get the very same number.
      int positive = 0, negative = 0; // edges the line clearly passes on one side of
      for (int k = 0; k < 3; ++k) {
        const int ka = k, kb = (k + 1) % 3;
        const bool ascending = corner_ids_[i][ka] < corner_ids_[i][kb];
        const Eigen::Vector3d& u = t.col(ascending ? ka : kb);
        const Eigen::Vector3d& v = t.col(ascending ? kb : ka);
        // |value| = |d| |v − u| × (distance between the two lines) × (sine of their angle).
        const double value = d.cross(u - from).dot(v - from);
        const double side = ascending ? value : -value;
        const double margin = tolerance * length * (v - u).norm();
        positive += side > margin;
        negative += side < -margin;
      }
      if (positive > 0 && negative > 0)
        continue; // the line misses the face
      if (positive < 3 && negative < 3)
        return false; // through (or next to) an edge or a corner
      if (std::abs(dist_from) <= tolerance || std::abs(dist_to) <= tolerance)
        return false; // an end point lies on the face
      change += dist_from < 0.0 ? -1 : 1; // back → front leaves the inside
    }
  }
  return true;
}

void
WindingNumber::evaluate(const std::vector<Eigen::Vector3d>& queries, std::vector<double>& values,
                        unsigned threads) const
{
  values.resize(queries.size());
  const long n = static_cast<long>(queries.size());
#ifdef _OPENMP
  const int num_threads = threads == 0 ? omp_get_max_threads() : static_cast<int>(threads);
#pragma omp parallel for schedule(dynamic, 256) num_threads(num_threads) if (num_threads > 1)
#else
  (void)threads;
#endif
  for (long i = 0; i < n; ++i)
    values[i] = (*this)(queries[i]);
}

} // namespace segmat
