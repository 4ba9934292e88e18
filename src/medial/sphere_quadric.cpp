/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/sphere_quadric.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace segmat {

namespace {
constexpr double kInverseTolerance = 1e-12;
}

SphereQuadric
SphereQuadric::fromPlane(const Eigen::Vector3d& normal, const Eigen::Vector4d& sphere, double weight)
{
  const Eigen::Vector4d n(normal.x(), normal.y(), normal.z(), 1.0);
  const double nc = n.dot(sphere);
  SphereQuadric q;
  q.A_ = (2.0 * weight) * (n * n.transpose());
  q.b_ = (2.0 * weight * nc) * n;
  q.c_ = weight * nc * nc;
  return q;
}

bool
SphereQuadric::minimiser(Eigen::Vector4d& m) const
{
  Eigen::Matrix4d inverse;
  double det = 0.0;
  bool invertible = false;
  A_.computeInverseAndDetWithCheck(inverse, det, invertible, kInverseTolerance);
  if (!invertible)
    return false;
  const Eigen::Vector4d x = inverse * b_;
  if (!x.allFinite())
    return false;
  m = x;
  return true;
}

bool
SphereQuadric::invertible() const
{
  return std::abs(A_.determinant()) > kInverseTolerance;
}

double
stabilityRatio(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1)
{
  const double len = (s0.head<3>() - s1.head<3>()).norm();
  if (!(len > 0.0))
    return 0.0;
  return std::max(0.0, len - std::abs(s0[3] - s1[3])) / len;
}

} // namespace segmat
