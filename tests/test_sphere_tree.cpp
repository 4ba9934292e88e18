// SphereTree against brute force.
#include <segmat/geometry/sphere_tree.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace segmat;

namespace {
double
unit(std::mt19937& rng)
{
  return static_cast<double>(rng()) / 4294967296.0; // [0, 1) from the raw engine output
}
} // namespace

TEST(SphereTree, MatchesBruteForceExactly)
{
  std::mt19937 rng(1234u);
  std::vector<Eigen::Vector3d> centers(700);
  std::vector<double> radii(700);
  for (std::size_t i = 0; i < centers.size(); ++i) {
    centers[i] = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 4.0;
    radii[i] = 0.3 * unit(rng);
  }
  // A subset with duplicates and junk indices.
  std::vector<int> subset;
  for (int i = 0; i < 700; i += 3)
    subset.push_back(i);
  subset.push_back(3);
  subset.push_back(-5);
  subset.push_back(10000);
  const SphereTree all(centers, radii), some(centers, radii, subset);
  EXPECT_EQ(all.size(), 700u);
  EXPECT_EQ(some.size(), 234u);
  // Spheres are read back by the index given to the constructor, whatever the tree's order.
  for (int i : {0, 3, 699}) {
    EXPECT_EQ(all.center(i), centers[i]);
    EXPECT_EQ(all.radius(i), radii[i]);
    EXPECT_EQ(some.center(i), centers[i]);
    EXPECT_EQ(some.radius(i), radii[i]);
  }
  int hint = -1;
  for (int q = 0; q < 500; ++q) {
    const Eigen::Vector3d p = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 5.0 -
                              Eigen::Vector3d::Constant(0.5);
    double brute_all = std::numeric_limits<double>::infinity(), brute_some = brute_all;
    int arg_all = -1;
    for (int i = 0; i < 700; ++i) {
      const double d = (p - centers[i]).norm() - radii[i];
      if (d < brute_all) {
        brute_all = d;
        arg_all = i;
      }
      if (i % 3 == 0)
        brute_some = std::min(brute_some, d);
    }
    int nearest = -1;
    EXPECT_EQ(all.signedDistance(p, -std::numeric_limits<double>::infinity(), &nearest),
              brute_all);
    EXPECT_EQ(nearest, arg_all);
    // With a hint carried over from the previous query: same value.
    EXPECT_EQ(some.signedDistance(p, -std::numeric_limits<double>::infinity(), &hint),
              brute_some);
    EXPECT_EQ(hint % 3, 0);
    // Early stop at 0: the exact value when it is positive, otherwise some value <= 0.
    const double clamped = all.signedDistance(p, 0.0);
    if (brute_all > 0.0)
      EXPECT_EQ(clamped, brute_all);
    else
      EXPECT_LE(clamped, 0.0);
  }
}

TEST(SphereTree, EmptyAndSingle)
{
  const SphereTree empty;
  int nearest = 4;
  EXPECT_TRUE(std::isinf(empty.signedDistance(Eigen::Vector3d::Zero(), 0.0, &nearest)));
  EXPECT_EQ(nearest, -1);
  const SphereTree none({{0, 0, 0}}, {1.0}, {7});
  EXPECT_TRUE(none.empty());

  const SphereTree one({{1, 0, 0}, {5, 5, 5}}, {0.5, 1.0}, {0});
  EXPECT_DOUBLE_EQ(one.signedDistance(Eigen::Vector3d(4, 0, 0)), 2.5);
  EXPECT_DOUBLE_EQ(one.signedDistance(Eigen::Vector3d(1, 0, 0)), -0.5); // inside
  nearest = 1; // a hint outside the tree is ignored
  EXPECT_DOUBLE_EQ(one.signedDistance(Eigen::Vector3d(1, 2, 0), 0.0, &nearest), 1.5);
  EXPECT_EQ(nearest, 0);
}

TEST(SphereTree, CoincidentCentres)
{
  // Many spheres at one point: the median split degenerates but stays correct.
  std::vector<Eigen::Vector3d> centers(100, Eigen::Vector3d(1, 1, 1));
  std::vector<double> radii(100);
  for (int i = 0; i < 100; ++i)
    radii[i] = 0.01 * i;
  const SphereTree tree(centers, radii);
  int nearest = -1;
  EXPECT_DOUBLE_EQ(tree.signedDistance(Eigen::Vector3d(1, 1, 4), -1e9, &nearest), 3.0 - 0.99);
  EXPECT_EQ(nearest, 99);
}
