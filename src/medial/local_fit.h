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

/** \brief Where point \a self should be, from a robust local fit of its neighbours.
 *
 * Gaussian weights exp(−d²/support²) about \a self; PCA frame of the neighbours; then, by
 * \a shape (or its classifyShape() when Unknown):
 *  - sheet: a quadratic height field over the tangent plane; the point keeps its tangent
 *    coordinates and takes the fitted height;
 *  - curve: a quadratic across-offset along the curve; the point keeps its curve coordinate;
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
