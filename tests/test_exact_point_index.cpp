/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// The exact index answers every query as a scan in double: checked against that scan on points
// where float rounding and ties matter.
#include "../src/common/exact_point_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using segmat::detail::ExactPointIndex;

namespace {

/// Points on a lattice of spacing 1/8 far from the origin, every other one moved by a few 1e-9
/// (float keeps about 0.03 of a spacing there, so float distances tie where double ones do
/// not), with an exact duplicate and a NaN.
std::vector<Eigen::Vector3d>
latticePoints(std::mt19937& rng)
{
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 600; ++i) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a)
      p[a] = 40000.0 + double(rng() % 64) / 8.0 + (i % 2 ? double(rng() % 3) * 1e-9 : 0.0);
    points.push_back(p);
  }
  points.push_back(points[17]); // a duplicate: ties go to the lower index, 17
  points.insert(points.begin() + 5, Eigen::Vector3d(std::nan(""), 0.0, 0.0));
  return points;
}

int
scanNearest(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& q)
{
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < points.size(); ++s) {
    const double d = (points[s] - q).squaredNorm();
    if (d < best_d) { // strict: the first of equal distances stays
      best_d = d;
      best = int(s);
    }
  }
  return best;
}

} // namespace

TEST(ExactPointIndex, NearestIsTheScansNearestTiesIncluded)
{
  std::mt19937 rng(7u);
  const std::vector<Eigen::Vector3d> points = latticePoints(rng);
  const ExactPointIndex index(points);
  int ties = 0, float_ties = 0;
  for (int k = 0; k < 2000; ++k) {
    Eigen::Vector3d q;
    for (int a = 0; a < 3; ++a)
      q[a] = 40000.0 + double(rng() % 129) / 16.0; // half-way points: many equidistant pairs
    const int expected = scanNearest(points, q);
    ASSERT_EQ(index.nearest(q), expected) << "query " << k;
    const double d = (points[std::size_t(expected)] - q).norm();
    int equal = 0, close = 0;
    for (const Eigen::Vector3d& p : points) {
      equal += (p - q).norm() == d;
      close += std::abs((p - q).norm() - d) < 1e-7;
    }
    ties += equal > 1;
    float_ties += close > equal;
  }
  // The queries did test the tie rule, and nearest points that float cannot tell apart.
  EXPECT_GT(ties, 20);
  EXPECT_GT(float_ties, 20);
  // The duplicate of point 17 (index 18 after the NaN went in at 5) loses to it.
  EXPECT_EQ(index.nearest(points[18]), 18);
  EXPECT_EQ(index.nearest(points.back()), 18);
}

TEST(ExactPointIndex, WithinIsStrictAndExact)
{
  std::mt19937 rng(11u);
  const std::vector<Eigen::Vector3d> points = latticePoints(rng);
  const ExactPointIndex index(points);
  std::vector<int> found;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d q = points[1 + rng() % (points.size() - 1)];
    const double radius = double(1 + rng() % 8) / 8.0; // lattice distances fall on it exactly
    index.within(q, radius, found);
    std::sort(found.begin(), found.end());
    std::vector<int> expected;
    for (std::size_t s = 0; s < points.size(); ++s)
      if ((points[s] - q).norm() < radius)
        expected.push_back(int(s));
    ASSERT_EQ(found, expected) << "query " << k;
  }
}

TEST(ExactPointIndex, NonFiniteQueriesAndEmptyIndexFindNothing)
{
  const std::vector<Eigen::Vector3d> none;
  const ExactPointIndex empty(none);
  std::vector<int> found{1, 2};
  empty.within(Eigen::Vector3d::Zero(), 1.0, found);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(empty.nearest(Eigen::Vector3d::Zero()), -1);

  const std::vector<Eigen::Vector3d> one{Eigen::Vector3d(1, 2, 3)};
  const ExactPointIndex index(one);
  EXPECT_EQ(index.nearest(Eigen::Vector3d(1e30, 0, 0)), 0); // its squared distance overflows float
  EXPECT_EQ(index.nearest(Eigen::Vector3d(1e39, 0, 0)), 0); // the query itself does
  index.within(Eigen::Vector3d(1e39, 0, 0), 2e39, found);
  EXPECT_EQ(found, std::vector<int>{0});
  index.within(Eigen::Vector3d(1e39, 0, 0), 1e38, found);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(index.nearest(Eigen::Vector3d(std::nan(""), 0, 0)), -1);
  index.within(Eigen::Vector3d(1, 2, 3), std::numeric_limits<double>::infinity(), found);
  EXPECT_TRUE(found.empty());
  index.within(Eigen::Vector3d(1, 2, 3.5), 0.5, found); // at distance exactly 0.5: outside
  EXPECT_TRUE(found.empty());
  index.within(Eigen::Vector3d(1, 2, 3.5), 0.5000001, found);
  EXPECT_EQ(found, std::vector<int>{0});
}
