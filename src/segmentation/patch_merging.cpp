/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "patch_merging.h"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace segmat {
namespace {

/** Uniform double in [0, 1) from two raw 32-bit outputs (53 bits, library-independent). */
double
uniform01(std::mt19937& engine)
{
  const std::uint64_t hi = engine() >> 5, lo = engine() >> 6;
  return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
}

/** Every 3rd sphere (the reference's visibility subsampling), and every k-th when that leaves
 * more than kMaxVisibilityPoints: a patch of up to 768 spheres is tested as in SEG-MAT, and a
 * larger one estimates the visible fraction about as finely as that. Every 3rd sphere of two
 * large patches (the wall of a noisy cup: 421 × 598 points) would ask for a quarter of a million
 * segment tests. */
std::vector<int>
visibilitySpheres(const std::vector<int>& spheres)
{
  constexpr std::size_t kMaxVisibilityPoints = 256;
  const std::size_t stride =
      std::max<std::size_t>(3, (spheres.size() + kMaxVisibilityPoints - 1) / kMaxVisibilityPoints);
  std::vector<int> out;
  for (std::size_t i = 0; i < spheres.size(); i += stride)
    out.push_back(spheres[i]);
  return out;
}

} // namespace

RadiusBinning
makeRadiusBinning(const std::vector<double>& radii, int intervals)
{
  RadiusBinning binning;
  binning.intervals = std::max(1, intervals);
  if (radii.empty())
    return binning;
  const auto [lo, hi] = std::minmax_element(radii.begin(), radii.end());
  binning.r_min = *lo;
  binning.spacing = (*hi - *lo) / binning.intervals;
  return binning;
}

std::vector<double>
radiusHistogram(const std::vector<int>& spheres, const std::vector<double>& radii,
                const RadiusBinning& binning)
{
  std::vector<double> h(binning.intervals + 1, 0.0);
  if (spheres.empty())
    return h;
  const double w = 1.0 / static_cast<double>(spheres.size());
  for (int s : spheres) {
    int k = 0;
    if (binning.spacing > 0.0) {
      const double x = (radii[s] - binning.r_min) / binning.spacing;
      if (x >= 0.0) { // also false for NaN
        const double base = std::floor(x);
        k = static_cast<int>(std::min<double>(base, binning.intervals));
        if (x - base > 0.5 && k < binning.intervals)
          ++k; // nearest mark, a tie goes to the lower one
      }
    }
    h[k] += w;
  }
  return h;
}

double
histogramEmd(const std::vector<double>& a, const std::vector<double>& b, double spacing)
{
  const std::size_t n = std::min(a.size(), b.size());
  double cdf_a = 0.0, cdf_b = 0.0, emd = 0.0;
  // The last mark adds nothing: both CDFs are 1 there.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    cdf_a += a[k];
    cdf_b += b[k];
    emd += std::abs(cdf_a - cdf_b);
  }
  return emd * spacing;
}

double
maxPairwiseEmd(const std::vector<std::vector<double>>& histograms, double spacing)
{
  double best = 0.0;
  for (std::size_t i = 0; i < histograms.size(); ++i)
    for (std::size_t j = i + 1; j < histograms.size(); ++j)
      best = std::max(best, histogramEmd(histograms[i], histograms[j], spacing));
  return best;
}

std::vector<std::pair<int, int>>
sphereSharingPairs(const std::vector<std::vector<int>>& patch_spheres, std::size_t num_spheres,
                   std::vector<int>* shared)
{
  std::vector<std::vector<int>> sphere_patches(num_spheres);
  for (std::size_t p = 0; p < patch_spheres.size(); ++p)
    for (int s : patch_spheres[p])
      if (sphere_patches[s].empty() || sphere_patches[s].back() != static_cast<int>(p))
        sphere_patches[s].push_back(static_cast<int>(p));
  std::vector<std::pair<int, int>> pairs;
  for (const auto& owners : sphere_patches)
    for (std::size_t i = 0; i < owners.size(); ++i)
      for (std::size_t j = i + 1; j < owners.size(); ++j)
        pairs.emplace_back(owners[i], owners[j]); // owners ascend: first < second
  std::sort(pairs.begin(), pairs.end());
  // One entry per shared sphere: the run length of a pair is its number of shared spheres.
  std::vector<std::pair<int, int>> unique_pairs;
  if (shared)
    shared->clear();
  for (std::size_t i = 0; i < pairs.size();) {
    std::size_t j = i + 1;
    while (j < pairs.size() && pairs[j] == pairs[i])
      ++j;
    unique_pairs.push_back(pairs[i]);
    if (shared)
      shared->push_back(static_cast<int>(j - i));
    i = j;
  }
  return unique_pairs;
}

Eigen::Vector3d
randomPointInBall(std::mt19937& engine, const Eigen::Vector3d& center, double radius)
{
  Eigen::Vector3d u;
  do {
    u = Eigen::Vector3d(2.0 * uniform01(engine) - 1.0, 2.0 * uniform01(engine) - 1.0,
                        2.0 * uniform01(engine) - 1.0);
  } while (u.squaredNorm() > 1.0);
  return center + radius * u;
}

bool
patchesSeeEachOther(const std::vector<int>& spheres_a, const std::vector<int>& spheres_b,
                    const std::vector<Eigen::Vector3d>& centers,
                    const std::vector<double>& radii, const SegmentVisibility& visible,
                    double ratio, std::uint32_t seed)
{
  if (!visible)
    return true;
  std::mt19937 engine(seed);
  std::vector<Eigen::Vector3d> pa, pb;
  for (int s : visibilitySpheres(spheres_a))
    pa.push_back(randomPointInBall(engine, centers[s], radii[s]));
  for (int s : visibilitySpheres(spheres_b))
    pb.push_back(randomPointInBall(engine, centers[s], radii[s]));
  const double total = static_cast<double>(pa.size()) * static_cast<double>(pb.size());
  if (total == 0.0)
    return false;
  const double needed = ratio * total;
  double count = 0.0, remaining = total;
  for (const Eigen::Vector3d& a : pa)
    for (const Eigen::Vector3d& b : pb) {
      if (a == b || visible(a, b))
        count += 1.0;
      remaining -= 1.0;
      if (count >= needed)
        return true;
      if (count + remaining < needed)
        return false; // even all remaining pairs visible would not reach the ratio
    }
  return count >= needed;
}

const std::vector<MergeRound>&
defaultMergeRounds()
{
  // The last round asks for 99 % rather than all of the segments: "all of N random segments"
  // fails more often the more segments two large patches sample, so a shallow dent of a
  // nearly convex part (a fish's body) split it in some jitter draws and not in others.
  static const std::vector<MergeRound> rounds{{0.8, 0.1}, {0.9, 0.2}, {0.99, 0.3}};
  return rounds;
}

std::vector<int>
mergeRoundGroups(const std::vector<std::vector<int>>& patch_spheres,
                 const std::vector<std::vector<double>>& histograms, double spacing,
                 const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii,
                 double emd_limit, double visibility_ratio, const SegmentVisibility& visible,
                 std::uint32_t seed, int round,
                 const std::vector<std::pair<int, int>>& extra_pairs)
{
  const int n = static_cast<int>(patch_spheres.size());
  std::vector<int> rank(n, 0), parent(n);
  for (int i = 0; i < n; ++i)
    parent[i] = i;
  boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
  std::vector<std::pair<int, int>> pairs = sphereSharingPairs(patch_spheres, centers.size());
  if (!extra_pairs.empty()) {
    pairs.insert(pairs.end(), extra_pairs.begin(), extra_pairs.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  }
  for (const auto& [a, b] : pairs) {
    // Cheap test first: the visibility test costs up to (|a|/3)·(|b|/3) segment queries.
    if (!(histogramEmd(histograms[a], histograms[b], spacing) < emd_limit))
      continue;
    if (sets.find_set(a) == sets.find_set(b))
      continue; // already joined: the visibility of this pair cannot change the groups
    std::seed_seq mix{seed, static_cast<std::uint32_t>(round), static_cast<std::uint32_t>(a),
                      static_cast<std::uint32_t>(b)};
    std::uint32_t pair_seed;
    mix.generate(&pair_seed, &pair_seed + 1);
    if (patchesSeeEachOther(patch_spheres[a], patch_spheres[b], centers, radii, visible,
                            visibility_ratio, pair_seed))
      sets.union_set(a, b);
  }
  std::vector<int> group(n, -1), root_group(n, -1);
  int groups = 0;
  for (int i = 0; i < n; ++i) {
    const int root = sets.find_set(i);
    if (root_group[root] < 0)
      root_group[root] = groups++;
    group[i] = root_group[root];
  }
  return group;
}

} // namespace segmat
