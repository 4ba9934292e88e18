/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_primitives.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace segmat {

double
clampedAcos(double x)
{
  return std::acos(std::clamp(x, -1.0, 1.0));
}

double
clampedAsin(double x)
{
  return std::asin(std::clamp(x, -1.0, 1.0));
}

bool
computeSlabSides(const Eigen::Vector3d c[3], const double r[3], const Eigen::Vector3d& n,
                 SlabSides& sides)
{
  // The reference's epsilon for concentric spheres (compute_slab).
  constexpr double kCoincident = 1e-8;
  const Eigen::Vector3d e1 = c[1] - c[0], e2 = c[2] - c[0];
  if (e1.norm() < kCoincident || e2.norm() < kCoincident || (c[2] - c[1]).norm() < kCoincident)
    return false;
  Eigen::Vector3d axis = e1.cross(e2);
  const double twice_area = axis.norm();
  if (!(twice_area > 1e-12 * e1.norm() * e2.norm())) // collinear centres (or NaN)
    return false;
  axis /= twice_area;
  if (axis.dot(n) < 0.0)
    axis = -axis;

  // In-plane part p = a·e1 + b·e2 of a side normal: p·e1 = r0 − r1, p·e2 = r0 − r2 (Gram system,
  // determinant |e1 × e2|² > 0).
  const double g11 = e1.squaredNorm(), g12 = e1.dot(e2), g22 = e2.squaredNorm();
  const double d1 = r[0] - r[1], d2 = r[0] - r[2];
  const double det = twice_area * twice_area;
  const double a = (d1 * g22 - d2 * g12) / det;
  const double b = (d2 * g11 - d1 * g12) / det;
  const Eigen::Vector3d p = a * e1 + b * e2;
  const double q = p.squaredNorm();
  if (!(q <= 1.0)) // the reference's sinφ > 1: no plane touches all three spheres
    return false;
  const double height = std::sqrt(1.0 - q);
  sides.normal[0] = p + height * axis;
  sides.normal[1] = p - height * axis;
  for (int s = 0; s < 2; ++s) {
    for (int k = 0; k < 3; ++k)
      sides.tangent[s][k] = c[k] + r[k] * sides.normal[s];
    const Eigen::Vector3d t1 = sides.tangent[s][1] - sides.tangent[s][0];
    const Eigen::Vector3d t2 = sides.tangent[s][2] - sides.tangent[s][0];
    if (!(t1.cross(t2).norm() > 1e-12 * t1.norm() * t2.norm())) // collinear tangent triangle
      return false;
  }
  return true;
}

double
coneSlopeAngle(const Eigen::Vector3d& c_from, double r_from, const Eigen::Vector3d& c_to,
               double r_to)
{
  const double length = (c_to - c_from).norm();
  const double dr = r_from - r_to;
  if (dr == 0.0 || !(length > 0.0))
    return 0.0;
  return clampedAsin(dr / length);
}

} // namespace segmat
