/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "growing_cost.h"
#include "../common/checked_setter.h"
#include <segmat/segmentation/mat_region_growing.h>
#include "patch_merging.h"
#include "spanning_spheres.h"

#include "../common/exact_point_index.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace segmat {
namespace {

/** A part while it is built: grown (coarse) nodes and all its nodes (dense). */
struct Patch
{
  std::vector<int> coarse;
  std::vector<int> dense;
};

/** Sorted unique spheres of a node list. */
std::vector<int>
spheresOf(const MatGraph& g, const std::vector<int>& nodes)
{
  std::vector<int> s;
  for (int i : nodes)
    for (int k = 0; k < g.node(i).size(); ++k)
      s.push_back(g.node(i).v[k]);
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

/** Tiny-patch absorption (the authors' `MergeTinyPatches`). Each tiny patch joins the
 * dense patch that overlaps it (some pair of spheres with |c1 − c2| < r1 + r2) with the lowest
 * score 0.5·EMD_norm + 0.5·distance_norm, both min–max normalised over the candidates (a term
 * with max == min counts 0). Fixes: a single candidate is taken (the reference skipped it and
 * left the patch unassigned), equal distances give 0 (not 0/0), ties go to the lower patch.
 * Without a candidate the patch joins the dense patch with the nearest sphere centre. Scores are
 * computed against the dense patches as grown, so the result does not depend on the order in
 * which tiny patches are absorbed.
 */
void
absorbTinyPatches(const MatGraph& g, const std::vector<std::vector<int>>& tiny,
                  const RadiusBinning& binning, const detail::ExactPointIndex& index, std::vector<Patch>& patches)
{
  if (tiny.empty() || patches.empty())
    return;
  const auto& c = g.centers();
  const auto& r = g.radii();
  const double r_max = *std::max_element(r.begin(), r.end());
  std::vector<std::vector<int>> dense_spheres;
  std::vector<std::vector<double>> dense_hist;
  std::vector<std::vector<int>> owners(g.numSpheres());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    dense_spheres.push_back(spheresOf(g, patches[p].dense));
    dense_hist.push_back(radiusHistogram(dense_spheres.back(), r, binning));
    for (int s : dense_spheres.back())
      owners[s].push_back(static_cast<int>(p));
  }

  std::vector<int> target(tiny.size(), -1);
  std::vector<int> near;
  for (std::size_t t = 0; t < tiny.size(); ++t) {
    const std::vector<int> spheres = spheresOf(g, tiny[t]);
    std::vector<int> candidates;
    for (int s : spheres) {
      index.within(c[s], r[s] + r_max, near);
      for (int q : near)
        if ((c[s] - c[q]).norm() < r[s] + r[q])
          candidates.insert(candidates.end(), owners[q].begin(), owners[q].end());
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    if (candidates.empty()) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t q = 0; q < owners.size(); ++q)
        for (int o : owners[q])
          for (int s : spheres) {
            const double d = (c[s] - c[q]).norm();
            if (d < best || (d == best && o < target[t])) {
              best = d;
              target[t] = o;
            }
          }
      if (target[t] < 0)
        target[t] = 0; // NaN coordinates: any patch is as good as another
      continue;
    }

    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int s : spheres)
      centroid += c[s];
    centroid /= static_cast<double>(spheres.size());
    const std::vector<double> hist = radiusHistogram(spheres, r, binning);
    std::vector<double> emd(candidates.size()), dist(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const int d = candidates[k];
      emd[k] = histogramEmd(hist, dense_hist[d], binning.spacing);
      dist[k] = std::numeric_limits<double>::infinity();
      for (int q : dense_spheres[d])
        dist[k] = std::min(dist[k], (centroid - c[q]).norm() - r[q]);
    }
    const auto normalised = [](const std::vector<double>& v, std::size_t k) {
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      return *hi > *lo ? (v[k] - *lo) / (*hi - *lo) : 0.0;
    };
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const double score = 0.5 * normalised(emd, k) + 0.5 * normalised(dist, k);
      if (score < best || target[t] < 0) {
        best = score;
        target[t] = candidates[k];
      }
    }
  }
  for (std::size_t t = 0; t < tiny.size(); ++t)
    patches[target[t]].dense.insert(patches[target[t]].dense.end(), tiny[t].begin(),
                                    tiny[t].end());
}

/** Large leftovers are shared out, not absorbed whole (not in the reference). Under noise the
 * regions stop after a few nodes and what none of them took forms one connected leftover of up
 * to a fifth of the graph (Mech 321 with 0.5 % noise: 813 of 3 724 nodes); absorbed whole into
 * one dense patch it distorts that patch's radius histogram and adjacency until real parts
 * merge, or it stays a part of its own. A leftover of at least \a min_size nodes is therefore
 * split among the dense patches by a breadth-first search from all of them at once: each of its
 * nodes joins the patch that reaches it first (ties: the lower node that reaches it, in queue
 * order, which depends only on the graph). Nodes no patch reaches, and smaller leftovers, stay
 * in \a tiny for absorbTinyPatches().
 */
void
splitLargeLeftovers(const MatGraph& g, std::vector<std::vector<int>>& tiny,
                    std::vector<Patch>& patches, std::size_t min_size)
{
  const int n = static_cast<int>(g.numNodes());
  // owner: -2 not in a leftover being split, -1 not reached yet, else the patch
  std::vector<int> owner(n, -2);
  std::vector<std::vector<int>> keep, large;
  for (auto& t : tiny) {
    if (t.size() < min_size) {
      keep.push_back(std::move(t));
      continue;
    }
    for (int i : t)
      owner[i] = -1;
    large.push_back(std::move(t));
  }
  if (large.empty()) { // nothing to split (no clean psb-dev shape reaches the limit)
    tiny = std::move(keep);
    return;
  }
  std::vector<int> queue;
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (int i : patches[p].dense)
      owner[i] = static_cast<int>(p);
  for (int i = 0; i < n; ++i)
    if (owner[i] >= 0)
      queue.push_back(i);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    for (const int* it = g.neighboursBegin(i); it != g.neighboursEnd(i); ++it)
      if (owner[*it] == -1) {
        owner[*it] = owner[i];
        patches[owner[i]].dense.push_back(*it);
        queue.push_back(*it);
      }
  }
  // A leftover is connected: the search reaches all of it or, when no patch touches it (a graph
  // component without a region), none of it. The latter stays a tiny patch.
  for (auto& t : large)
    if (owner[t.front()] == -1)
      keep.push_back(std::move(t));
  tiny = std::move(keep);
}

/** Patch pairs joined by a MAT-graph edge. On a medial mesh every such pair already shares a
 * sphere (graph edges join nodes with a common sphere), so this only adds adjacency for medial
 * points, which have one sphere each: one merging rule then serves meshes and clouds.
 */
std::vector<std::pair<int, int>>
graphEdgePairs(const MatGraph& g, const std::vector<Patch>& patches)
{
  if (g.hasPrimitives())
    return {};
  std::vector<int> owner(g.numNodes(), -1);
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (int i : patches[p].dense)
      owner[i] = static_cast<int>(p);
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < static_cast<int>(g.numNodes()); ++i)
    for (const int* j = g.neighboursBegin(i); j != g.neighboursEnd(i); ++j) {
      const int a = owner[i], b = owner[*j];
      if (a >= 0 && b >= 0 && a < b)
        pairs.emplace_back(a, b);
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

/** Merging rounds (the authors' `MergeIterations`). EMD_max is taken once, over all pairs
 * of the patches entering round 1, as in the reference. A merged patch takes the place of its
 * lowest member and concatenates the members' nodes in patch order. A patch's histogram counts
 * its spheres flagged in \a in_histogram (all of them when it has none flagged, or when the
 * flags are empty).
 */
void
mergePatches(const MatGraph& g, const RadiusBinning& binning, int rounds,
             const SegmentVisibility& visibility, unsigned seed,
             const std::vector<char>& in_histogram, std::vector<Patch>& patches)
{
  double emd_max = 0.0;
  for (int round = 0; round < rounds && patches.size() > 1; ++round) {
    std::vector<std::vector<int>> spheres;
    std::vector<std::vector<double>> hist;
    std::vector<int> counted;
    for (const Patch& p : patches) {
      spheres.push_back(spheresOf(g, p.dense));
      counted.clear();
      if (!in_histogram.empty())
        for (const int s : spheres.back())
          if (in_histogram[s])
            counted.push_back(s);
      hist.push_back(
          radiusHistogram(counted.empty() ? spheres.back() : counted, g.radii(), binning));
    }
    if (round == 0)
      emd_max = maxPairwiseEmd(hist, binning.spacing);
    const MergeRound& settings = defaultMergeRounds()[round];
    const std::vector<int> group =
        mergeRoundGroups(spheres, hist, binning.spacing, g.centers(), g.radii(),
                         settings.emd_factor * emd_max, settings.visibility_ratio, visibility,
                         seed, round, graphEdgePairs(g, patches));
    std::vector<Patch> merged(*std::max_element(group.begin(), group.end()) + 1);
    for (std::size_t p = 0; p < patches.size(); ++p) {
      Patch& into = merged[group[p]];
      into.coarse.insert(into.coarse.end(), patches[p].coarse.begin(), patches[p].coarse.end());
      into.dense.insert(into.dense.end(), patches[p].dense.begin(), patches[p].dense.end());
    }
    patches = std::move(merged);
  }
}

} // namespace

MatRegionGrowing::MatRegionGrowing()
: delta0_(0.015)
, eta_(0.002)
, alpha_(0.05)
, lambda_(1.5)
, use_primitive_term_(true)
, merge_rounds_(3)
, max_seed_radius_ratio_(3.0)
, max_bend_angle_(60.0)
, radius_tolerance_(0.0)
, touching_tolerance_(0.0)
, seed_(0x5e6a7u)
{}

void
MatRegionGrowing::setInputGraph(const MatGraph::ConstPtr& graph)
{
  graph_ = graph;
}

void
MatRegionGrowing::setStructureTags(const StructureTags& tags)
{
  tags_ = tags;
}

void
MatRegionGrowing::setGrowingThreshold(double delta0)
{
  detail::assignChecked(delta0_, delta0, delta0 > 0.0 && std::isfinite(delta0),
                        "MatRegionGrowing::setGrowingThreshold", "finite and > 0");
}

void
MatRegionGrowing::setMinRegionFraction(double eta)
{
  detail::assignChecked(eta_, eta, eta >= 0.0 && eta <= 1.0,
                        "MatRegionGrowing::setMinRegionFraction", "in [0, 1]");
}

void
MatRegionGrowing::setAngleWeight(double alpha)
{
  detail::assignChecked(alpha_, alpha, alpha >= 0.0 && std::isfinite(alpha),
                        "MatRegionGrowing::setAngleWeight", "finite and >= 0");
}

void
MatRegionGrowing::setPrimitiveWeight(double lambda)
{
  detail::assignChecked(lambda_, lambda, lambda >= 0.0 && std::isfinite(lambda),
                        "MatRegionGrowing::setPrimitiveWeight", "finite and >= 0");
}

void
MatRegionGrowing::setMaxBendAngle(double degrees)
{
  detail::assignChecked(max_bend_angle_, degrees, degrees > 0.0 && degrees <= 90.0,
                        "MatRegionGrowing::setMaxBendAngle", "in (0, 90]");
}

void
MatRegionGrowing::setRadiusTolerance(double length)
{
  detail::assignChecked(radius_tolerance_, length, length >= 0.0 && std::isfinite(length),
                        "MatRegionGrowing::setRadiusTolerance", "finite and >= 0");
}

void
MatRegionGrowing::setSurfaceSamples(std::vector<Eigen::Vector3d> samples, double tolerance)
{
  if (detail::assignChecked(touching_tolerance_, tolerance,
                            tolerance >= 0.0 && std::isfinite(tolerance),
                            "MatRegionGrowing::setSurfaceSamples", "finite and >= 0"))
    surface_samples_ = std::move(samples);
}

void
MatRegionGrowing::setMaxSeedRadiusRatio(double ratio)
{
  detail::assignChecked(max_seed_radius_ratio_, ratio, ratio >= 1.0,
                        "MatRegionGrowing::setMaxSeedRadiusRatio",
                        ">= 1 (infinity disables the guard)");
}

void
MatRegionGrowing::setMergeRounds(int rounds)
{
  const int available = static_cast<int>(defaultMergeRounds().size());
  if (rounds < 0 || rounds > available) {
    PCL_WARN("[segmat::MatRegionGrowing::setMergeRounds] %d is not in [0, %d]; keeping %d.\n",
             rounds, available, merge_rounds_);
    return;
  }
  merge_rounds_ = rounds;
}

void
MatRegionGrowing::clearOutput()
{
  coarse_parts_.clear();
  node_labels_.clear();
  grown_region_sizes_.clear();
  tiny_patch_sizes_.clear();
}

bool
MatRegionGrowing::extract(std::vector<pcl::PointIndices>& parts)
{
  parts.clear();
  clearOutput();
  if (!graph_ || graph_->empty()) {
    PCL_ERROR("[segmat::MatRegionGrowing::extract] No input graph, or it is empty.\n");
    return false;
  }
  const MatGraph& g = *graph_;
  const int n = static_cast<int>(g.numNodes());

  // Structural tags: all 0 unless a matching set was given.
  std::vector<int> tag(n, 0);
  if (tags_.node_tag.size() == static_cast<std::size_t>(n)) {
    tag = tags_.node_tag;
    int unknown = 0;
    for (int& t : tag)
      if (t < 0 || t >= static_cast<int>(tags_.tag_ratio.size()) ||
          !std::isfinite(tags_.tag_ratio[t])) {
        t = 0;
        ++unknown;
      }
    if (unknown > 0)
      PCL_WARN("[segmat::MatRegionGrowing::extract] %d nodes carry a tag without a finite "
               "ratio; treated as 0.\n",
               unknown);
  }
  else if (!tags_.node_tag.empty()) {
    PCL_WARN("[segmat::MatRegionGrowing::extract] %zu structure tags for %d nodes; ignored.\n",
             tags_.node_tag.size(), n);
  }

  GrowingCostWeights weights;
  weights.alpha = alpha_;
  weights.lambda = lambda_;
  weights.use_primitive_term = use_primitive_term_ && g.hasPrimitives();
  weights.radius_tolerance = radius_tolerance_;

  // η counts spheres (base-MAT vertices), not nodes, as the authors' `RegionGrowing`; at least
  // one node.
  const int min_region =
      std::max(1, static_cast<int>(eta_ * static_cast<double>(g.numSpheres())));

  // Seeds by decreasing mean radius; stable, so ties go to the smaller index (the reference's
  // std::sort left ties unordered). A NaN radius sorts last.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto key = [&g](int i) {
    const double r = g.node(i).mean_radius;
    return std::isnan(r) ? -std::numeric_limits<double>::infinity() : r;
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) > key(b); });

  std::vector<std::vector<int>> sphere_nodes(g.numSpheres());
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < g.node(i).size(); ++k)
      sphere_nodes[g.node(i).v[k]].push_back(i);
  const detail::ExactPointIndex index(g.centers());

  // Tube directions of the nodes (zero: not on a structured line); see setMaxBendAngle().
  static const std::vector<Eigen::Vector3d> no_axes;
  const std::vector<Eigen::Vector3d>& axis =
      tags_.node_axis.size() == static_cast<std::size_t>(n) ? tags_.node_axis : no_axes;
  // 90° disables the guard: |cos| < cos 90° would still reject exact right angles.
  const double bend_cos = max_bend_angle_ >= 90.0 ? -1.0 : std::cos(max_bend_angle_ * M_PI / 180.0);

  std::vector<char> visited(n, 0);
  std::vector<char> sphere_queried(g.numSpheres(), 0);
  std::vector<Patch> patches;
  std::vector<int> region, near;
  for (int seed : order) {
    if (visited[seed])
      continue;
    // Breadth-first growth; the test is local: current node against neighbour.
    region.assign(1, seed);
    visited[seed] = 1;
    Eigen::Vector3d region_axis =
        axis.empty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : axis[seed];
    for (std::size_t head = 0; head < region.size(); ++head) {
      const int i = region[head];
      for (const int* it = g.neighboursBegin(i); it != g.neighboursEnd(i); ++it) {
        const int j = *it;
        if (visited[j])
          continue;
        // Thickness guard (not in the reference): the growing test is local, so a run of
        // small steps (each C_r below δ0, e.g. 1 % per node along a tapering finger or a
        // vase's neck) lets one region drift from the body far into a limb. A part whose
        // nodes are more than max_seed_radius_ratio_ times thinner than its seed — the
        // thickest node, seeds come in decreasing radius — is no longer one part; such
        // nodes are left for a later seed. NaN radii fail the comparison and may join. It
        // matters most inside thin parts, whose threshold δ0·log2 ρ lets larger steps chain.
        if (g.node(j).mean_radius * max_seed_radius_ratio_ < g.node(seed).mean_radius)
          continue;
        if (!axis.empty() && !region_axis.isZero() && !axis[j].isZero() &&
            std::abs(region_axis.dot(axis[j])) < bend_cos)
          continue;
        const double t = growingThreshold(delta0_, tag[i], tag[j], tags_.tag_ratio);
        if (growingCost(g, i, j, weights) <= t) {
          visited[j] = 1;
          region.push_back(j);
          if (!axis.empty() && region_axis.isZero())
            region_axis = axis[j];
        }
      }
    }
    if (static_cast<int>(region.size()) < min_region) {
      for (int i : region)
        visited[i] = 0; // released: these nodes may seed or join later
      continue;
    }
    // Swallowing: every free node with a sphere centre strictly inside a sphere of the region.
    // A sphere queried once has already swallowed all it can: visited nodes stay visited.
    Patch patch;
    patch.coarse = region;
    patch.dense = region;
    for (int s : spheresOf(g, region)) {
      if (sphere_queried[s])
        continue;
      sphere_queried[s] = 1;
      index.within(g.centers()[s], g.radii()[s], near);
      for (int q : near)
        for (int j : sphere_nodes[q])
          if (!visited[j]) {
            visited[j] = 1;
            patch.dense.push_back(j);
          }
    }
    grown_region_sizes_.push_back(static_cast<int>(region.size()));
    patches.push_back(std::move(patch));
  }

  // Leftovers: connected components of free nodes (the start node is marked at once; the
  // reference did not, and could list it twice).
  std::vector<std::vector<int>> tiny;
  for (int s = 0; s < n; ++s) {
    if (visited[s])
      continue;
    std::vector<int> component{s};
    visited[s] = 1;
    for (std::size_t head = 0; head < component.size(); ++head)
      for (const int* it = g.neighboursBegin(component[head]);
           it != g.neighboursEnd(component[head]); ++it)
        if (!visited[*it]) {
          visited[*it] = 1;
          component.push_back(*it);
        }
    tiny_patch_sizes_.push_back(static_cast<int>(component.size()));
    tiny.push_back(std::move(component));
  }

  const RadiusBinning binning = makeRadiusBinning(g.radii());
  if (patches.empty()) {
    // No region reached the minimal size: the leftovers are the parts.
    for (auto& t : tiny)
      patches.push_back({t, t});
    tiny.clear();
  }
  // 5 % of the graph: on clean shapes leftovers are small details (a box's edges) that belong
  // whole to the part they touch, as in the reference; under noise a leftover can span several
  // parts and is split.
  splitLargeLeftovers(g, tiny, patches, std::max<std::size_t>(2, g.numNodes() / 20));
  absorbTinyPatches(g, tiny, binning, index, patches);
  // On a noisy surface each bump sends a spike into the shape: spheres of every radius up to
  // the part's, touching the bump's flanks only. They fill every part's histogram alike, and
  // parts of different thickness compare as alike (docs/noise.md, "Spikes in the merging").
  std::vector<char> in_histogram;
  if (touching_tolerance_ > 0.0)
    in_histogram = detail::spheresSpanningRightAngle(g.centers(), g.radii(), surface_samples_,
                                                     touching_tolerance_);
  mergePatches(g, binning, merge_rounds_, visibility_, seed_, in_histogram, patches);

  // Outputs, in patch order.
  node_labels_.assign(n, -1);
  parts.resize(patches.size());
  coarse_parts_.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    std::vector<int>& dense = patches[p].dense;
    std::sort(dense.begin(), dense.end());
    for (int i : dense)
      node_labels_[i] = static_cast<int>(p);
    parts[p].indices = dense;
    coarse_parts_[p] = std::move(patches[p].coarse);
    std::sort(coarse_parts_[p].begin(), coarse_parts_[p].end());
  }
  return true;
}

} // namespace segmat
