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
SphereQuadric::fromPlane(const Eigen::Vector3d& normal, const Eigen::Vector4d& sphere,
                         double weight)
{
  const double n[4] = {normal.x(), normal.y(), normal.z(), 1.0};
  const double nc = n[0] * sphere[0] + n[1] * sphere[1] + n[2] * sphere[2] + n[3] * sphere[3];
  SphereQuadric q;
  int k = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j)
      q.v_[k++] = 2.0 * weight * n[i] * n[j];
  for (int i = 0; i < 4; ++i)
    q.v_[10 + i] = 2.0 * weight * nc * n[i];
  q.v_[14] = weight * nc * nc;
  return q;
}

Eigen::Matrix4d
SphereQuadric::A() const
{
  Eigen::Matrix4d a;
  int k = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j)
      a(i, j) = a(j, i) = v_[k++];
  return a;
}

double
SphereQuadric::operator()(const Eigen::Vector4d& m) const
{
  const double x = m[0], y = m[1], z = m[2], r = m[3];
  const double diagonal = v_[0] * x * x + v_[4] * y * y + v_[7] * z * z + v_[9] * r * r;
  const double off = v_[1] * x * y + v_[2] * x * z + v_[3] * x * r + v_[5] * y * z +
                     v_[6] * y * r + v_[8] * z * r;
  return 0.5 * diagonal + off - (v_[10] * x + v_[11] * y + v_[12] * z + v_[13] * r) + v_[14];
}

bool
SphereQuadric::minimiser(Eigen::Vector4d& m) const
{
  Eigen::Matrix4d inverse;
  double det = 0.0;
  bool invertible = false;
  A().computeInverseAndDetWithCheck(inverse, det, invertible, kInverseTolerance);
  if (!invertible)
    return false;
  const Eigen::Vector4d x = inverse * b();
  if (!x.allFinite())
    return false;
  m = x;
  return true;
}

bool
SphereQuadric::invertible() const
{
  return std::abs(A().determinant()) > kInverseTolerance;
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
