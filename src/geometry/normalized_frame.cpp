/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "normalized_frame.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace segmat {
namespace detail {
namespace {
// Sum of term(q) over \a q, added in sorted order: the same in any order of the points.
template <typename Term>
double
sortedSum(const std::vector<Eigen::Vector3d>& q, const Term& term)
{
  std::vector<double> terms(q.size());
  for (std::size_t i = 0; i < q.size(); ++i)
    terms[i] = term(q[i]);
  std::sort(terms.begin(), terms.end());
  return std::accumulate(terms.begin(), terms.end(), 0.0);
}

// Turns \a frame onto the principal axes of \a q (the points in \a frame) and rescales it.
void
turnToPrincipalAxes(const std::vector<Eigen::Vector3d>& q, NormalizedFrame& frame)
{
  const double n = static_cast<double>(q.size());
  Eigen::Vector3d mean;
  for (int k = 0; k < 3; ++k)
    mean[k] = sortedSum(q, [&](const Eigen::Vector3d& p) { return p[k] / n; });
  Eigen::Matrix3d covariance;
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b)
      covariance(a, b) = covariance(b, a) = sortedSum(q, [&](const Eigen::Vector3d& p) {
        return (p[a] - mean[a]) * (p[b] - mean[b]) / n;
      });
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success)
    return;
  Eigen::Matrix3d rotation;
  for (int k = 0; k < 2; ++k) { // eigenvalues ascend: the largest variance is column 2
    Eigen::Vector3d axis = solver.eigenvectors().col(2 - k);
    const double skew = sortedSum(q, [&](const Eigen::Vector3d& p) {
      const double t = axis.dot(p - mean);
      return t * t * t;
    });
    rotation.row(k) = (skew < 0.0 ? -axis : axis).transpose();
  }
  rotation.row(2) = rotation.row(0).cross(rotation.row(1)); // a rotation, not a reflection
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : q)
    box.extend(rotation * (p - mean));
  const double diagonal = box.diagonal().norm();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
    return;
  // A further power of two (exact) brings the turned box's diagonal into [1/√2, √2).
  const int exponent = std::ilogb(diagonal);
  const double adjust =
      std::ldexp(1.0, -(exponent + (std::scalbn(diagonal, -exponent) >= std::sqrt(2.0) ? 1 : 0)));
  frame.scale *= adjust;
  frame.shift = mean * adjust;
  frame.rotation = rotation;
  frame.rotated = true;
}
} // namespace

NormalizedFrame
NormalizedFrame::of(const std::vector<Eigen::Vector3d>& points, bool principal_axes)
{
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite())
      box.extend(p);
  NormalizedFrame frame;
  if (box.isEmpty())
    return frame;
  // Halves first, so that coordinates near the double limit cannot overflow; multiplying by
  // 1/2 is exact, so the centre still scales exactly with the input.
  frame.centre = box.min() * 0.5 + box.max() * 0.5;
  const Eigen::Vector3d half_extent = box.max() * 0.5 - box.min() * 0.5;
  const double largest = half_extent.maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest))
    return frame;
  // The binary exponent of diagonal × √2 = 2 × largest × relative, without forming the
  // product; the scale then puts the diagonal in [1/√2, √2).
  const double relative = (half_extent / largest).norm() * std::sqrt(2.0); // in [√2, √6]
  const int exponent = std::ilogb(largest) + 1;
  frame.scale = std::ldexp(
      1.0, -(exponent + std::ilogb(std::scalbn(largest, 1 - exponent) * relative)));
  if (principal_axes) {
    std::vector<Eigen::Vector3d> q;
    q.reserve(points.size());
    for (const Eigen::Vector3d& p : points)
      if (p.allFinite())
        q.push_back(frame.toFrame(p));
    turnToPrincipalAxes(q, frame);
  }
  return frame;
}

namespace {
// \a mat with every centre mapped by \a move and every radius multiplied by \a factor.
template <typename Move>
MedialMesh
mappedMat(const MedialMesh& mat, const Move& move, double factor)
{
  std::vector<Eigen::Vector3d> centres = mat.centers();
  std::vector<double> radii = mat.radii();
  for (Eigen::Vector3d& c : centres)
    c = move(c);
  for (double& r : radii)
    r *= factor;
  return MedialMesh(std::move(centres), std::move(radii), mat.edges(), mat.triangles());
}
} // namespace

MedialMesh
NormalizedFrame::toFrame(const MedialMesh& mat) const
{
  return mappedMat(mat, [this](const Eigen::Vector3d& c) { return toFrame(c); }, scale);
}

MedialMesh
NormalizedFrame::fromFrame(const MedialMesh& mat) const
{
  return mappedMat(mat, [this](const Eigen::Vector3d& c) { return fromFrame(c); }, 1.0 / scale);
}

TriangleMesh
NormalizedFrame::toFrame(const TriangleMesh& mesh) const
{
  std::vector<Eigen::Vector3d> moved;
  moved.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices)
    moved.push_back(toFrame(v));
  return TriangleMesh(std::move(moved), mesh.faces);
}

} // namespace detail
} // namespace segmat
