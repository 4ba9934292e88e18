/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace segmat {

/** \brief A 3D Delaunay tetrahedralisation as flat arrays. */
struct DelaunayTetrahedra
{
  /** Point indices of each tetrahedron. */
  std::vector<Eigen::Vector4i> tetrahedra;
  /** neighbors[t][i]: the tetrahedron across the facet opposite corner i of t, or -1 on the
   * convex hull. */
  std::vector<Eigen::Vector4i> neighbors;
};

/** \brief 3D Delaunay tetrahedralisation with qhull (reentrant libqhull_r, options
 * `d Qt Qbb Qz`: Delaunay, triangulated output, scaled paraboloid, point at infinity).
 *
 * Qt may leave flat (zero-volume) tetrahedra where input points are co-spherical; callers that
 * need circumcentres must skip those (or jitter the input, which also keeps qhull fast on
 * grid-like points). qhull's messages are captured, never printed.
 * \param[in] points the points (at least 4, not all coplanar, all finite)
 * \param[out] output the tetrahedra (cleared on failure)
 * \param[out] error_message qhull's first error line when false is returned
 * \return true on success
 */
bool
delaunayTetrahedralize(const std::vector<Eigen::Vector3d>& points, DelaunayTetrahedra& output,
                       std::string& error_message);

} // namespace segmat
