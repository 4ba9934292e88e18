/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: the untyped steps of the meso-skeleton, shared with CloudSegmentation's
// medial-mesh path (implemented in meso_skeleton_estimation.cpp).

#include <segmat/medial/meso_skeleton_estimation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace segmat {
namespace detail {

/** \brief The input-to-working map of a cloud that was copied from \a indices of the input.
 * \param[in] input_size points in the input cloud
 * \param[in] indices copy point i is input point indices[i]
 * \param[in] copy_to_working for each copy point, its working point (-1: none); may be empty
 * \return for each input point, its working point; -1 for points outside \a indices (empty
 *         when \a copy_to_working is)
 */
std::vector<int>
inputToWorking(std::size_t input_size, const pcl::Indices& indices,
               const std::vector<int>& copy_to_working);

/** \brief The meso-skeleton of a cloud given as pcl::PointNormal (the untyped core of
 * segmat::MesoSkeletonEstimation; see there).
 * \param[in] cloud the points (non-finite ones are skipped)
 * \param[in] has_normals whether \a cloud's normal fields hold the input's normals
 * \param[in] params the parameters
 * \param[out] skeleton the medial points; surface_index / contact_index index \a cloud
 * \param[out] working the resampled, oriented cloud the balls were computed on
 * \param[out] working_indices for each working point, its index in \a cloud
 * \param[out] input_to_working for each point of \a cloud, the working point standing for it
 *             (CloudPreprocessing::getInputToWorking(); -1: non-finite)
 * \param[out] stats sizes and timings
 * \return false (PCL_ERROR, empty skeleton) when the cloud cannot give a working cloud or no
 *         ball survives
 */
bool
estimateMesoSkeleton(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud, bool has_normals,
                     const MesoSkeletonParameters& params, pcl::PointCloud<MedialPoint>& skeleton,
                     pcl::PointCloud<pcl::PointNormal>& working, std::vector<int>& working_indices,
                     std::vector<int>& input_to_working, MesoSkeletonStatistics& stats);


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
