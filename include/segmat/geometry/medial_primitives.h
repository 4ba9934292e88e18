/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

namespace segmat {

/** \brief The two boundary planes of a medial slab (Q-MAT, Li et al. 2015; SEG-MAT §4.1).
 *
 * A medial slab is the convex hull of three spheres; its two flat sides are the planes tangent
 * to all three spheres. `normal[0]` is the unit normal of the side on the +n side of the medial
 * triangle (n = the orientation passed in), pointing away from the slab; `normal[1]` that of the
 * side on the −n side. `tangent[s][k]` is the point where side s touches sphere k.
 */
struct SlabSides
{
  Eigen::Vector3d normal[2];
  Eigen::Vector3d tangent[2][3];
};

/** \brief Tangent planes of the slab of three spheres.
 *
 * Same planes as the homothety construction of Q-MAT / SEG-MAT (`compute_slab`: external
 * similitude centres of the sphere pairs, then the tangent from their line), computed here
 * directly: a unit normal m of a side satisfies m·(c_k − c_0) = r_0 − r_k (k = 1, 2), which fixes
 * its in-plane part; the part along n is ±sqrt(1 − |in-plane|²). This avoids the apex
 * construction's divisions by radius differences (and its special cases for equal radii).
 *
 * \param[in] c sphere centres
 * \param[in] r sphere radii
 * \param[in] n orientation of the triangle (need not be unit; its sign picks side 0)
 * \param[out] sides the two sides
 * \return false when no slab exists: two centres closer than 1e-8, collinear centres, a sphere
 *         inside the others so that no common tangent plane exists, or a collinear tangent
 *         triangle (the reference's failure cases).
 */
bool
computeSlabSides(const Eigen::Vector3d c[3], const double r[3], const Eigen::Vector3d& n,
                 SlabSides& sides);

/** \brief Signed slope angle of the medial cone from sphere (c_from, r_from) to (c_to, r_to):
 * asin((r_from − r_to) / |c_to − c_from|), the angle between the cone's surface lines and its
 * axis, positive when the cone narrows towards c_to.
 *
 * The asin argument is clamped to [−1, 1] (one sphere inside the other gives ±π/2) and equal
 * radii give exactly 0 (sign(0) = 0; the reference computed 0/0 here).
 * Coincident centres give 0.
 */
double
coneSlopeAngle(const Eigen::Vector3d& c_from, double r_from, const Eigen::Vector3d& c_to,
               double r_to);

/** \brief acos with its argument clamped to [−1, 1] (dot products of unit vectors drift). */
double
clampedAcos(double x);

/** \brief asin with its argument clamped to [−1, 1]. */
double
clampedAsin(double x);

} // namespace segmat
