/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

namespace segmat {

/** \brief The two planes tangent to three spheres: the sides of a medial slab (Q-MAT, Li et al.
 * 2015, §4; SEG-MAT's C_mp uses the same construction, reference-facts §3.5).
 *
 * A sphere s = (x, y, z, r). A plane with unit normal n and offset d is tangent to all three
 * spheres from outside when n·c_i + r_i = d for i = 0, 1, 2 (the spheres lie on the −n side).
 * Solved directly: n = u ± t·f with u in the plane of the centres and f the unit normal
 * (c1 − c0) × (c2 − c0); this also covers equal radii without the apex special cases of the
 * reference code.
 * \param[in] s0 first sphere
 * \param[in] s1 second sphere
 * \param[in] s2 third sphere
 * \param[out] n_plus unit normal of the side on the +f side
 * \param[out] n_minus unit normal of the side on the −f side
 * \return false when the centres are (nearly) collinear or coincide, or when no common tangent
 *         plane exists (one sphere reaches past the others' tangent cone); outputs untouched.
 */
bool
slabTangentPlanes(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1, const Eigen::Vector4d& s2,
                  Eigen::Vector3d& n_plus, Eigen::Vector3d& n_minus);

/** \brief A plane tangent to the cone (convex hull) of two spheres: a medial cone's side.
 *
 * Returns the unit normal n with n·c_0 + r_0 = n·c_1 + r_1 that makes the angle \a angle
 * (radians) around the axis c_1 − c_0, measured from a reference direction that depends only on
 * the axis direction (so the result does not depend on where the origin is).
 * \param[in] s0 first sphere
 * \param[in] s1 second sphere
 * \param[in] angle position of the plane around the axis, radians
 * \param[out] normal unit plane normal
 * \return false when the centres coincide or one sphere contains the other (no cone).
 */
bool
coneTangentPlane(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1, double angle,
                 Eigen::Vector3d& normal);

} // namespace segmat
