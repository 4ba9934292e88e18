/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/ball_union_visibility.h>
#include <segmat/medial/medial_point_graph.h>
#include <segmat/segmentation/cloud_segmentation.h>
#include <segmat/segmentation/impl/cloud_segmentation.hpp>
#include <segmat/segmentation/patch_merging.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>

namespace segmat {
namespace detail {
namespace {

/** Merging of parts that a graph edge joins (SEG-MAT's three rounds, reference-facts §3.9).
 *
 * Workaround for a gap of MatRegionGrowing on point graphs: it treats two patches as adjacent
 * when they share a sphere, and point nodes (one sphere each) never share one, so it never
 * merges a cloud's parts. This runs the same rounds with the grower's public pieces
 * (radiusHistogram, maxPairwiseEmd, mergeRoundGroups, the same seed) and lets every graph edge
 * between two patches count as a shared sphere: the edge gets a sphere of its own (a copy of
 * its lower endpoint's), listed in both patches. The histograms use the patches' own spheres
 * only. To be dropped once the grower knows graph adjacency (then setMergeRounds(3) again).
 */
void
mergeGraphAdjacentParts(const MatGraph& g, const SegmentVisibility& visibility,
                        std::uint32_t seed, std::vector<std::vector<int>>& dense,
                        std::vector<std::vector<int>>& coarse)
{
  const RadiusBinning binning = makeRadiusBinning(g.radii());
  const int n = static_cast<int>(g.numNodes());
  double emd_max = 0.0;
  const std::vector<MergeRound>& rounds = defaultMergeRounds();
  for (int round = 0; round < static_cast<int>(rounds.size()) && dense.size() > 1; ++round) {
    const int patches = static_cast<int>(dense.size());
    std::vector<int> owner(n, -1);
    for (int p = 0; p < patches; ++p)
      for (int i : dense[p])
        owner[i] = p;
    std::vector<Eigen::Vector3d> centers = g.centers();
    std::vector<double> radii = g.radii();
    std::vector<std::vector<int>> spheres(patches), own(patches);
    for (int p = 0; p < patches; ++p) {
      for (int i : dense[p])
        own[p].push_back(g.node(i).v[0]);
      std::sort(own[p].begin(), own[p].end());
      own[p].erase(std::unique(own[p].begin(), own[p].end()), own[p].end());
      spheres[p] = own[p];
    }
    for (int i = 0; i < n; ++i)
      for (const int* j = g.neighboursBegin(i); j != g.neighboursEnd(i); ++j)
        if (*j > i && owner[i] >= 0 && owner[*j] >= 0 && owner[i] != owner[*j]) {
          const int edge_sphere = static_cast<int>(centers.size());
          centers.push_back(g.centers()[g.node(i).v[0]]);
          radii.push_back(g.radii()[g.node(i).v[0]]);
          spheres[owner[i]].push_back(edge_sphere);
          spheres[owner[*j]].push_back(edge_sphere);
        }
    std::vector<std::vector<double>> histograms(patches);
    for (int p = 0; p < patches; ++p) {
      std::sort(spheres[p].begin(), spheres[p].end());
      histograms[p] = radiusHistogram(own[p], g.radii(), binning);
    }
    if (round == 0)
      emd_max = maxPairwiseEmd(histograms, binning.spacing);
    const std::vector<int> group =
        mergeRoundGroups(spheres, histograms, binning.spacing, centers, radii,
                         rounds[round].emd_factor * emd_max, rounds[round].visibility_ratio,
                         visibility, seed, round);
    const int groups = *std::max_element(group.begin(), group.end()) + 1;
    std::vector<std::vector<int>> merged_dense(groups), merged_coarse(groups);
    for (int p = 0; p < patches; ++p) {
      merged_dense[group[p]].insert(merged_dense[group[p]].end(), dense[p].begin(),
                                    dense[p].end());
      merged_coarse[group[p]].insert(merged_coarse[group[p]].end(), coarse[p].begin(),
                                     coarse[p].end());
    }
    dense.swap(merged_dense);
    coarse.swap(merged_coarse);
  }
  for (auto* lists : {&dense, &coarse})
    for (std::vector<int>& list : *lists)
      std::sort(list.begin(), list.end());
}

} // namespace

bool
segmentWorkingCloud(const pcl::PointCloud<MedialPoint>::ConstPtr& skeleton,
                    const pcl::PointCloud<pcl::PointNormal>& working, int medial_k,
                    int transfer_k, bool visibility, MatRegionGrowing& grower,
                    CloudLabelTransfer& transfer, MatGraph::Ptr& graph,
                    std::vector<int>& working_labels, std::vector<int>& label_parts,
                    std::vector<pcl::PointIndices>& parts,
                    std::vector<std::pair<std::string, double>>& stage_seconds)
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

  MedialPointGraph builder;
  builder.setInputCloud(skeleton);
  builder.setKSearch(medial_k);
  graph = std::make_shared<MatGraph>();
  if (!builder.compute(*graph)) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] The MAT graph could not be built.\n");
    return false;
  }
  stage_seconds.emplace_back("graph", lap());

  grower.setInputGraph(graph);
  grower.setStructureTags(StructureTags()); // no structured MAT for a cloud: all bulky
  grower.setMergeRounds(0);                 // merged below (mergeGraphAdjacentParts)
  SegmentVisibility see;
  if (visibility)
    see = BallUnionVisibility(graph->centers(), graph->radii());
  grower.setSegmentVisibility(see);
  std::vector<pcl::PointIndices> grown;
  if (!grower.extract(grown) || grown.empty()) {
    PCL_ERROR("[segmat::CloudSegmentation::segment] Region growing failed.\n");
    return false;
  }
  std::vector<std::vector<int>> dense(grown.size()), coarse = grower.getCoarseParts();
  for (std::size_t p = 0; p < grown.size(); ++p)
    dense[p].assign(grown[p].indices.begin(), grown[p].indices.end());
  mergeGraphAdjacentParts(*graph, see, grower.getRandomSeed(), dense, coarse);
  parts.resize(dense.size());
  for (std::size_t p = 0; p < dense.size(); ++p)
    parts[p].indices.assign(dense[p].begin(), dense[p].end());
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
