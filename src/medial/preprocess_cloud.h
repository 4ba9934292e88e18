/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: step 1 of the meso-skeleton, shared with CloudSegmentation's medial-mesh
// path (implemented in meso_skeleton_estimation.cpp).

#include <segmat/medial/meso_skeleton_estimation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Step 1 of the meso-skeleton, also the cloud path's pre-processing when it builds a
 * medial mesh instead: segmat::CloudPreprocessing with \a params' working size, normal and
 * orientation neighbours, smoothing and threads.
 * \param[in] cloud the points (non-finite ones are skipped)
 * \param[in] has_normals whether \a cloud's normal fields hold normals to keep
 * \param[in] params the parameters
 * \param[out] working the resampled cloud with unit outward normals
 * \param[out] working_indices for each working point, its index in \a cloud
 * \param[out] input_to_working for each point of \a cloud, its working point (-1: none)
 * \param[in,out] stats working_points, normals_estimated and seconds_preprocessing are set
 * \return false (PCL_ERROR) when no working cloud can be made
 */
bool
preprocessCloud(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud, bool has_normals,
                const MesoSkeletonParameters& params, pcl::PointCloud<pcl::PointNormal>& working,
                std::vector<int>& working_indices, std::vector<int>& input_to_working,
                MesoSkeletonStatistics& stats);

} // namespace detail
} // namespace segmat
