/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/structure_tags.h>

#include <Eigen/Core>
#include <pcl/PointIndices.h>

#include <functional>
#include <memory>
#include <vector>

namespace segmat {

/** \brief Returns true when the straight segment between two points does not cross the shape's
 * surface (the points "see" each other): the visibility test of the merging.
 */
using SegmentVisibility = std::function<bool(const Eigen::Vector3d&, const Eigen::Vector3d&)>;

/** \brief Region growing on a MAT graph: the part-finding core of SEG-MAT (Lin et al. 2022, §4–5).
 *
 * Steps (SEG-MAT §4.3–4.4 and the authors' `RegionGrowing`, `MergeTinyPatches`,
 * `MergeIterations`), on a MatGraph built from a medial mesh (slabs and cones)
 * or from a cloud's meso-skeleton (points with normals):
 *  1. seeds in order of decreasing mean radius (ties: smaller node index first);
 *  2. breadth-first growth: a neighbour j of the current node i joins when
 *     cost(i, j) = min(C_r + α·C_θ, λ·C_mp) <= t, with t = δ0 (both tags 0),
 *     δ0·tag_ratio (same thin part) or 0 (different tags), see docs/method.md; and (not in
 *     the reference) when j is at most setMaxSeedRadiusRatio() times thinner than the seed;
 *  3. regions with fewer than N_min = max(1, int(η · number of spheres)) nodes are released;
 *     an accepted region swallows every free node that has a sphere centre strictly inside one
 *     of the region's spheres;
 *  4. leftover nodes form tiny patches (connected components), each absorbed by the best
 *     sphere-overlapping part (radius-histogram EMD and distance);
 *  5. three merging rounds join adjacent parts with similar radius histograms that see each
 *     other (visibility 0.8/0.9/1.0, EMD below 0.1/0.2/0.3 of the largest EMD of round 1).
 *
 * Part order: parts are numbered in growing order; after merging a part takes the place of its
 * lowest-numbered member. So part 0 always holds the first grown region, the one seeded at the
 * node with the largest mean radius.
 *
 * \code
 * auto graph = std::make_shared<segmat::MatGraph>(segmat::MatGraph::fromMedialMesh(base_mat));
 * segmat::MatRegionGrowing grower;
 * grower.setInputGraph(graph);
 * grower.setStructureTags(segmat::computeStructureTags(structured_mat, *graph));
 * grower.setSegmentVisibility([&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
 *   return !surface_tree.segmentIntersects(a, b);
 * });
 * std::vector<pcl::PointIndices> parts;
 * grower.extract(parts); // parts[k].indices: node indices of part k
 * \endcode
 */
class MatRegionGrowing
{
public:
  using Ptr = std::shared_ptr<MatRegionGrowing>;
  using ConstPtr = std::shared_ptr<const MatRegionGrowing>;
  /** \brief The visibility test of the merging (segmat::SegmentVisibility). */
  using SegmentVisibility = segmat::SegmentVisibility;

  /** \brief Defaults of the paper: δ0 = 0.015, η = 0.002, α = 0.05, λ = 1.5, 3 merge rounds. */
  MatRegionGrowing();

  /** \brief Set the MAT graph to segment. */
  void
  setInputGraph(const MatGraph::ConstPtr& graph);
  /** \brief The MAT graph to segment. */
  MatGraph::ConstPtr
  getInputGraph() const
  {
    return graph_;
  }

  /** \brief Set the structural tags (computeStructureTags). Optional: by default all nodes carry
   * tag 0. Tags of the wrong size are ignored with a warning at extract().
   */
  void
  setStructureTags(const StructureTags& tags);
  /** \brief The structural tags in use (empty node_tag: all 0). */
  const StructureTags&
  getStructureTags() const
  {
    return tags_;
  }

  /** \brief Set δ0, the growing threshold on the edge cost (> 0 and finite; default 0.015). */
  void
  setGrowingThreshold(double delta0);
  /** \brief δ0, the growing threshold. */
  double
  getGrowingThreshold() const
  {
    return delta0_;
  }

  /** \brief Set η: a region needs at least int(η · number of spheres) nodes (in [0, 1];
   * default 0.002; at least one node is always required).
   */
  void
  setMinRegionFraction(double eta);
  /** \brief η, the minimal region fraction. */
  double
  getMinRegionFraction() const
  {
    return eta_;
  }

  /** \brief Set α, the weight of the angle term C_θ (>= 0; default 0.05). */
  void
  setAngleWeight(double alpha);
  /** \brief α, the weight of the angle term. */
  double
  getAngleWeight() const
  {
    return alpha_;
  }

  /** \brief Set λ, the weight of the medial-primitive term C_mp (>= 0; default 1.5). */
  void
  setPrimitiveWeight(double lambda);
  /** \brief λ, the weight of the medial-primitive term. */
  double
  getPrimitiveWeight() const
  {
    return lambda_;
  }

  /** \brief Use the medial-primitive term C_mp (default true). It is off anyway when the graph
   * has no slabs or cones (a cloud's meso-skeleton): the cost is then C_r + α·C_θ.
   */
  void
  usePrimitiveTerm(bool use)
  {
    use_primitive_term_ = use;
  }
  /** \brief Whether the medial-primitive term is requested. */
  bool
  getUsePrimitiveTerm() const
  {
    return use_primitive_term_;
  }

  /** \brief Set the number of merging rounds, 0 to 3 (default 3; 0 keeps the grown regions). */
  void
  setMergeRounds(int rounds);
  /** \brief Number of merging rounds. */
  int
  getMergeRounds() const
  {
    return merge_rounds_;
  }

  /** \brief Set the largest ratio between a region's seed radius and the mean radius of a node
   * it may grow into (default 3; infinity disables the guard, as in the reference).
   *
   * The growing test compares neighbours only, so many small radius steps can carry one region
   * from the body far down a tapering limb. With this guard a node thinner than the seed by
   * more than this factor is left for a later seed. Not in SEG-MAT; it splits
   * tapering parts (a vase's neck, a human's limb) where the humans do.
   * \param[in] ratio a value >= 1; other values are rejected with a warning
   */
  void
  setMaxSeedRadiusRatio(double ratio);
  /** \brief Largest seed-to-node radius ratio inside one grown region. */
  double
  getMaxSeedRadiusRatio() const
  {
    return max_seed_radius_ratio_;
  }

  /** \brief Set the largest turn, in degrees, of a tube inside one grown region (default 60;
   * 90 disables the guard, as in the reference).
   *
   * SEG-MAT's cost compares neighbouring nodes only, so a tube that bends by 90° over many
   * medial triangles (an L-shaped pipe, an elbow) costs little at every step and stays one part.
   * The structured MAT sees the bend at once: its lines are a few long segments. Each region
   * keeps the direction of the first structured line it reaches (StructureTags::node_axis);
   * a node mapped to a line turned by more than this angle from it is left for a later seed.
   * Not in SEG-MAT.
   * \param[in] degrees a value in (0, 90]; other values are rejected with a warning
   */
  void
  setMaxBendAngle(double degrees);
  /** \brief Largest turn of a tube inside one grown region, in degrees. */
  double
  getMaxBendAngle() const
  {
    return max_bend_angle_;
  }

  /** \brief Set the radius tolerance: differences of two nodes' mean radii up to this length
   * do not count in the radius term C_r (SEG-MAT §4.3), which becomes
   * max(0, max − min − tolerance) / min. MeshSegmentation and CloudSegmentation set it to the
   * noise that remains on a denoised surface, where a radius difference of that size tells
   * nothing; 0 (the default) is the paper's term.
   * \param[in] length a finite length >= 0, in the graph's units; other values are rejected
   * with a warning
   */
  void
  setRadiusTolerance(double length);
  /** \brief Radius differences up to this length cost nothing in C_r. */
  double
  getRadiusTolerance() const
  {
    return radius_tolerance_;
  }

  /** \brief Set the surface samples that the medial spheres touch, and how far outside a
   * sphere a sample still touches it. With a tolerance > 0, merging compares parts by the radii
   * of their spheres whose touching samples span at least a right angle as seen from the
   * centre (the separation angle of the θ-simplified medial axis, Foskey et al. 2003): a
   * tube's axis spheres touch a ring, a box edge's sheet spheres two faces at 90°. A bump of
   * a noisy surface sends a spike into the shape, spheres of every radius up to the part's
   * that touch the bump's two flanks a small angle apart; counted in SEG-MAT's radius
   * histograms (§4.4) they make every part's histogram alike, and two parts of different
   * thickness pass the EMD test. A part with no spanning sphere is compared by all of its
   * spheres. CloudSegmentation sets the smoothed points of a noisy cloud with the input's
   * noise σ̂ as the tolerance (medial mesh only); 0 (the default) is the paper's histogram of
   * all spheres.
   * \param[in] samples surface points, in the graph's frame
   * \param[in] tolerance a finite length >= 0, in the graph's units; other values are rejected
   * with a warning
   */
  void
  setSurfaceSamples(std::vector<Eigen::Vector3d> samples, double tolerance);
  /** \brief How far outside a sphere a surface sample still touches it (0: merging counts all
   * spheres). */
  double
  getTouchingTolerance() const
  {
    return touching_tolerance_;
  }

  /** \brief Set the visibility test used when merging. When unset (the default) the visibility
   * gate is skipped: parts merge on adjacency and histogram similarity alone.
   */
  void
  setSegmentVisibility(SegmentVisibility visibility)
  {
    visibility_ = std::move(visibility);
  }

  /** \brief Seed of the Monte-Carlo visibility sampling (default 0x5e6a7). */
  void
  setRandomSeed(unsigned seed)
  {
    seed_ = seed;
  }
  /** \brief Seed of the Monte-Carlo visibility sampling. */
  unsigned
  getRandomSeed() const
  {
    return seed_;
  }

  /** \brief Segment the graph.
   * \param[out] parts one entry per part: its node indices, ascending. Every node belongs to
   *             exactly one part (grown, swallowed or absorbed).
   * \return false (and empty output) when no graph is set or it is empty.
   */
  bool
  extract(std::vector<pcl::PointIndices>& parts);

  /** \brief Per final part, its grown ("coarse") nodes, ascending — the nodes the surface data
   * term may use (as the authors' `transfer_MAT_mesh`). Never empty for a part: when no region
   * reaches the
   * minimal size, the leftover components become the parts and all their nodes count as coarse.
   * Valid after extract().
   */
  const std::vector<std::vector<int>>&
  getCoarseParts() const
  {
    return coarse_parts_;
  }

  /** \brief Final part of each node. Valid after extract(). */
  const std::vector<int>&
  getNodeLabels() const
  {
    return node_labels_;
  }

  /** \brief Node counts of the grown regions in growing order, before swallowing and merging
   * (diagnostics; teddy with the authors' MATs: 12 regions). Valid after extract().
   */
  const std::vector<int>&
  getGrownRegionSizes() const
  {
    return grown_region_sizes_;
  }

  /** \brief Node counts of the tiny patches (leftovers) before absorption. Valid after extract().
   */
  const std::vector<int>&
  getTinyPatchSizes() const
  {
    return tiny_patch_sizes_;
  }

private:
  void
  clearOutput();

  MatGraph::ConstPtr graph_;
  StructureTags tags_;
  double delta0_;
  double eta_;
  double alpha_;
  double lambda_;
  bool use_primitive_term_;
  int merge_rounds_;
  double max_seed_radius_ratio_;
  double max_bend_angle_;
  double radius_tolerance_;
  double touching_tolerance_;
  std::vector<Eigen::Vector3d> surface_samples_;
  SegmentVisibility visibility_;
  unsigned seed_;

  std::vector<std::vector<int>> coarse_parts_;
  std::vector<int> node_labels_;
  std::vector<int> grown_region_sizes_;
  std::vector<int> tiny_patch_sizes_;
};

} // namespace segmat
