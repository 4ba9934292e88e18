/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

namespace segmat {

/** \brief A plane tangent to the cone (convex hull) of two spheres: a medial cone's side (the
 * slab counterpart is computeSlabSides() in medial_primitives.h).
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
