/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include "../common/checked_setter.h"
#include "preprocess_cloud.h"
#include <segmat/medial/meso_skeleton_estimation.h>

#include <pcl/console/print.h>
#include <pcl/type_traits.h>

#include <cstdint>
#include <limits>

namespace segmat {
namespace detail {

/** \brief Copies the points of \a input selected by \a indices into a pcl::PointNormal cloud
 * (normals copied when PointT has them, NaN otherwise).
 * \return whether PointT has normal fields
 */
template <typename PointT>
bool
copyToPointNormal(const pcl::PointCloud<PointT>& input, const pcl::Indices& indices,
                  pcl::PointCloud<pcl::PointNormal>& out)
{
  out.resize(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const PointT& p = input[indices[i]];
    pcl::PointNormal& q = out[i];
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    if constexpr (pcl::traits::has_normal_v<PointT>) {
      q.normal_x = p.normal_x;
      q.normal_y = p.normal_y;
      q.normal_z = p.normal_z;
    }
    else
      q.normal_x = q.normal_y = q.normal_z = std::numeric_limits<float>::quiet_NaN();
    q.curvature = 0.0f;
  }
  out.width = static_cast<std::uint32_t>(out.size());
  out.height = 1;
  return pcl::traits::has_normal_v<PointT>;
}

} // namespace detail

template <typename PointT>
void
MesoSkeletonEstimation<PointT>::setWorkingSize(std::size_t size)
{
  detail::assignChecked(params_.working_size, size, size > 0,
                        "MesoSkeletonEstimation::setWorkingSize", "positive");
}

template <typename PointT>
void
MesoSkeletonEstimation<PointT>::setNormalKSearch(int k)
{
  detail::assignChecked(params_.normal_k, k, k >= 3,
                        "MesoSkeletonEstimation::setNormalKSearch", "at least 3");
}

template <typename PointT>
void
MesoSkeletonEstimation<PointT>::setMinSeparationAngle(float angle)
{
  detail::assignChecked(params_.min_separation_angle, angle, angle >= 0.0f && angle <= 3.14159265f,
                        "MesoSkeletonEstimation::setMinSeparationAngle", "in [0, pi]");
}

template <typename PointT>
void
MesoSkeletonEstimation<PointT>::setContractionIterations(int iterations)
{
  detail::assignChecked(params_.contraction_iterations, iterations, iterations >= 0,
                        "MesoSkeletonEstimation::setContractionIterations", ">= 0");
}

template <typename PointT>
void
MesoSkeletonEstimation<PointT>::setTargetSize(std::size_t size)
{
  detail::assignChecked(params_.target_size, size, size > 0,
                        "MesoSkeletonEstimation::setTargetSize", "positive");
}

template <typename PointT>
bool
MesoSkeletonEstimation<PointT>::compute(pcl::PointCloud<MedialPoint>& skeleton)
{
  skeleton.clear();
  working_.clear();
  working_indices_.clear();
  input_to_working_.clear();
  stats_ = MesoSkeletonStatistics();
  if (!input_) {
    PCL_ERROR("[segmat::MesoSkeletonEstimation::compute] No input cloud.\n");
    return false;
  }
  if (!initCompute()) {
    PCL_ERROR("[segmat::MesoSkeletonEstimation::compute] Cannot initialise (no input?).\n");
    return false;
  }
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  std::vector<int> copy_to_working;
  const bool has_normals = detail::copyToPointNormal(*input_, *indices_, *cloud);
  const bool ok = detail::estimateMesoSkeleton(cloud, has_normals && params_.use_input_normals,
                                               params_, skeleton, working_, working_indices_,
                                               copy_to_working, stats_);
  // Indices into the copy → indices into the input cloud.
  const pcl::Indices& map = *indices_;
  for (int& i : working_indices_)
    i = map[i];
  input_to_working_ = detail::inputToWorking(input_->size(), map, copy_to_working);
  for (MedialPoint& m : skeleton) {
    if (m.surface_index >= 0)
      m.surface_index = map[m.surface_index];
    if (m.contact_index >= 0)
      m.contact_index = map[m.contact_index];
  }
  deinitCompute();
  return ok;
}

} // namespace segmat

#define SEGMAT_INSTANTIATE_MesoSkeletonEstimation(T) template class segmat::MesoSkeletonEstimation<T>;
