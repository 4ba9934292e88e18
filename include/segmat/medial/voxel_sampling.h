/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace segmat {

/** \brief One representative point per occupied cubic voxel.
 *
 * Voxels are cells of side \a voxel_size anchored at the points' minimum corner. In each occupied
 * cell the point nearest the cell centre is kept (ties: the lower index), like
 * pcl::UniformSampling, so the representatives are input points (normals and indices survive)
 * rather than averages (averaging would cancel the opposite normals of a thin plate).
 * O(n log n), deterministic.
 * \param[in] points the points (all finite)
 * \param[in] voxel_size cell side (> 0; raised when the grid would exceed 2^21 cells per axis)
 * \return indices into \a points, ascending
 */
std::vector<int>
voxelRepresentatives(const std::vector<Eigen::Vector3f>& points, double voxel_size);

/** \brief Voxel representatives whose count is close to a target.
 *
 * Searches the voxel size (a few passes of a log-log secant on the occupied-cell count, which
 * falls like h^-2 on surfaces and h^-1 on curves; at most 8 passes, stopping within about 5 %)
 * and keeps the pass whose count is nearest to \a target in ratio. Returns every index when
 * there are at most \a target points.
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
