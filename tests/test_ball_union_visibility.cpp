/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * BallUnionVisibility: a segment sees through when it stays inside the union of the balls.
 * Worked cases on two balls and a tube of balls, and random segments among random balls
 * checked against dense sampling of the segment.
 */
#include <segmat/medial/ball_union_visibility.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

using segmat::BallUnionVisibility;
using V = Eigen::Vector3d;

// Unit balls at x = 0 and x = 1.5 (not inflated). At height y = 0.9 their union spans
// x <= sqrt(1 - 0.81) = 0.436 and x >= 1.064, so a segment there leaves it; inflated by 1.2 the
// balls reach x <= 0.794 and x >= 0.706 at that height and the same segment stays inside.
TEST(BallUnionVisibility, TwoBalls)
{
  const std::vector<V> centers{V(0, 0, 0), V(1.5, 0, 0)};
  const std::vector<double> radii{1.0, 1.0};
  const BallUnionVisibility plain(centers, radii, 1.0), inflated(centers, radii, 1.2);
  EXPECT_TRUE(plain(V(-0.5, 0, 0), V(2, 0, 0)));
  EXPECT_TRUE(plain(V(2, 0, 0), V(-0.5, 0, 0)));
  EXPECT_FALSE(plain(V(0, 0.9, 0), V(1.5, 0.9, 0)));
  EXPECT_TRUE(inflated(V(0, 0.9, 0), V(1.5, 0.9, 0)));
  EXPECT_FALSE(plain(V(0, 0, 0), V(0, 2, 0))); // the end point lies outside
  EXPECT_TRUE(plain(V(0.2, 0.1, 0), V(0.2, 0.1, 0))); // a point inside
  EXPECT_FALSE(BallUnionVisibility({}, {})(V(0, 0, 0), V(1, 0, 0)));
}

// The same balls widened by a margin m (radius 1 + m): at y = 0.9 they reach
// x <= sqrt((1 + m)² − 0.81), past the midpoint 0.75 once (1 + m)² > 1.3725, i.e. m > 0.1715.
// A point at height 1.15 above a centre lies inside with a margin of 0.2, outside with 0.1.
TEST(BallUnionVisibility, MarginWidensEveryBall)
{
  const std::vector<V> centers{V(0, 0, 0), V(1.5, 0, 0)};
  const std::vector<double> radii{1.0, 1.0};
  EXPECT_FALSE(BallUnionVisibility(centers, radii, 1.0, 0.16)(V(0, 0.9, 0), V(1.5, 0.9, 0)));
  EXPECT_TRUE(BallUnionVisibility(centers, radii, 1.0, 0.18)(V(0, 0.9, 0), V(1.5, 0.9, 0)));
  EXPECT_TRUE(BallUnionVisibility(centers, radii, 1.0, 0.2)(V(0, 1.15, 0), V(0, 1.15, 0)));
  EXPECT_FALSE(BallUnionVisibility(centers, radii, 1.0, 0.1)(V(0, 1.15, 0), V(0, 1.15, 0)));
}

// 200 balls of radius 0.1 every 0.05 along x (a tube 10 long). At height y the balls' chords
// are 2·sqrt(0.01 − y²) long: 0.087 at y = 0.09, which covers the 0.05 spacing; 0.028 at
// y = 0.099, which leaves gaps of 0.022 — twice the minimal step of the walk (1e-3 of the
// balls' extent, 0.0101).
TEST(BallUnionVisibility, TubeOfBalls)
{
  std::vector<V> centers;
  std::vector<double> radii;
  for (int i = 0; i < 200; ++i) {
    centers.emplace_back(0.05 * i, 0, 0);
    radii.push_back(0.1);
  }
  const BallUnionVisibility see(centers, radii, 1.0);
  EXPECT_TRUE(see(V(0, 0, 0), V(9.95, 0, 0)));
  EXPECT_TRUE(see(V(0, 0.09, 0), V(9.95, 0.09, 0)));
  EXPECT_TRUE(see(V(0, 0, 0.09), V(9.95, 0.0, -0.09)));
  EXPECT_FALSE(see(V(0.025, 0.099, 0), V(9.925, 0.099, 0)));
  EXPECT_FALSE(see(V(0, 0, 0), V(10.2, 0, 0))); // beyond the last ball
}

// Random balls and segments (fixed seed), against 20 001 samples along each segment. Where the
// samples leave the union for longer than twice the walk's minimal step the walk must say
// "not visible"; where they never leave it, "visible". Runs shorter than that are the gaps the
// minimal step may bridge, and are not judged.
TEST(BallUnionVisibility, AgreesWithDenseSampling)
{
  std::mt19937 engine(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<V> centers;
  std::vector<double> radii;
  for (int i = 0; i < 60; ++i) {
    centers.emplace_back(unit(engine), unit(engine), unit(engine));
    radii.push_back(0.08 + 0.12 * unit(engine));
  }
  const BallUnionVisibility see(centers, radii, 1.0);
  V lo = centers[0], hi = centers[0];
  for (std::size_t i = 0; i < centers.size(); ++i) {
    lo = lo.cwiseMin(centers[i] - V::Constant(radii[i]));
    hi = hi.cwiseMax(centers[i] + V::Constant(radii[i]));
  }
  const double min_step = 1e-3 * (hi - lo).norm();
  const auto inside = [&](const V& p) {
    for (std::size_t i = 0; i < centers.size(); ++i)
      if ((p - centers[i]).norm() <= radii[i])
        return true;
    return false;
  };
  int judged_visible = 0, judged_hidden = 0;
  for (int s = 0; s < 400; ++s) {
    // End points at ball centres, as the merging draws them (inside the union).
    const V a = centers[engine() % centers.size()], b = centers[engine() % centers.size()];
    const int samples = 20000;
    double longest_outside = 0.0, run = 0.0;
    const double step = (b - a).norm() / samples;
    for (int k = 0; k <= samples; ++k) {
      run = inside(a + (b - a) * (double(k) / samples)) ? 0.0 : run + step;
      longest_outside = std::max(longest_outside, run);
    }
    if (longest_outside == 0.0) {
      EXPECT_TRUE(see(a, b)) << "segment " << s;
      ++judged_visible;
    }
    else if (longest_outside > 2.0 * min_step) {
      EXPECT_FALSE(see(a, b)) << "segment " << s;
      ++judged_hidden;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(judged_visible, 40);
  EXPECT_GT(judged_hidden, 40);
}

} // namespace
