/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace segmat {

/** \brief Which point of an occupied voxel represents it. */
enum class VoxelPick
{
  /// The point nearest to the cell's centre, like pcl::UniformSampling. On a dense sampling the
  /// representatives then lie close to a lattice of the grid's axes.
  Centre,
  /// The point nearest to a target placed in the cell by a hash of the cell's grid coordinates
  /// (jittered, or stratified, sampling): no lattice, and still independent of the points'
  /// order, of the thread count and of where the shape sits.
  Jittered,
};

/** \brief One representative point per occupied cubic voxel.
 *
 * Voxels are cells of side \a voxel_size anchored at the points' minimum corner. In each occupied
 * cell the point nearest the cell's target (\a pick) is kept (ties: the lower index), so the
 * representatives are input points (normals and indices survive) rather than averages
 * (averaging would cancel the opposite normals of a thin plate). O(n log n), deterministic.
 * \param[in] points the points (all finite)
 * \param[in] voxel_size cell side (> 0; raised when the grid would exceed 2^21 cells per axis)
 * \param[out] representative_of for every point, the index of its cell's representative; may
 *             be nullptr
 * \param[in] pick the cell's target: its centre, or a jittered point
 * \return indices into \a points, ascending
 */
std::vector<int>
voxelRepresentatives(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                     std::vector<int>* representative_of = nullptr,
                     VoxelPick pick = VoxelPick::Centre);

/** \brief The occupied cell of every point, numbered 0..cells−1 in the order of the cells'
 * (x, y, z) grid keys. Cells as in voxelRepresentatives().
 * \param[in] points the points (all finite)
 * \param[in] voxel_size cell side (> 0)
 * \param[out] cells number of occupied cells; may be nullptr
 * \return one cell number per point
 */
std::vector<int>
voxelCellIndices(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                 std::size_t* cells = nullptr);

/** \brief A cell side whose occupied-cell count is close to a target: a few passes of a log-log
 * secant on the count, which falls like h^-2 on surfaces and h^-1 on curves (at most 8 passes,
 * stopping within about 5 %); the pass whose count is nearest to \a target in ratio wins.
 * \param[in] points the points (all finite)
 * \param[in] target wanted number of occupied cells (> 0)
 * \param[in] min_voxel_size the side is never smaller than this (then fewer cells may be used)
 * \return the side; 0 when there are at most \a target points and no minimum is given (keep
 *         every point)
 */
double
voxelSizeForCount(const std::vector<Eigen::Vector3f>& points, std::size_t target,
                  double min_voxel_size = 0.0);

/** \brief Voxel representatives whose count is close to a target.
 *
 * voxelRepresentatives() with the side from voxelSizeForCount(). Returns every index when there
 * are at most \a target points and no minimum side is given.
 * \param[in] points the points (all finite)
 * \param[in] target wanted number of representatives (> 0)
 * \param[out] voxel_size the cell side used (0 when every point was kept); may be nullptr
 * \param[in] min_voxel_size cells are never smaller than this (then fewer points may be kept)
 * \return indices into \a points, ascending
 */
std::vector<int>
voxelRepresentativesNear(const std::vector<Eigen::Vector3f>& points, std::size_t target,
                         double* voxel_size = nullptr, double min_voxel_size = 0.0);

} // namespace segmat
