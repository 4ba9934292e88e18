/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Which spheres touch the surface over at least a right angle (1) and which do not (0).
 *
 * A sphere's touching samples are those at most \a tolerance outside it. Seen from its centre,
 * two touching points an angle θ apart have unit directions whose mean is cos(θ/2) long, so
 * the sphere spans a right angle when the mean of all its touching directions is at most
 * cos 45° long: the axis spheres of a tube touch a ring (a mean of about 0), the sheet spheres
 * of a box's edge two faces at 90°. The spheres of a spike, the medial branch that a bump of a
 * noisy surface sends into the shape, touch the bump's two flanks a small angle apart. This is
 * the separation angle of the θ-simplified medial axis (Foskey, Lin and Manocha, "Efficient
 * computation of a simplified medial axis", 2003) with θ = 90°.
 *
 * A sphere that touches no sample (Q-MAT moved it off the surface) or is not finite counts as
 * spanning: nothing tells that it is a spike.
 * \param[in] tolerance a length > 0, in the samples' units
 */
std::vector<char>
spheresSpanningRightAngle(const std::vector<Eigen::Vector3d>& centers,
                          const std::vector<double>& radii,
                          const std::vector<Eigen::Vector3d>& samples, double tolerance);

} // namespace detail
} // namespace segmat
