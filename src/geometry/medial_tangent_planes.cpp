/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_tangent_planes.h>

#include <Eigen/Geometry>

#include <cmath>

namespace segmat {

bool
slabTangentPlanes(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1, const Eigen::Vector4d& s2,
                  Eigen::Vector3d& n_plus, Eigen::Vector3d& n_minus)
{
  const Eigen::Vector3d e1 = s1.head<3>() - s0.head<3>();
  const Eigen::Vector3d e2 = s2.head<3>() - s0.head<3>();
  const Eigen::Vector3d f = e1.cross(e2);
  const double g11 = e1.squaredNorm(), g22 = e2.squaredNorm(), g12 = e1.dot(e2);
  const double det = f.squaredNorm(); // = g11·g22 − g12²
  // Relative test: sin²(angle between the sides) below 1e-16 is collinear for doubles.
  if (!(det > 1e-16 * g11 * g22) || !(g11 > 0.0) || !(g22 > 0.0))
    return false;
  // The in-plane part u of every tangent normal: e_k·u = −(r_k − r_0).
  const double h1 = -(s1[3] - s0[3]), h2 = -(s2[3] - s0[3]);
  const double alpha = (g22 * h1 - g12 * h2) / det;
  const double beta = (g11 * h2 - g12 * h1) / det;
  const Eigen::Vector3d u = alpha * e1 + beta * e2;
  const double uu = u.squaredNorm();
  if (!(uu <= 1.0))
    return false;
  const double t = std::sqrt(1.0 - uu);
  const Eigen::Vector3d fu = f / std::sqrt(det);
  n_plus = u + t * fu;
  n_minus = u - t * fu;
  return n_plus.allFinite() && n_minus.allFinite();
}

bool
coneTangentPlane(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1, double angle,
                 Eigen::Vector3d& normal)
{
  const Eigen::Vector3d axis = s1.head<3>() - s0.head<3>();
  const double len = axis.norm();
  if (!(len > 0.0))
    return false;
  const Eigen::Vector3d a = axis / len;
  const double s = -(s1[3] - s0[3]) / len; // n·a for every tangent normal
  if (!(std::abs(s) <= 1.0))
    return false;
  // Reference direction: a crossed with the coordinate axis it is least aligned with.
  int k = 0;
  if (std::abs(a[1]) < std::abs(a[k]))
    k = 1;
  if (std::abs(a[2]) < std::abs(a[k]))
    k = 2;
  const Eigen::Vector3d e1 = a.cross(Eigen::Vector3d::Unit(k)).normalized();
  const Eigen::Vector3d e2 = a.cross(e1);
  const double c = std::sqrt(1.0 - s * s);
  normal = s * a + c * (std::cos(angle) * e1 + std::sin(angle) * e2);
  return normal.allFinite();
}

} // namespace segmat
