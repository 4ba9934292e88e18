/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/medial: local PCA and robust quadratic fits shared by the surface smoothing
// of the pre-processing and the contraction of the meso-skeleton.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Angle between two vectors in radians (0 when either is zero), argument clamped. */
double
angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/** \brief The points as a PCL cloud, for PCL's precompiled kd-tree. */
pcl::PointCloud<pcl::PointXYZ>::Ptr
toXYZ(const std::vector<Eigen::Vector3f>& points);

/** \brief Eigen-decomposition of the covariance of points[nn] (ascending eigenvalues). */
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>
neighbourhoodPca(const std::vector<Eigen::Vector3f>& points, const pcl::Indices& nn);

/** \brief What a neighbourhood looks like, from its covariance eigenvalues. */
enum class LocalShape
{
  Unknown, ///< decide from the eigenvalues
  Blob,    ///< no thin direction
  Sheet,   ///< thin in one direction (smallest eigenvalue < 0.1 × the middle one)
  Curve,   ///< thin in two directions (middle eigenvalue < 0.1 × the largest)
};

/** \brief Curve when the middle eigenvalue is below 0.1 × the largest, else sheet when the
 * smallest is below 0.1 × the middle, else blob.
 */
LocalShape
classifyShape(const Eigen::Vector3d& ascending_eigenvalues);

/** \brief A robust line through point \a self: its direction, or zero when its neighbours do
 * not lie along one.
 *
 * The line passes through the point itself (not through the neighbours' mean): the best of the
 * lines through the point and one neighbour (most neighbours within 2 scales), refitted three
 * times with Cauchy weights on the distances to it (scale 0.1 × the median neighbour
 * distance); it counts when 45 % of the neighbours lie within 2 scales of it (a line through a
 * point of a sheet holds far fewer). At the corner of a bent tube a point so finds the line of
 * its own branch — at the very corner one of the two — where PCA sees a planar L.
 * \param[out] weights the final Cauchy weight of each entry of \a nn (1 for \a self); may be
 *             nullptr
 */
Eigen::Vector3d
robustLineThrough(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn,
                  std::vector<double>* weights = nullptr);

/** \brief What C_θ should compare at medial point \a self: the curve direction where its
 * neighbours lie along one line (PCA curve-like, or PCA sheet-like — a planar L — and
 * robustLineThrough() finds one), else the
 * sheet normal (smallest PCA direction); zero when the neighbourhood is degenerate. So the two
 * branches of a bent tube meet at a sharp change of direction, as the cones of a medial mesh
 * do.
 */
Eigen::Vector3d
medialDirection(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn);

/** \brief Where point \a self should be, from a robust local fit of its neighbours.
 *
 * Gaussian weights exp(−d²/support²) about \a self; PCA frame of the neighbours; then, by
 * \a shape (or its classifyShape() when Unknown):
 *  - sheet: a quadratic height field over the tangent plane; the point keeps its tangent
 *    coordinates and takes the fitted height;
 *  - curve (not a blob, and robustLineThrough() finds a line; or PCA curve-like): a
 *    quadratic across-offset
 *    along the robust line through the point, its weights starting from that line's; the point
 *    keeps its curve coordinate;
 *  - blob: the weighted mean.
 * Fits are weighted least squares with two Cauchy reweighting passes (residual scale
 * \a residual_scale) and fall back to linear, then constant, when there are too few points or the
 * system is rank-deficient. A quadratic fit, unlike a plain mean or a plane, does not pull a
 * point towards the inside of a bent sheet or curve; the robust weights make the fit follow the
 * branch the point is on where two branches meet.
 * \param[in] points all points
 * \param[in] self the point to move
 * \param[in] nn its neighbours (including itself), \a d2 their squared distances to it
 * \param[in] support the Gaussian's scale (> 0)
 * \param[in] shape the structure to fit, or Unknown
 * \param[in] residual_scale residual at which a neighbour's weight halves (> 0)
 */
Eigen::Vector3d
fitLocalStructure(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn,
                  const std::vector<float>& d2, double support, LocalShape shape,
                  double residual_scale);

} // namespace detail
} // namespace segmat
