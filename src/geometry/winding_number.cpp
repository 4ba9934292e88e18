/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/face_orientation.h>
#include <segmat/geometry/winding_number.h>

#include <Eigen/Geometry>

#include <algorithm>
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
  const TriangleMesh* mesh = &input;
  TriangleMesh oriented;
  if (fix_orientation) {
    oriented = input;
    num_flipped_ = orientFacesOutward(oriented, 0.0);
    mesh = &oriented;
  }
  const int nv = static_cast<int>(mesh->vertices.size());
  std::vector<Eigen::Matrix3d> triangles;
  triangles.reserve(mesh->faces.size());
  for (const Eigen::Vector3i& f : mesh->faces) {
    if (f.minCoeff() < 0 || f.maxCoeff() >= nv || f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
      continue;
    Eigen::Matrix3d t;
    for (int k = 0; k < 3; ++k)
      t.col(k) = mesh->vertices[f[k]];
    // Zero-area faces subtend no solid angle; non-finite ones would poison every query.
    if (!t.allFinite() || (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0)).squaredNorm() == 0.0)
      continue;
    triangles.push_back(t);
  }
  const int n = static_cast<int>(triangles.size());
  if (n == 0)
    return;
  std::vector<Eigen::Vector3d> centroids(n);
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) {
    centroids[i] = triangles[i].rowwise().mean();
    order[i] = i;
  }
  nodes_.reserve(static_cast<std::size_t>(4 * n / kLeafSize + 2));
  build(0, n, centroids, order);
  triangles_.resize(n);
  for (int i = 0; i < n; ++i)
    triangles_[i] = triangles[order[i]];
  for (Node& node : nodes_)
    computeMoments(node);
}

void
WindingNumber::computeMoments(Node& node) const
{
  // Each node sums its own face range: O(F log F) in total, no bottom-up bookkeeping.
  double area_sum = 0.0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero(), centroid_sum = Eigen::Vector3d::Zero();
  node.dipole.setZero();
  for (int i = node.begin; i < node.end; ++i) {
    const Eigen::Matrix3d& t = triangles_[i];
    const Eigen::Vector3d area_vector = 0.5 * (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
    const double area = area_vector.norm();
    const Eigen::Vector3d c = t.rowwise().mean();
    node.dipole += area_vector;
    weighted += area * c;
    centroid_sum += c;
    area_sum += area;
  }
  node.center = area_sum > 0.0 ? Eigen::Vector3d(weighted / area_sum)
                               : Eigen::Vector3d(centroid_sum / (node.end - node.begin));
  node.moment.setZero();
  for (int k = 0; k < 3; ++k)
    node.second[k].setZero();
  node.radius2 = 0.0;
  for (int i = node.begin; i < node.end; ++i) {
    const Eigen::Matrix3d t = triangles_[i].colwise() - node.center;
    const Eigen::Vector3d area_vector = 0.5 * (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
    const Eigen::Vector3d s = t.rowwise().sum();
    // ∫_T x dA = A·centroid and ∫_T x xᵀ dA = A/12 (Σ_a v_a v_aᵀ + s sᵀ), s = Σ_a v_a.
    node.moment += (s / 3.0) * area_vector.transpose();
    const Eigen::Matrix3d quadratic = (t * t.transpose() + s * s.transpose()) / 12.0;
    for (int k = 0; k < 3; ++k)
      node.second[k] += area_vector[k] * quadratic;
    for (int k = 0; k < 3; ++k)
      node.radius2 = std::max(node.radius2, t.col(k).squaredNorm());
  }
  for (int k = 0; k < 3; ++k) {
    node.second_trace[k] = node.second[k].trace();
  }
  node.second_diag = node.second[0].col(0) + node.second[1].col(1) + node.second[2].col(2);
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
