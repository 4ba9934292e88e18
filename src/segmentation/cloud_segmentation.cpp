/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/ball_union_visibility.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/medial_point_graph.h>
#include <segmat/medial/normal_orientation.h>
#include <segmat/segmentation/cloud_segmentation.h>
#include <segmat/segmentation/impl/cloud_segmentation.hpp>
#include <segmat/segmentation/structure_tags.h>

#include "../common/thread_count.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <set>
#include <stdexcept>

namespace segmat {
namespace detail {
namespace {
/// Adds each stage of \a more to the stage of the same name in \a total, appending new ones.
void
addStageSeconds(const std::vector<std::pair<std::string, double>>& more,
                std::vector<std::pair<std::string, double>>& total)
{
  for (const auto& stage : more) {
    auto mine = std::find_if(total.begin(), total.end(),
                             [&](const auto& t) { return t.first == stage.first; });
    if (mine == total.end())
      total.push_back(stage);
    else
      mine->second += stage.second;
  }
}

/// Per run, the contingency of a labeling's parts (rows) with the run's labels (columns).
struct ContingencyTable
{
  int width = 0;
  std::vector<double> joint, rows;
};

std::vector<ContingencyTable>
contingencyTables(const std::vector<std::vector<int>>& labelings, const std::vector<int>& labels,
                  int count)
{
  std::vector<ContingencyTable> tables(labelings.size());
  for (std::size_t r = 0; r < labelings.size(); ++r) {
    const std::vector<int>& run = labelings[r];
    const std::size_t n = std::min(run.size(), labels.size());
    ContingencyTable& t = tables[r];
    for (std::size_t i = 0; i < n; ++i)
      t.width = std::max(t.width, run[i] + 1);
    t.joint.assign(std::size_t(count) * t.width, 0.0);
    t.rows.assign(count, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (labels[i] >= 0 && run[i] >= 0) {
        t.joint[std::size_t(labels[i]) * t.width + run[i]] += 1.0;
        t.rows[labels[i]] += 1.0;
      }
  }
  return tables;
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
medialMeshGraph(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& working,
                CloudMedialMeshEstimation& estimation, MedialMesh& base, MedialMesh& structured,
                MatGraph::Ptr& graph, StructureTags& tags,
                std::vector<std::pair<std::string, double>>& stage_seconds)
{
  auto start = std::chrono::steady_clock::now();
  estimation.setInputCloud(working);
  const bool ok = estimation.compute(base, structured);
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
retryFragmentedWithMirrorNormals(pcl::PointCloud<pcl::PointNormal>::Ptr& working, int orientation_k,
                                 CloudMedialMeshEstimation& estimation, MedialMesh& base,
                                 MedialMesh& structured, MatGraph::Ptr& graph, StructureTags& tags,
                                 std::vector<std::pair<std::string, double>>& stage_seconds)
{
  // A solid's medial axis is connected; clean clouds leave a few stray spheres (no clean
  // psb-dev cloud has more than 8 components), a plate whose normals flipped in patches leaves
  // dozens (noisy PSB chair 101: 69).
  constexpr std::size_t kFragmented = 8;
  const std::size_t components = base.numConnectedComponents();
  if (components <= kFragmented)
    return false;
  pcl::PointCloud<pcl::PointNormal>::Ptr mirrored(new pcl::PointCloud<pcl::PointNormal>(*working));
  NormalOrientation orientation;
  orientation.setKSearch(orientation_k);
  orientation.setMirrorRelationFlag(true);
  MedialMesh other_base, other_structured;
  MatGraph::Ptr other_graph;
  StructureTags other_tags;
  std::vector<std::pair<std::string, double>> other_seconds;
  const auto start = std::chrono::steady_clock::now();
  bool ok = orientation.orient(*mirrored);
  // The re-orientation counts as medial time (the first orientation is preprocessing's).
  other_seconds.emplace_back(
      "medial", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  ok = ok && medialMeshGraph(mirrored, estimation, other_base, other_structured, other_graph,
                             other_tags, other_seconds);
  // Only a clearly less fragmented axis replaces the first: near-ties swap one noisy answer for
  // another (noisy octopus 126: 85 → 84 components, and a worse score).
  const bool keep = ok && 4 * other_base.numConnectedComponents() <= 3 * components;
  if (keep) {
    working = mirrored;
    base = std::move(other_base);
    structured = std::move(other_structured);
    graph = other_graph;
    tags = std::move(other_tags);
  }
  addStageSeconds(other_seconds, stage_seconds);
  return keep;
}

bool
segmentWorkingCloud(const MatGraph::Ptr& graph, const StructureTags& tags,
                    const pcl::PointCloud<pcl::PointNormal>& working, int transfer_k,
                    bool visibility, MatRegionGrowing& grower, CloudLabelTransfer& transfer,
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

  grower.setInputGraph(graph);
  grower.setStructureTags(tags);
  SegmentVisibility see;
  if (visibility)
    see = BallUnionVisibility(graph->centers(), graph->radii());
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

double
randDistance(const std::vector<int>& a, const std::vector<int>& b)
{
  const std::size_t n = std::min(a.size(), b.size());
  int labels_a = 0, labels_b = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] >= 0 && b[i] >= 0) {
      labels_a = std::max(labels_a, a[i] + 1);
      labels_b = std::max(labels_b, b[i] + 1);
    }
  std::vector<double> joint(std::size_t(labels_a) * labels_b, 0.0), count_a(labels_a, 0.0),
      count_b(labels_b, 0.0);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] >= 0 && b[i] >= 0) {
      joint[std::size_t(a[i]) * labels_b + b[i]] += 1.0;
      count_a[a[i]] += 1.0;
      count_b[b[i]] += 1.0;
      total += 1.0;
    }
  if (total < 2.0)
    return 0.0;
  // Pairs split by exactly one labeling: together in a + together in b − 2 · together in both.
  auto pairs = [](double m) { return 0.5 * m * (m - 1.0); };
  double split = 0.0;
  for (double m : count_a)
    split += pairs(m);
  for (double m : count_b)
    split += pairs(m);
  for (double m : joint)
    split -= 2.0 * pairs(m);
  return split / pairs(total);
}

int
consensusLabeling(const std::vector<std::vector<int>>& labelings)
{
  const int count = static_cast<int>(labelings.size());
  std::vector<double> summed(count, 0.0);
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const double d = randDistance(labelings[i], labelings[j]);
      summed[i] += d;
      summed[j] += d;
    }
  int best = count > 0 ? 0 : -1;
  for (int i = 1; i < count; ++i)
    if (summed[i] < summed[best])
      best = i;
  return best;
}

std::vector<int>
mergeByConsensus(const std::vector<std::vector<int>>& labelings,
                 const std::vector<std::pair<int, int>>& edges, double threshold,
                 std::vector<int>& labels, bool keep_reproduced_cuts)
{
  int count = 0;
  for (int l : labels)
    count = std::max(count, l + 1);
  std::vector<int> into(count);
  std::iota(into.begin(), into.end(), 0);
  if (labelings.empty() || count < 2)
    return into;
  // Merging two parts adds their rows, so the co-association of the merged part needs no pass
  // over points.
  std::vector<ContingencyTable> tables = contingencyTables(labelings, labels, count);
  auto coAssociation = [&](int p, int q) {
    double sum = 0.0;
    for (const ContingencyTable& t : tables) {
      if (!(t.rows[p] > 0.0) || !(t.rows[q] > 0.0))
        continue;
      double together = 0.0;
      for (int l = 0; l < t.width; ++l)
        together += t.joint[std::size_t(p) * t.width + l] * t.joint[std::size_t(q) * t.width + l];
      sum += together / (t.rows[p] * t.rows[q]);
    }
    return sum / double(tables.size());
  };
  // A run cuts P from Q "alike" when each side is, to kCutPurity, one of its labels and the two
  // labels differ: the run reproduces the cut, wherever else its own noise cuts fall.
  constexpr double kCutPurity = 0.8;
  auto dominant = [](const ContingencyTable& t, int p) {
    int best = -1;
    double most = 0.0;
    for (int l = 0; l < t.width; ++l)
      if (t.joint[std::size_t(p) * t.width + l] > most) {
        most = t.joint[std::size_t(p) * t.width + l];
        best = l;
      }
    return most >= kCutPurity * t.rows[p] ? best : -1;
  };
  auto reproduced = [&](int p, int q) {
    int alike = 0;
    for (const ContingencyTable& t : tables) {
      if (!(t.rows[p] > 0.0) || !(t.rows[q] > 0.0))
        continue;
      const int a = dominant(t, p), b = dominant(t, q);
      alike += a >= 0 && b >= 0 && a != b;
    }
    return 3 * alike >= int(tables.size());
  };
  std::set<std::pair<int, int>> adjacent;
  for (const auto& [i, j] : edges) {
    if (i < 0 || j < 0 || std::size_t(std::max(i, j)) >= labels.size())
      continue;
    const int p = labels[i], q = labels[j];
    if (p >= 0 && q >= 0 && p != q)
      adjacent.emplace(std::min(p, q), std::max(p, q));
  }
  while (!adjacent.empty()) {
    double best = -1.0;
    std::pair<int, int> pair;
    for (const auto& candidate : adjacent) {
      const double c = coAssociation(candidate.first, candidate.second);
      if (c > best && !(keep_reproduced_cuts && reproduced(candidate.first, candidate.second))) {
        best = c;
        pair = candidate;
      }
    }
    if (!(best > threshold))
      break;
    const auto [p, q] = pair; // p < q: q goes into p
    for (ContingencyTable& t : tables) {
      for (int l = 0; l < t.width; ++l)
        t.joint[std::size_t(p) * t.width + l] += t.joint[std::size_t(q) * t.width + l];
      t.rows[p] += t.rows[q];
      t.rows[q] = 0.0;
    }
    for (int& l : labels)
      if (l == q)
        l = p;
    for (int& l : into)
      if (l == q)
        l = p;
    std::set<std::pair<int, int>> renamed;
    for (auto [a, b] : adjacent) {
      a = a == q ? p : a;
      b = b == q ? p : b;
      if (a != b)
        renamed.emplace(std::min(a, b), std::max(a, b));
    }
    adjacent.swap(renamed);
  }
  return into;
}

int
voteByConsensus(const std::vector<std::vector<int>>& labelings,
                const std::vector<std::pair<int, int>>& edges, std::vector<int>& labels)
{
  int count = 0;
  for (int l : labels)
    count = std::max(count, l + 1);
  if (labelings.empty() || count < 2)
    return 0;
  const std::size_t n = labels.size();
  // Candidates of each point besides its own part: the parts of its neighbours.
  std::vector<std::vector<int>> candidates(n);
  for (const auto& [a, b] : edges) {
    if (a < 0 || b < 0 || std::size_t(std::max(a, b)) >= n || labels[a] < 0 || labels[b] < 0 ||
        labels[a] == labels[b])
      continue;
    candidates[a].push_back(labels[b]);
    candidates[b].push_back(labels[a]);
  }
  // The votes are taken against the parts as they were before any point moves, so the result
  // does not depend on the order of the points.
  const std::vector<ContingencyTable> tables = contingencyTables(labelings, labels, count);
  std::vector<int> voted = labels;
  int moved = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (labels[i] < 0 || candidates[i].empty())
      continue;
    std::vector<int>& parts = candidates[i];
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    auto score = [&](int p) {
      double sum = 0.0;
      for (std::size_t r = 0; r < labelings.size(); ++r) {
        const ContingencyTable& t = tables[r];
        if (i >= labelings[r].size() || labelings[r][i] < 0 || !(t.rows[p] > 0.0))
          continue;
        sum += t.joint[std::size_t(p) * t.width + labelings[r][i]] / t.rows[p];
      }
      return sum;
    };
    int best = labels[i];
    double best_score = score(best);
    for (int p : parts) {
      if (p == labels[i])
        continue;
      const double s = score(p);
      if (s > best_score) { // a tie keeps the point's own part, else the lower
        best_score = s;
        best = p;
      }
    }
    if (best != labels[i]) {
      voted[i] = best;
      ++moved;
    }
  }
  labels.swap(voted);
  return moved;
}

MedialMeshRunStatus
segmentWithMedialMesh(const pcl::PointCloud<pcl::PointNormal>& working, int runs,
                      double merge_threshold, bool keep_reproduced_cuts, bool retry,
                      int orientation_k, int transfer_k, bool visibility, unsigned int threads,
                      CloudMedialMeshEstimation& estimation, const MatRegionGrowing& grower,
                      const CloudLabelTransfer& transfer, MedialMeshRun& result, int& chosen,
                      std::vector<std::pair<std::string, double>>& stage_seconds)
{
  chosen = -1;
  runs = std::max(1, runs);
  const unsigned int own_seed = estimation.getSampleOrderSeed();
  std::vector<MedialMeshRun> done(runs);
  std::vector<MedialMeshRunStatus> status(runs, MedialMeshRunStatus::Failed);
  std::vector<std::vector<std::pair<std::string, double>>> seconds(runs);
  // Each run's estimation is kept: the kept one goes back to the caller (statistics, splats).
  std::vector<CloudMedialMeshEstimation> estimations(runs, estimation);
  // The runs are independent, each with its own copies of the stages (their parameters), so
  // they may run side by side; each run's result does not depend on which thread made it.
  // Steps inside a run then get one thread (OpenMP does not nest by default).
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(threadCount(threads), runs))
  for (int run = 0; run < runs; ++run) {
    try {
      MedialMeshRun& r = done[run];
      CloudMedialMeshEstimation& run_estimation = estimations[run];
      MatRegionGrowing run_grower = grower;
      CloudLabelTransfer run_transfer = transfer;
      r.working.reset(new pcl::PointCloud<pcl::PointNormal>(working));
      // Run 0 keeps the caller's order, so one run is exactly the plain pipeline.
      run_estimation.setSampleOrderSeed(own_seed + static_cast<unsigned int>(run));
      if (!medialMeshGraph(r.working, run_estimation, r.base, r.structured, r.graph, r.tags,
                           seconds[run])) {
        status[run] = MedialMeshRunStatus::NoMedialAxis;
        continue;
      }
      if (retry)
        retryFragmentedWithMirrorNormals(r.working, orientation_k, run_estimation, r.base,
                                         r.structured, r.graph, r.tags, seconds[run]);
      if (segmentWorkingCloud(r.graph, r.tags, *r.working, transfer_k, visibility, run_grower,
                              run_transfer, r.working_labels, r.label_parts, r.parts,
                              seconds[run]))
        status[run] = MedialMeshRunStatus::Segmented;
    }
    catch (const std::exception& e) { // out of memory, most likely: the run is lost, not the process
      PCL_ERROR("[segmat::CloudSegmentation::segment] Run %d failed: %s\n", run, e.what());
    }
  }
  for (const auto& run_seconds : seconds)
    addStageSeconds(run_seconds, stage_seconds);
  // Run 0 is the plain pipeline: its outcome stands for the cloud; a later run that fails is
  // another thinning of the same cloud and is left out.
  if (status[0] != MedialMeshRunStatus::Segmented) {
    estimation = std::move(estimations[0]);
    estimation.setSampleOrderSeed(own_seed);
    return status[0];
  }
  std::vector<std::vector<int>> labelings;
  std::vector<int> run_of; // run number of each labeling
  for (int run = 0; run < runs; ++run)
    if (status[run] == MedialMeshRunStatus::Segmented) {
      labelings.push_back(std::move(done[run].working_labels));
      run_of.push_back(run);
    }
  // Each run's parts that the runs join are merged first (mergeByConsensus), so the medoid is
  // chosen among labelings whose noise cuts are gone: it then weighs where the runs differ in
  // structure, not in where the foam happened to cut.
  std::vector<std::vector<int>> merged = labelings;
  std::vector<std::vector<int>> merged_into(labelings.size());
  // The points' adjacency (for the parts' adjacency of the merge and the vote's candidates):
  // the transfer's graph of the working points (symmetric k-NN; its weights are not needed).
  std::vector<std::pair<int, int>> edges;
  if (labelings.size() > 1) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    pcl::copyPointCloud(working, *xyz);
    std::vector<int> nodes(xyz->size());
    std::iota(nodes.begin(), nodes.end(), 0);
    for (const PottsEdge& e : computeCloudSmoothnessEdges(xyz, nullptr, nodes, transfer_k, 0.0,
                                                           CreaseModel::Reference, threads))
      edges.emplace_back(e.a, e.b);
  }
  if (labelings.size() > 1 && merge_threshold <= 1.0) {
    for (std::size_t r = 0; r < merged.size(); ++r)
      merged_into[r] = mergeByConsensus(labelings, edges, merge_threshold, merged[r]);
  }
  const int kept = consensusLabeling(merged);
  chosen = run_of[kept];
  estimation = std::move(estimations[chosen]);
  estimation.setSampleOrderSeed(own_seed);
  result = std::move(done[chosen]);
  // The medoid is chosen among the plainly merged runs; the kept run is then merged again
  // keeping the cuts that a third of the runs reproduce (with them kept before the choice, the
  // majority of runs that miss such a cut would tend to be the closer to each other).
  if (keep_reproduced_cuts && labelings.size() > 1 && merge_threshold <= 1.0) {
    merged[kept] = labelings[kept];
    merged_into[kept] = mergeByConsensus(labelings, edges, merge_threshold, merged[kept], true);
  }
  result.working_labels = std::move(merged[kept]);
  // The kept run's boundaries are one run's; each point then joins the part the runs put it with
  // most often.
  if (labelings.size() > 1)
    voteByConsensus(labelings, edges, result.working_labels);
  // A merged label's MAT nodes join those of the label it went into.
  const std::vector<int>& into = merged_into[kept];
  for (std::size_t l = 0; l < into.size() && l < result.label_parts.size(); ++l) {
    if (into[l] == static_cast<int>(l))
      continue;
    auto& from = result.parts[result.label_parts[l]].indices;
    auto& to = result.parts[result.label_parts[into[l]]].indices;
    to.insert(to.end(), from.begin(), from.end());
    from.clear();
  }
  return MedialMeshRunStatus::Segmented;
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
