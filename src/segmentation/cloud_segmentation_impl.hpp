/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: CloudSegmentation's template code, instantiated in cloud_segmentation.cpp.

#include "../common/checked_setter.h"
#include "../medial/meso_skeleton_estimation_impl.hpp"
#include <segmat/segmentation/cloud_segmentation.h>

#include "../medial/preprocess_cloud.h"
#include "cloud_segmentation_steps.h"
#include "flat_boundaries.h"

#include <pcl/common/colors.h>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/type_traits.h>

#include <chrono>
#include <cstdint>
#include <limits>

namespace segmat {

template <typename PointT>
CloudSegmentation<PointT>::CloudSegmentation()
{
  // Two α-expansion cycles, as the reference (GCO expansion(2)): a cycle costs one max-flow per
  // part on the working cloud's graph, and later cycles change few points.
  transfer_.setMaxCycles(2);
}

template <typename PointT>
void
CloudSegmentation<PointT>::setKSearch(int k)
{
  if (k <= 0) {
    PCL_WARN("[segmat::CloudSegmentation::setKSearch] k must be positive; keeping %d.\n", k_);
    return;
  }
  if (k != k_ && medial_axis_ == CloudMedialAxis::MesoSkeleton)
    field_valid_ = false; // the meso-skeleton's graph links k neighbours
  k_ = k;
}

template <typename PointT>
bool
CloudSegmentation<PointT>::computeField()
{
  field_valid_ = false;
  field_medial_ok_ = false;
  field_seconds_.clear();
  mat_statistics_ = MedialMeshEstimationStatistics();
  base_.reset();
  structured_.reset();
  skeleton_.reset(new pcl::PointCloud<MedialPoint>);
  graph_.reset();
  tags_ = StructureTags();
  stats_ = MesoSkeletonStatistics();
  working_remaining_sigma_ = 0.0;
  working_touching_ = 0.0;
  working_.reset(new pcl::PointCloud<pcl::PointNormal>);
  input_to_working_.clear();
  // Every stage works on a copy in the normalised frame (centred, scaled by a power of two) and
  // in position order, so that where the cloud lies, how large it is and the order of its points
  // cannot change its parts.
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  const bool has_normals = detail::copyToPointNormal(*input_, *indices_, *cloud);
  const detail::CloudFrame frame = detail::moveToNormalizedFrame(*cloud, *indices_);
  const MesoSkeletonParameters& params = skeleton_estimation_.getParameters();
  const bool use_normals = has_normals && params.use_input_normals;
  std::vector<int> working_indices, copy_to_working;
  MedialMesh base, structured;
  MatGraph::Ptr graph;
  bool medial_ok = false;
  if (medial_axis_ == CloudMedialAxis::MedialMesh) {
    if (detail::preprocessCloud(cloud, use_normals, params, *working_, working_indices,
                                copy_to_working, stats_)) {
      field_seconds_.emplace_back("preprocessing", stats_.seconds_preprocessing);
      medial_ok = detail::medialMeshGraph(working_, stats_.normals_estimated, params.orientation_k,
                                          mesh_estimation_, base, structured, graph, tags_,
                                          field_seconds_, mat_statistics_);
    }
  }
  else {
    medial_ok = detail::estimateMesoSkeleton(cloud, use_normals, params, *skeleton_, *working_,
                                             working_indices, copy_to_working, stats_);
    field_seconds_.emplace_back("preprocessing", stats_.seconds_preprocessing);
    field_seconds_.emplace_back("medial", stats_.seconds_balls + stats_.seconds_medial);
    if (medial_ok) {
      const auto start = std::chrono::steady_clock::now();
      if (!detail::medialPointGraph(skeleton_, k_, graph))
        return false;
      field_seconds_.emplace_back(
          "graph",
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  }
  input_to_working_ = detail::inputToWorking(input_->size(), frame.indices, copy_to_working);
  working_remaining_sigma_ = stats_.remaining_sigma; // the grower's frame
  // Measured on the medial mesh only (docs/noise.md, "Spikes in the merging").
  working_touching_ = medial_axis_ == CloudMedialAxis::MedialMesh && stats_.smoothing_passes > 0
                          ? stats_.noise_sigma
                          : 0.0;
  // What the caller reads back is in the input's frame (the graph stays in the normalised one).
  detail::moveFromNormalizedFrame(frame, frame.indices, base, structured, *skeleton_, stats_);
  if (!base.empty())
    base_ = std::make_shared<const MedialMesh>(std::move(base));
  if (!structured.empty())
    structured_ = std::make_shared<const MedialMesh>(std::move(structured));
  graph_ = medial_ok ? graph : nullptr;
  field_medial_ok_ = medial_ok;
  field_input_ = input_;
  field_size_ = input_->size();
  field_indices_ = *indices_;
  field_valid_ = true;
  return true;
}

template <typename PointT>
bool
CloudSegmentation<PointT>::segment(std::vector<pcl::PointIndices>& parts)
{
  parts.clear();
  labels_.clear();
  mat_parts_.clear();
  stage_seconds_.clear();
  if (!input_) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] No input cloud.\n");
    return false;
  }
  if (!initCompute()) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] Cannot initialise (no input?).\n");
    return false;
  }
  // The cloud is taken as unchanged while it is the same object of the same size with the same
  // indices: only the growing and the transfer run again.
  const bool reuse = field_valid_ && input_ == field_input_ && input_->size() == field_size_ &&
                     *indices_ == field_indices_;
  if (reuse) {
    for (const auto& stage : field_seconds_)
      stage_seconds_.emplace_back(stage.name, 0.0);
  }
  else {
    if (!computeField()) {
      deinitCompute();
      return false;
    }
    stage_seconds_ = field_seconds_;
  }

  if (!field_medial_ok_) {
    // No medial axis: one part when there is anything to label at all.
    pcl::PointIndices all;
    for (const auto i : *indices_)
      if (pcl::isXYZFinite((*input_)[i]))
        all.indices.push_back(i);
    if (all.indices.empty()) {
      PCL_ERROR("[segmat::CloudSegmentation::segment] The cloud has no finite point.\n");
      stage_seconds_.clear();
      deinitCompute();
      return false;
    }
    PCL_WARN("[segmat::CloudSegmentation::segment] No medial axis (the cloud encloses no "
             "volume, or has too few points): one part.\n");
    std::sort(all.indices.begin(), all.indices.end());
    all.indices.erase(std::unique(all.indices.begin(), all.indices.end()), all.indices.end());
    labels_.assign(input_->size(), -1);
    for (const auto i : all.indices)
      labels_[i] = 0;
    parts.push_back(all);
    deinitCompute();
    return true;
  }

  std::vector<int> working_labels;
  std::vector<std::vector<int>> label_parts;
  std::vector<pcl::PointIndices> grown;
  // As for meshes: radius differences within the noise that smoothing left tell nothing.
  grower_.setRadiusTolerance(working_remaining_sigma_);
  // Merging tells a noisy cloud's spikes from its parts by how its spheres touch the smoothed
  // points, within the input's noise (MatRegionGrowing::setSurfaceSamples).
  std::vector<Eigen::Vector3d> samples;
  if (working_touching_ > 0.0) {
    samples.reserve(working_->size());
    for (const auto& p : working_->points)
      samples.push_back(p.getVector3fMap().template cast<double>());
  }
  grower_.setSurfaceSamples(std::move(samples), working_touching_);
  if (!detail::segmentWorkingCloud(graph_, tags_, *working_, k_, visibility_, grower_, transfer_,
                                   working_labels, label_parts, grown, stage_seconds_)) {
    stage_seconds_.clear();
    deinitCompute();
    return false;
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<int> rank;
  detail::labelInputPoints(input_to_working_, working_labels, labels_, parts, rank);
  mat_parts_.assign(parts.size(), pcl::PointIndices());
  for (std::size_t l = 0; l < rank.size(); ++l)
    if (rank[l] >= 0)
      mat_parts_[rank[l]] = detail::joinParts(grown, label_parts[l]);
  stage_seconds_.emplace_back(
      "labels",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  deinitCompute();
  return true;
}

template <typename PointT>
bool
CloudSegmentation<PointT>::segment(std::vector<int>& labels)
{
  std::vector<pcl::PointIndices> parts;
  const bool ok = segment(parts);
  labels = labels_;
  return ok;
}

template <typename PointT>
template <typename LabeledT>
void
CloudSegmentation<PointT>::fillLabeledCloud(pcl::PointCloud<LabeledT>& cloud) const
{
  cloud.clear();
  if (!input_ || labels_.size() != input_->size())
    return;
  cloud.resize(input_->size());
  for (std::size_t i = 0; i < input_->size(); ++i) {
    LabeledT& out = cloud[i];
    out.getVector3fMap() = (*input_)[i].getVector3fMap();
    out.label = labels_[i] >= 0 ? std::uint32_t(labels_[i])
                                : std::numeric_limits<std::uint32_t>::max();
    if constexpr (pcl::traits::has_color_v<LabeledT>) {
      const pcl::RGB colour =
          labels_[i] >= 0 ? pcl::GlasbeyLUT::at(std::size_t(labels_[i]) % pcl::GlasbeyLUT::size())
                          : pcl::RGB(0, 0, 0);
      out.r = colour.r;
      out.g = colour.g;
      out.b = colour.b;
    }
  }
  cloud.width = input_->width;
  cloud.height = input_->height;
  cloud.is_dense = input_->is_dense;
}

template <typename PointT>
void
CloudSegmentation<PointT>::getLabeledCloud(pcl::PointCloud<pcl::PointXYZL>& cloud) const
{
  fillLabeledCloud(cloud);
}

template <typename PointT>
void
CloudSegmentation<PointT>::getLabeledCloud(pcl::PointCloud<pcl::PointXYZRGBL>& cloud) const
{
  fillLabeledCloud(cloud);
}

} // namespace segmat

#define SEGMAT_INSTANTIATE_CloudSegmentation(T) template class segmat::CloudSegmentation<T>;
