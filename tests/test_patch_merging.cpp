// Radius histograms, EMD, patch adjacency, Monte-Carlo visibility and merge rounds
// (SEG-MAT §4.4).
#include "../src/segmentation/patch_merging.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace segmat;

namespace {
std::vector<double>
spike(int mark, int marks = 21)
{
  std::vector<double> h(marks, 0.0);
  h[mark] = 1.0;
  return h;
}
} // namespace

TEST(PatchMerging, EmdOnHandMadeHistograms)
{
  // Range [0, 1], 20 intervals: spacing 0.05.
  // All mass at mark 0 vs mark 20: CDFs differ by 1 on marks 0..19 → 20 · 1 · 0.05 = 1.0.
  EXPECT_NEAR(histogramEmd(spike(0), spike(20), 0.05), 1.0, 1e-12);
  // One mark apart: differ by 1 on one mark → 0.05.
  EXPECT_NEAR(histogramEmd(spike(3), spike(4), 0.05), 0.05, 1e-15);
  EXPECT_EQ(histogramEmd(spike(7), spike(7), 0.05), 0.0);
  // Half at 0 and half at 20 vs all at 10: |0.5 − 0| on marks 0..9, |0.5 − 1| on 10..19 →
  // 20 · 0.5 · 0.05 = 0.5 (moving each half 10 marks · 0.05 = 0.5 · 0.5 · 2).
  std::vector<double> split(21, 0.0);
  split[0] = split[20] = 0.5;
  EXPECT_NEAR(histogramEmd(split, spike(10), 0.05), 0.5, 1e-12);
  EXPECT_NEAR(maxPairwiseEmd({spike(0), spike(4), spike(10)}, 0.05), 0.5, 1e-12);
  EXPECT_EQ(maxPairwiseEmd({spike(4)}, 0.05), 0.0);
}

TEST(PatchMerging, RadiusHistogramNearestMark)
{
  // Radii over [0, 1]: marks every 0.05. 0.025 is a tie between marks 0 and 1 → mark 0;
  // 0.026 → mark 1; 0.974 → mark 19 (0.974/0.05 = 19.48); 1.0 → mark 20.
  const std::vector<double> radii{0.0, 0.025, 0.026, 0.974, 1.0};
  const RadiusBinning b = makeRadiusBinning(radii);
  EXPECT_EQ(b.intervals, 20);
  EXPECT_DOUBLE_EQ(b.spacing, 0.05);
  const std::vector<double> h = radiusHistogram({0, 1, 2, 3, 4}, radii, b);
  ASSERT_EQ(h.size(), 21u);
  EXPECT_DOUBLE_EQ(h[0], 0.4);
  EXPECT_DOUBLE_EQ(h[1], 0.2);
  EXPECT_DOUBLE_EQ(h[19], 0.2);
  EXPECT_DOUBLE_EQ(h[20], 0.2);
  double sum = 0.0;
  for (double w : h)
    sum += w;
  EXPECT_NEAR(sum, 1.0, 1e-15);
  // All radii equal: everything on mark 0, every EMD 0.
  const RadiusBinning flat = makeRadiusBinning({0.3, 0.3});
  EXPECT_EQ(flat.spacing, 0.0);
  EXPECT_EQ(radiusHistogram({0, 1}, {0.3, 0.3}, flat)[0], 1.0);
  EXPECT_EQ(radiusHistogram({}, radii, b), std::vector<double>(21, 0.0));
}

TEST(PatchMerging, SphereSharingPairs)
{
  const auto pairs = sphereSharingPairs({{0, 1}, {1, 2}, {3}, {2, 3}, {1, 3}}, 4);
  const std::vector<std::pair<int, int>> expected{{0, 1}, {0, 4}, {1, 3}, {1, 4}, {2, 3}, {2, 4},
                                                  {3, 4}};
  EXPECT_EQ(pairs, expected);
  // Shared spheres per pair: P0 = {0,1,2} and P1 = {1,2,3} share 1 and 2; P1 and P2 share 3.
  std::vector<int> shared;
  EXPECT_EQ(sphereSharingPairs({{0, 1, 2}, {1, 2, 3}, {3, 4}, {5}}, 6, &shared),
            (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
  EXPECT_EQ(shared, (std::vector<int>{2, 1}));
}

TEST(PatchMerging, RandomPointsFillTheBallUniformly)
{
  std::mt19937 engine(7);
  const Eigen::Vector3d c(1, 2, 3);
  int octant[8] = {0}, inner = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = randomPointInBall(engine, c, 2.0);
    const Eigen::Vector3d d = p - c;
    ASSERT_LE(d.norm(), 2.0);
    octant[(d.x() > 0) + 2 * (d.y() > 0) + 4 * (d.z() > 0)]++;
    inner += d.norm() < 1.0;
  }
  // Volume-uniform: P(|d| < r/2) = 1/8; every octant 1/8 (the reference drew one octant only).
  EXPECT_NEAR(inner / double(n), 0.125, 0.01);
  for (int o = 0; o < 8; ++o)
    EXPECT_NEAR(octant[o] / double(n), 0.125, 0.01);
  // Same seed, same points.
  std::mt19937 e1(11), e2(11);
  EXPECT_EQ(randomPointInBall(e1, c, 1.0), randomPointInBall(e2, c, 1.0));
}

TEST(PatchMerging, VisibilityRatioCountsEveryThirdSphere)
{
  // Zero radii make the samples the centres. A = spheres 0..8, of which every 3rd (0, 3, 6) sits at
  // y = 0, 1, 2 (x = −1); B = spheres 9..17, every 3rd (9, 12, 15) at y = 0, 1, 2 (x = +1); the
  // others are far away and must not be sampled. A "wall" hides segments whose midpoint has
  // y > 1.2: the pairs (yA, yB) = (1,2), (2,1), (2,2) → 6 of 9 visible = 0.667.
  std::vector<Eigen::Vector3d> c(18, Eigen::Vector3d(0, 50, 0)); // unused spheres: far away
  for (int k = 0; k < 3; ++k) {
    c[3 * k] = Eigen::Vector3d(-1, k, 0);
    c[9 + 3 * k] = Eigen::Vector3d(1, k, 0);
  }
  const std::vector<double> r(18, 0.0);
  std::vector<int> a, b;
  for (int s = 0; s < 9; ++s) {
    a.push_back(s);
    b.push_back(9 + s);
  }
  int calls = 0;
  const SegmentVisibility wall = [&calls](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    ++calls;
    return 0.5 * (p.y() + q.y()) <= 1.2;
  };
  EXPECT_TRUE(patchesSeeEachOther(a, b, c, r, wall, 0.6, 1));
  EXPECT_FALSE(patchesSeeEachOther(a, b, c, r, wall, 0.7, 1));
  calls = 0;
  EXPECT_FALSE(patchesSeeEachOther(a, b, c, r, wall, 1.0, 1));
  EXPECT_LT(calls, 9); // gives up at the first hidden pair
  // No callback: the gate is open. Empty patch: nothing to see.
  EXPECT_TRUE(patchesSeeEachOther(a, b, c, r, SegmentVisibility(), 1.0, 1));
  EXPECT_FALSE(patchesSeeEachOther({}, b, c, r, wall, 0.5, 1));
}

TEST(PatchMerging, LargePatchesSendAtMost256Points)
{
  // Every segment is visible and the ratio is 1, so every pair of points is tested once: the
  // calls count the points. 300 spheres: every 3rd, 100 points; 768: 256; 769: every 4th, 193;
  // 2000: every 8th, 250.
  for (const auto& [spheres, points] : {std::pair<int, int>{300, 100}, {768, 256}, {769, 193},
                                        {2000, 250}}) {
    std::vector<Eigen::Vector3d> c;
    std::vector<int> a, b;
    for (int i = 0; i < spheres; ++i) {
      a.push_back(int(c.size()));
      c.emplace_back(i, 0.0, 0.0);
      b.push_back(int(c.size()));
      c.emplace_back(i, 1.0, 0.0);
    }
    const std::vector<double> r(c.size(), 0.0);
    long calls = 0;
    const SegmentVisibility open = [&calls](const Eigen::Vector3d&, const Eigen::Vector3d&) {
      ++calls;
      return true;
    };
    EXPECT_TRUE(patchesSeeEachOther(a, b, c, r, open, 1.0, 5));
    EXPECT_EQ(calls, long(points) * points) << spheres << " spheres a patch";
  }
}

TEST(PatchMerging, MergeRoundJoinsSimilarAdjacentVisiblePatches)
{
  // P0 and P1 share sphere 2 and have the same radii; P2 shares sphere 4 with P1 but is fat;
  // P3 looks like P0 but touches nobody. Radii 0.1 (thin) and 1.0 (fat), 20 intervals.
  const std::vector<Eigen::Vector3d> c{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0},
                                       {5, 0, 0}, {6, 0, 0}, {20, 0, 0}, {21, 0, 0}};
  const std::vector<double> r{0.1, 0.1, 0.1, 0.1, 0.1, 1.0, 1.0, 0.1, 0.1};
  const std::vector<std::vector<int>> patches{{0, 1, 2}, {2, 3, 4}, {4, 5, 6}, {7, 8}};
  const RadiusBinning bin = makeRadiusBinning(r);
  std::vector<std::vector<double>> h;
  for (const auto& p : patches)
    h.push_back(radiusHistogram(p, r, bin));
  // EMD(P1, P2) = 2/3 of the mass moved 0.9 = 0.6 = EMD_max; limit 0.1 · 0.6.
  const double emd_max = maxPairwiseEmd(h, bin.spacing);
  EXPECT_NEAR(emd_max, 0.6, 1e-12);
  const auto open = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return true; };
  const auto closed = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return false; };
  EXPECT_EQ(mergeRoundGroups(patches, h, bin.spacing, c, r, 0.1 * emd_max, 0.8, open, 5, 0),
            (std::vector<int>{0, 0, 1, 2}));
  EXPECT_EQ(mergeRoundGroups(patches, h, bin.spacing, c, r, 0.1 * emd_max, 0.8, closed, 5, 0),
            (std::vector<int>{0, 1, 2, 3}));
  // Without a visibility test (no surface), adjacency and EMD decide.
  EXPECT_EQ(mergeRoundGroups(patches, h, bin.spacing, c, r, 0.1 * emd_max, 0.8,
                             SegmentVisibility(), 5, 0),
            (std::vector<int>{0, 0, 1, 2}));
  // A limit above every EMD joins everything adjacent; P3 stays alone.
  EXPECT_EQ(mergeRoundGroups(patches, h, bin.spacing, c, r, 1.0, 0.8, open, 5, 0),
            (std::vector<int>{0, 0, 0, 1}));
}

TEST(PatchMerging, DefaultRounds)
{
  ASSERT_EQ(defaultMergeRounds().size(), 3u);
  EXPECT_EQ(defaultMergeRounds()[2].visibility_ratio, 0.99);
  EXPECT_EQ(defaultMergeRounds()[2].emd_factor, 0.3);
}

// The last round's ratio is a fraction, not "every segment": of two patches of 30 spheres each
// (every third sampled: 10 × 10 = 100 segments), one blocked segment still lets them join there,
// two do not.
TEST(PatchMerging, LastRoundToleratesOneSegmentInAHundred)
{
  std::vector<Eigen::Vector3d> c;
  std::vector<double> r;
  std::vector<int> a, b;
  for (int i = 0; i < 30; ++i) {
    a.push_back(int(c.size()));
    c.emplace_back(0.1 * i, 0.0, 0.0);
    r.push_back(0.05);
    b.push_back(int(c.size()));
    c.emplace_back(0.1 * i, 1.0, 0.0);
    r.push_back(0.05);
  }
  const double ratio = defaultMergeRounds()[2].visibility_ratio;
  for (const int blocked : {1, 2}) {
    auto calls = std::make_shared<int>(0);
    const SegmentVisibility few_blocked = [calls, blocked](const Eigen::Vector3d&,
                                                           const Eigen::Vector3d&) {
      return ++*calls > blocked; // the first `blocked` segments are blocked
    };
    EXPECT_EQ(patchesSeeEachOther(a, b, c, r, few_blocked, ratio, 3), blocked == 1)
        << blocked << " blocked segments";
  }
}
