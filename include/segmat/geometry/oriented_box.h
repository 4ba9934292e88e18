/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace segmat {

/** \brief A box with any orientation: centre, three orthonormal axes and edge lengths.
 *
 * Row i of `axes` is the unit direction of the box's i-th edge and `extents[i]` that edge's full
 * length, so the box is { center + Σ t_i axes.row(i) : |t_i| ≤ extents[i] / 2 }.
 */
struct OrientedBox
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity(); ///< unit axes as rows, right-handed
  Eigen::Vector3d extents = Eigen::Vector3d::Zero();  ///< full edge lengths along the axes

  /** \brief Product of the edge lengths. */
  double
  volume() const
  {
    return extents.prod();
  }

  /** \brief True when p lies in the box grown by \a tolerance on every side. */
  bool
  contains(const Eigen::Vector3d& p, double tolerance = 0.0) const;

  /** \brief The eight corners; corner k has sign (bit i of k ? + : −) along axis i. */
  std::array<Eigen::Vector3d, 8>
  corners() const;

  /** \brief Surface of the box: 8 vertices (corners()) and 12 outward triangles. */
  TriangleMesh
  toMesh() const;
};

/** \brief The box of one part of a segmentation, with the part's label. */
struct PartBox
{
  int part = -1;          ///< the part's label (as in the .seg file)
  OrientedBox box;        ///< its box
  std::size_t points = 0; ///< number of vertices or points the box was fitted to
};

/** \brief A tight oriented bounding box of a point set: close to the minimal-volume one.
 *
 * The exact minimal-volume box (O'Rourke 1985) has a face flush with a face of the convex hull
 * or two adjacent faces flush with two hull edges; it costs O(n³). This is an approximation in
 * that spirit (as in Chang, Gorissen, Melchior 2011, "Fast oriented bounding box optimization
 * on the rotation group", which start from hull-based candidates and refine):
 *  1. the convex hull (qhull) keeps only the hull's vertices; a hull with more than 200
 *     vertices proposes its candidates (step 2) from the hull of 200 of them spread evenly
 *     (thinPointsToCount), which keeps the cost near-linear, and its 16 best candidates are
 *     redone on the whole hull;
 *  2. candidate directions for one box axis: every hull facet normal, every hull edge direction,
 *     the cross product of every pair of edge directions when there are at most 60 of them
 *     (the axis shared by two box faces each flush with an edge: O'Rourke's second case, e.g.
 *     the cube around a regular tetrahedron), the three principal axes (PCA) and the three
 *     coordinate axes;
 *  3. for each candidate axis n the hull is projected onto the plane ⊥ n and the minimal-area
 *     rectangle of that 2D hull is found by rotating calipers (Toussaint 1983; exact in 2D, one
 *     rectangle side is flush with a hull edge), giving a box of volume area × extent along n;
 *  4. the smallest box is refined by a descent over small rotations (step halving from 2°
 *     to 0.001°), which only accepts smaller boxes.
 * Step 3 is exact whenever the optimal box has a face flush with a hull facet (boxes, prisms,
 * cylinders, most CAD parts). bench/bench_box_fit measures the ratio to the known optimum
 * (docs/abstraction.md). Since the coordinate axes are candidates, the box is never larger
 * than the axis-aligned box, and since PCA axes are candidates it is never larger than the PCA
 * box. Points that are coplanar, collinear or fewer than four skip the hull (the candidates are
 * then the PCA and coordinate axes, which contain the plane's normal). The final extents are
 * measured on all points, so every point lies in the box up to rounding. Non-finite points are
 * ignored; no finite point gives a zero box at the origin.
 *
 * Axes are sorted by decreasing extent and made right-handed; the result is deterministic.
 * \param[in] points the points
 * \return the box
 */
OrientedBox
computeMinimumVolumeBox(const std::vector<Eigen::Vector3d>& points);

/** \brief The box spanned by the principal axes of the points (covariance eigenvectors), as
 * PCL's MomentOfInertiaEstimation gives it: a fast, usually looser baseline.
 */
OrientedBox
computePcaBox(const std::vector<Eigen::Vector3d>& points);

/** \brief The axis-aligned bounding box as an OrientedBox (identity axes). */
OrientedBox
computeAxisAlignedBox(const std::vector<Eigen::Vector3d>& points);

/** \brief All boxes' surfaces in one mesh (12 triangles per box, box k's faces at 12k..12k+11). */
TriangleMesh
boxesToMesh(const std::vector<OrientedBox>& boxes);

} // namespace segmat
