/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/ball_union_visibility.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/medial_point_graph.h>
#include <segmat/medial/normal_orientation.h>
#include <segmat/segmentation/cloud_segmentation.h>
#include <segmat/segmentation/structure_tags.h>

#include "../geometry/normalized_frame.h"
#include "../geometry/position_order.h"
#include "cloud_segmentation_impl.hpp"
#include "cloud_segmentation_steps.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <optional>

namespace segmat {
namespace detail {
namespace {

/// The components that Q-MAT leaves of \a mat: it drops isolated spheres and never joins or
/// splits the others.
std::size_t
componentsAfterQmat(const MedialMesh& mat)
{
  std::size_t isolated = 0;
  for (std::size_t v = 0; v < mat.numVertices(); ++v)
    isolated += mat.vertexEdges(int(v)).empty();
  return mat.numConnectedComponents() - isolated;
}

} // namespace

bool
medialPointGraph(const pcl::PointCloud<MedialPoint>::ConstPtr& skeleton, int k, MatGraph::Ptr& graph)
{
  MedialPointGraph builder;
  builder.setInputCloud(skeleton);
  builder.setKSearch(k);
  graph = std::make_shared<MatGraph>();
  if (!builder.compute(*graph)) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] The MAT graph could not be built.\n");
    return false;
  }
  return true;
}

bool
medialMeshGraph(pcl::PointCloud<pcl::PointNormal>::Ptr& working, bool retry_fragmented,
                int orientation_k, CloudMedialMeshEstimation& estimation, MedialMesh& base,
                MedialMesh& structured, MatGraph::Ptr& graph, StructureTags& tags,
                StageTimings& stage_seconds, MedialMeshEstimationStatistics& statistics)
{
  auto start = std::chrono::steady_clock::now();
  estimation.setInputCloud(working);
  if (!estimation.computeInitialMat()) {
    estimation.setInputCloud(nullptr);
    return false;
  }
  // A solid's medial axis is connected; clean clouds leave a few stray spheres (no clean
  // psb-dev cloud has more than 8 components), a plate whose normals flipped in patches leaves
  // dozens (noisy PSB chair 101: 69). Noise on a plate thinner than the orientation
  // neighbourhood flips patches of estimated normals, and the inside test then cuts the
  // plate's medial sheet to pieces.
  constexpr std::size_t kFragmented = 8;
  const std::size_t components =
      componentsAfterQmat(estimation.getMedialMeshEstimation().getInitialMat());
  std::optional<CloudMedialMeshEstimation> mirrored_estimation;
  CloudMedialMeshEstimation* kept = &estimation;
  if (retry_fragmented && components > kFragmented) {
    pcl::PointCloud<pcl::PointNormal>::Ptr mirrored(
        new pcl::PointCloud<pcl::PointNormal>(*working));
    NormalOrientation orientation;
    orientation.setKSearch(orientation_k);
    orientation.setMirrorRelationFlag(true);
    mirrored_estimation.emplace(estimation); // the same settings; its own initial MAT below
    mirrored_estimation->setInputCloud(mirrored);
    // Only a clearly less fragmented axis replaces the first: near-ties swap one noisy answer
    // for another (noisy octopus 126: 85 → 84 components, and a worse score).
    if (orientation.orient(*mirrored) && mirrored_estimation->computeInitialMat() &&
        4 * componentsAfterQmat(mirrored_estimation->getMedialMeshEstimation().getInitialMat()) <=
            3 * components) {
      kept = &*mirrored_estimation;
      working = mirrored;
    }
    mirrored_estimation->setInputCloud(nullptr);
  }
  const bool ok = kept->simplify(base, structured);
  statistics = kept->getStatistics();
  estimation.setInputCloud(nullptr);
  if (!ok || base.empty())
    return false;
  auto now = std::chrono::steady_clock::now();
  stage_seconds.emplace_back("medial", std::chrono::duration<double>(now - start).count());
  start = now;
  graph = std::make_shared<MatGraph>(MatGraph::fromMedialMesh(base));
  if (graph->empty()) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] The base medial mesh has no triangle and no "
              "edge.\n");
    return false;
  }
  tags = structured.empty() ? StructureTags() : computeStructureTags(structured, *graph);
  now = std::chrono::steady_clock::now();
  stage_seconds.emplace_back("graph", std::chrono::duration<double>(now - start).count());
  return true;
}

bool
segmentWorkingCloud(const MatGraph::Ptr& graph, const StructureTags& tags,
                    const pcl::PointCloud<pcl::PointNormal>& working, int transfer_k,
                    bool visibility, MatRegionGrowing& grower, CloudLabelTransfer& transfer,
                    std::vector<int>& working_labels,
                    std::vector<std::vector<int>>& label_parts,
                    std::vector<pcl::PointIndices>& parts,
                    StageTimings& stage_seconds)
{
  working_labels.clear();
  label_parts.clear();
  parts.clear();
  auto start = std::chrono::steady_clock::now();
  auto lap = [&start]() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start).count();
    start = now;
    return seconds;
  };

  grower.setInputGraph(graph);
  grower.setStructureTags(tags);
  SegmentVisibility see;
  // A medial mesh's balls are taken as they are, widened by ten times the noise that smoothing
  // left (a clean cloud: none): inflated by a tenth of each radius, the union overshoots the
  // surface in concave creases, and parts across a neck or a step see each other; on a noisy
  // cloud the balls' radii err with the smoothed surface, and the union of a thin part has gaps.
  // The remaining σ̂ measures only the roughness the passes left: the smoothed points lie about
  // six times as far from the true surface (docs/noise.md, "Limits"). The sparse balls of a
  // meso-skeleton need the inflation to bridge their gaps.
  if (visibility)
    see = graph->hasPrimitives() ? BallUnionVisibility(graph->centers(), graph->radii(), 1.0,
                                                       10.0 * grower.getRadiusTolerance())
                                 : BallUnionVisibility(graph->centers(), graph->radii());
  grower.setSegmentVisibility(see);
  std::vector<pcl::PointIndices> grown;
  if (!grower.extract(grown) || grown.empty()) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] Region growing failed.\n");
    return false;
  }
  // The grower merges parts joined by a shared sphere or a graph edge (points never share a
  // sphere).
  parts = std::move(grown);
  const std::vector<std::vector<int>>& coarse = grower.getCoarseParts();
  stage_seconds.emplace_back("grow_merge", lap());

  // The cut runs on the working cloud: it carries oriented normals (the crease term needs them)
  // and stands for every input point.
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  points->resize(working.size());
  normals->resize(working.size());
  for (std::size_t i = 0; i < working.size(); ++i) {
    (*points)[i].getVector3fMap() = working[i].getVector3fMap();
    (*normals)[i].getNormalVector3fMap() = working[i].getNormalVector3fMap();
  }
  transfer.setInputCloud(points);
  transfer.setInputNormals(normals);
  transfer.setNeighbourCount(transfer_k);
  transfer.setMaxGraphPoints(0);
  transfer.setInputGraph(graph);
  transfer.setParts(coarse);
  if (!transfer.transfer(working_labels)) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] The transfer to the points failed.\n");
    return false;
  }
  label_parts = transfer.getLabelParts();
  stage_seconds.emplace_back("transfer", lap());
  return true;
}

CloudFrame
moveToNormalizedFrame(pcl::PointCloud<pcl::PointNormal>& cloud, const pcl::Indices& indices)
{
  const std::size_t n = cloud.size();
  std::vector<Eigen::Vector3d> points(n);
  for (std::size_t i = 0; i < n; ++i)
    points[i] = cloud[i].getVector3fMap().cast<double>();
  const NormalizedFrame normalized = NormalizedFrame::of(points);
  for (std::size_t i = 0; i < n; ++i) // ordered as the later steps see them: in float
    points[i] = normalized.toFrame(points[i]).cast<float>().cast<double>();
  const std::vector<int> order = positionOrder(points);
  pcl::PointCloud<pcl::PointNormal> moved;
  moved.resize(n);
  CloudFrame frame;
  frame.indices.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    moved[k] = cloud[order[k]];
    moved[k].getVector3fMap() = points[order[k]].cast<float>();
    frame.indices[k] = indices[order[k]];
  }
  moved.width = static_cast<std::uint32_t>(n);
  moved.height = 1;
  moved.is_dense = cloud.is_dense;
  cloud.swap(moved);
  frame.centre = normalized.centre;
  frame.scale = normalized.scale;
  return frame;
}

void
moveFromNormalizedFrame(const CloudFrame& frame, const pcl::Indices& indices, MedialMesh& base,
                        MedialMesh& structured, pcl::PointCloud<MedialPoint>& skeleton,
                        MesoSkeletonStatistics& stats)
{
  NormalizedFrame normalized;
  normalized.centre = frame.centre;
  normalized.scale = frame.scale;
  if (!base.empty())
    base = normalized.fromFrame(base);
  if (!structured.empty())
    structured = normalized.fromFrame(structured);
  for (MedialPoint& m : skeleton) {
    m.getVector3fMap() = normalized.fromFrame(m.getVector3fMap().cast<double>()).cast<float>();
    m.radius = static_cast<float>(m.radius / frame.scale);
    if (m.surface_index >= 0)
      m.surface_index = indices[m.surface_index];
    if (m.contact_index >= 0)
      m.contact_index = indices[m.contact_index];
  }
  stats.noise_sigma /= frame.scale;
  stats.spacing /= frame.scale;
  stats.remaining_sigma /= frame.scale;
}

void
labelInputPoints(const std::vector<int>& input_to_working, const std::vector<int>& working_labels,
                 std::vector<int>& labels, std::vector<pcl::PointIndices>& parts,
                 std::vector<int>& rank)
{
  int num_labels = 0;
  for (int l : working_labels)
    num_labels = std::max(num_labels, l + 1);
  labels.assign(input_to_working.size(), -1);
  std::vector<std::size_t> counts(num_labels, 0);
  for (std::size_t i = 0; i < input_to_working.size(); ++i) {
    const int w = input_to_working[i];
    if (w < 0 || w >= static_cast<int>(working_labels.size()) || working_labels[w] < 0)
      continue;
    labels[i] = working_labels[w];
    ++counts[labels[i]];
  }
  std::vector<int> order(num_labels);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return counts[a] > counts[b]; });
  rank.assign(num_labels, -1);
  int used = 0;
  for (int l : order)
    if (counts[l] > 0)
      rank[l] = used++;
  parts.assign(used, pcl::PointIndices());
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] >= 0) {
      labels[i] = rank[labels[i]];
      parts[labels[i]].indices.push_back(static_cast<int>(i));
    }
}

} // namespace detail
} // namespace segmat

SEGMAT_INSTANTIATE_CloudSegmentation(pcl::PointXYZ)
SEGMAT_INSTANTIATE_CloudSegmentation(pcl::PointNormal)
SEGMAT_INSTANTIATE_CloudSegmentation(pcl::PointXYZRGBNormal)
