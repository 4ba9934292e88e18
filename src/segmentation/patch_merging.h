/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/segmentation/mat_region_growing.h> // SegmentVisibility

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <random>
#include <utility>
#include <vector>

namespace segmat {

/** \brief The radius marks of SEG-MAT's patch signatures (the authors' `getPatchSignature`):
 * intervals + 1 marks r_min + k·spacing over the radius range of the whole base MAT.
 */
struct RadiusBinning
{
  double r_min = 0.0;   ///< first mark
  double spacing = 0.0; ///< distance between marks (0 when all radii are equal)
  int intervals = 20;   ///< number of intervals; there are intervals + 1 marks
};

/** \brief Marks spanning [min radius, max radius] with \a intervals intervals (default 20). */
RadiusBinning
makeRadiusBinning(const std::vector<double>& radii, int intervals = 20);

/** \brief Normalised radius histogram of a set of spheres: each sphere counts 1/|spheres| at its
 * nearest mark (ties go to the lower mark).
 *
 * Deliberate difference: the authors' code kept adding to a patch's histogram across steps
 * (round-1 weights summed to more than 1); this histogram is always built fresh.
 * \param[in] spheres sphere indices (each counted once per occurrence; pass a unique set)
 * \return intervals + 1 weights summing to 1 (all 0 for an empty set)
 */
std::vector<double>
radiusHistogram(const std::vector<int>& spheres, const std::vector<double>& radii,
                const RadiusBinning& binning);

/** \brief Earth mover's distance between two histograms on the same equally spaced marks, in
 * radius units: Σ_k |CDF_a(k) − CDF_b(k)| · spacing (the closed form of the 1-D EMD with
 * ground distance |mark_i − mark_j| that the reference computed with Rubner's solver).
 */
double
histogramEmd(const std::vector<double>& a, const std::vector<double>& b, double spacing);

/** \brief Largest EMD over all pairs (0 with fewer than two histograms). */
double
maxPairwiseEmd(const std::vector<std::vector<double>>& histograms, double spacing);

/** \brief Pairs (a < b) of patches that share at least one sphere, sorted.
 * \param[in] patch_spheres sorted unique sphere indices of each patch
 * \param[in] num_spheres number of spheres (indices are below it)
 * \param[out] shared if set, the number of spheres each returned pair shares
 */
std::vector<std::pair<int, int>>
sphereSharingPairs(const std::vector<std::vector<int>>& patch_spheres, std::size_t num_spheres,
                   std::vector<int>* shared = nullptr);

/** \brief A point uniformly distributed in a ball, from the raw engine output (the same numbers on
 * every standard library): rejection sampling in the bounding cube.
 */
Eigen::Vector3d
randomPointInBall(std::mt19937& engine, const Eigen::Vector3d& center, double radius);

/** \brief Monte-Carlo visibility of two patches (the authors' `checkPatchVisibility`).
 *
 * Every 3rd sphere of each patch contributes one random point inside it, or every k-th, with
 * the smallest k that leaves at most 256 points: a patch of more than 768 spheres then estimates
 * the visible fraction about as finely as one of 768, and two large patches do not cost a
 * quarter of a million segment tests. The patches see each other when at least
 * ratio · (all point pairs) segments are visible (a degenerate segment is visible). Fix of the
 * reference: points are uniform in the ball (it sampled one octant of directions with a
 * non-uniform radius) and the engine is seeded (it used unseeded rand()).
 * \param[in] seed seeds the sampling; the result is a function of all arguments
 */
bool
patchesSeeEachOther(const std::vector<int>& spheres_a, const std::vector<int>& spheres_b,
                    const std::vector<Eigen::Vector3d>& centers,
                    const std::vector<double>& radii, const SegmentVisibility& visible,
                    double ratio, std::uint32_t seed);

/** \brief Settings of one merging round (MergeIterations). */
struct MergeRound
{
  double visibility_ratio; ///< fraction of visible segments needed
  double emd_factor;       ///< merge when EMD < emd_factor · EMD_max
};

/** \brief The three rounds: (0.8, 0.1), (0.9, 0.2), (0.99, 0.3). The reference's last round
 * needs every sampled segment (1.0); a fixed fraction makes the test independent of how many
 * segments two patches sample. */
const std::vector<MergeRound>&
defaultMergeRounds();

/** \brief One merging round: which patches join.
 *
 * Two patches join when they are adjacent (share a sphere, or appear in \a extra_pairs), EMD < emd_limit and (when \a visible is set) they
 * see each other with the round's ratio. The visibility test is evaluated once per unordered
 * pair, so the relation is symmetric (the reference tested both directions with fresh random
 * samples and could keep only one). Groups are the connected components.
 * \param[in] patch_spheres sorted unique sphere indices of each patch
 * \param[in] histograms radiusHistogram of each patch
 * \param[in] spacing mark spacing of the histograms
 * \param[in] emd_limit emd_factor · EMD_max of the round
 * \param[in] seed seeds the visibility sampling (mixed with the round and the patch pair)
 * \param[in] round round number, only mixed into the seed
 * \param[in] extra_pairs further adjacent patch pairs (first < second), e.g. patches joined by a
 *            MAT-graph edge: medial points of a cloud have one sphere each and never share one
 * \return the group of each patch; groups are numbered in order of their lowest patch, so group
 *         k's lowest patch comes before group k+1's
 */
std::vector<int>
mergeRoundGroups(const std::vector<std::vector<int>>& patch_spheres,
                 const std::vector<std::vector<double>>& histograms, double spacing,
                 const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii,
                 double emd_limit, double visibility_ratio, const SegmentVisibility& visible,
                 std::uint32_t seed, int round,
                 const std::vector<std::pair<int, int>>& extra_pairs = {});

} // namespace segmat
