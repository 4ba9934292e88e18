// IoU and Chamfer distance of boxes against a solid, with values worked out by hand.
#include <segmat/common/error.h>
#include <segmat/evaluation/box_abstraction_metrics.h>

#include <util/synthetic_mesh.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace segmat;

namespace {
OrientedBox
axisBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
  OrientedBox box;
  box.center = 0.5 * (lo + hi);
  box.extents = hi - lo;
  return box;
}
} // namespace

TEST(BoxAbstractionMetrics, ExactBoxScoresOne)
{
  const TriangleMesh shape = test::box({0, 0, 0}, {1, 1, 1}, 4);
  const BoxAbstractionScores s =
      scoreBoxAbstraction(shape, {axisBox({0, 0, 0}, {1, 1, 1})}, 32, 10000);
  EXPECT_EQ(s.iou, 1.0);
  // Two independent samplings of one surface (10000 points on area 6, spacing about 0.025):
  // only the sampling gap remains, a fraction of the spacing over the diagonal √3.
  EXPECT_LT(s.chamfer, 0.01);
  EXPECT_LT(s.chamfer_squared, 1e-4);
}

TEST(BoxAbstractionMetrics, HalfABarMatchesTheWorkedOutValues)
{
  // Shape [0,2]×[0,1]², box [0,1]³ (diagonal √6). IoU: half the cells (32 along x).
  // Chamfer, shape → box: 4 of the 10 units of area at mean distance 1/2 (sides, x − 1), 1 at
  // distance 1 (the end), mean 0.3; box → shape: only the face x = 1 (1 of 6) is off the
  // surface, at the mean distance 1/6 to the square's border: 1/36. CD = ½ (0.3 + 1/36) / √6 = 0.06692. Squared: sides
  // E[(x−1)²] = 1/3, end 1: 0.2333; the face E[d²] = 1/24: 1/144; CD² = ½ (0.2333 + 1/144) / 6
  // = 0.02002.
  const TriangleMesh shape = test::box({0, 0, 0}, {2, 1, 1}, 8);
  for (const unsigned threads : {1u, 2u}) {
    const BoxAbstractionScores s =
        scoreBoxAbstraction(shape, {axisBox({0, 0, 0}, {1, 1, 1})}, 32, 20000, threads);
    EXPECT_NEAR(s.iou, 0.5, 1e-12);
    EXPECT_NEAR(s.chamfer, 0.06692, 0.003);
    EXPECT_NEAR(s.chamfer_squared, 0.02002, 0.001);
  }
  // A union of two boxes covering the bar is exact again; overlap is counted once.
  const BoxAbstractionScores both = scoreBoxAbstraction(
      shape, {axisBox({0, 0, 0}, {1.25, 1, 1}), axisBox({0.75, 0, 0}, {2, 1, 1})}, 32, 1000);
  EXPECT_EQ(both.iou, 1.0);
}

TEST(BoxAbstractionMetrics, BadInputIsRefused)
{
  const TriangleMesh shape = test::box({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(scoreBoxAbstraction(shape, {}), Error);
  EXPECT_THROW(scoreBoxAbstraction(TriangleMesh(), {axisBox({0, 0, 0}, {1, 1, 1})}), Error);
  EXPECT_THROW(scoreBoxAbstraction(shape, {axisBox({0, 0, 0}, {1, 1, 1})}, 1), Error);
}
