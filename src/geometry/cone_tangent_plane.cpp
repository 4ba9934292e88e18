/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/cone_tangent_plane.h>

#include <Eigen/Geometry>

#include <cmath>

namespace segmat {

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
