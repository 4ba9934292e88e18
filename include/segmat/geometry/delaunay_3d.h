/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace segmat {

/** \brief Which 3D Delaunay code to use. */
enum class DelaunayMethod
{
  Exact, ///< delaunayTetrahedralizeExact(): incremental, exact integer predicates (default)
  Qhull  ///< delaunayTetrahedralize(): qhull `d Qt Qbb Qz`
};

/** \brief A 3D Delaunay tetrahedralisation as flat arrays. */
struct DelaunayTetrahedra
{
  /** Point indices of each tetrahedron. */
  std::vector<Eigen::Vector4i> tetrahedra;
  /** neighbors[t][i]: the tetrahedron across the facet opposite corner i of t, or -1 on the
   * convex hull. */
  std::vector<Eigen::Vector4i> neighbors;
  /** The coordinates the tetrahedralisation is Delaunay for, one per input point: the input
   * itself (qhull), or the input snapped to the exact backend's integer grid. Circumcentres
   * should be computed from these. */
  std::vector<Eigen::Vector3d> points;
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

/** \brief 3D Delaunay tetrahedralisation, incremental (Bowyer–Watson) with exact predicates.
 *
 * The points are snapped to a 2^22 grid over their bounding box (a relative move of at most
 * 1.2e-7 of the box's longest side, returned in `output.points`); on that grid the orientation and
 * in-sphere determinants are computed exactly in 128-bit integers, so the result is a true
 * Delaunay tetrahedralisation of the snapped points whatever their degeneracy (ties: strict
 * in-sphere conflicts), with no flat tetrahedra. Points that snap together are inserted once
 * (the later ones are in no tetrahedron). Insertion in BRIO order (Morton-sorted rounds), point
 * location by a deterministic visibility walk; about 3–5 times faster than qhull on surface
 * samples, with the same tetrahedra on input in general position. Needs a compiler with 128-bit
 * integers (GCC, Clang); elsewhere it returns false (VoronoiMat then uses qhull).
 * \param[in] points the points (at least 4 not coplanar, all finite)
 * \param[out] output the tetrahedra, neighbours (-1 on the hull) and snapped points
 * \param[out] error_message why false was returned
 * \return true on success
 */
bool
delaunayTetrahedralizeExact(const std::vector<Eigen::Vector3d>& points, DelaunayTetrahedra& output,
                            std::string& error_message);

} // namespace segmat
