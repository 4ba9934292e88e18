// Shrinking balls on shapes whose medial axis is known in closed form.
#include "util/cloud_sampler.h"

#include <segmat/medial/shrinking_ball_estimation.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace segmat;
using namespace segmat::test;

TEST(ShrinkingBall, SphereBallsAreTheSphere)
{
  ShrinkingBallEstimation estimation;
  estimation.setInputCloud(sphereCloud(3000, 1).toPointNormal());
  pcl::PointCloud<MedialPoint> balls;
  ASSERT_TRUE(estimation.compute(balls));
  ASSERT_EQ(balls.size(), 3000u);
  EXPECT_TRUE(balls.is_dense);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    // Every ball is the unit sphere itself up to the sampling: the ball through p and q tangent
    // at p has radius 1 exactly when q is on the sphere.
    EXPECT_NEAR(balls[i].radius, 1.0f, 1e-3f);
    EXPECT_LT(balls[i].getVector3fMap().norm(), 1e-3f);
    EXPECT_EQ(balls[i].surface_index, int(i));
    EXPECT_GE(balls[i].contact_index, 0);
    EXPECT_NE(balls[i].contact_index, int(i));
  }
}

TEST(ShrinkingBall, TorusBallsSitOnTheCoreCircle)
{
  const SampledCloud torus = torusCloud(20000, 2);
  ShrinkingBallEstimation estimation;
  estimation.setInputCloud(torus.toPointNormal());
  // Balls for every 10th point only; the search still sees all 20000.
  auto selected = std::make_shared<std::vector<int>>();
  for (int i = 0; i < 20000; i += 10)
    selected->push_back(i);
  estimation.setIndices(selected);
  pcl::PointCloud<MedialPoint> balls;
  ASSERT_TRUE(estimation.compute(balls));
  ASSERT_EQ(balls.size(), 2000u);
  int good = 0;
  for (const MedialPoint& b : balls) {
    const Eigen::Vector3f c = b.getVector3fMap();
    // Medial axis: the circle of radius 2 in z = 0; radius 0.5.
    good += std::abs(b.radius - 0.5f) < 0.01f && std::abs(std::hypot(c.x(), c.y()) - 2.0f) < 0.01f &&
            std::abs(c.z()) < 0.01f;
  }
  EXPECT_GE(good, 1990);
}

TEST(ShrinkingBall, FlatDiscHasNoInteriorBall)
{
  ShrinkingBallEstimation estimation;
  estimation.setInputCloud(discCloud(2000, 3).toPointNormal());
  pcl::PointCloud<MedialPoint> balls;
  ASSERT_TRUE(estimation.compute(balls));
  EXPECT_FALSE(balls.is_dense);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    EXPECT_TRUE(std::isnan(balls[i].radius));
    EXPECT_TRUE(std::isnan(balls[i].x));
    EXPECT_TRUE(std::isnan(estimation.getSeparationAngles()[i]));
  }
}

TEST(ShrinkingBall, ThreadCountDoesNotChangeTheBalls)
{
  auto cloud = dumbbellCloud(6000, 4).toPointNormal();
  pcl::PointCloud<MedialPoint> one, two;
  ShrinkingBallEstimation estimation;
  estimation.setInputCloud(cloud);
  estimation.setNumberOfThreads(1);
  ASSERT_TRUE(estimation.compute(one));
  estimation.setNumberOfThreads(2);
  ASSERT_TRUE(estimation.compute(two));
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].radius, two[i].radius);
    ASSERT_EQ(one[i].contact_index, two[i].contact_index);
  }
}

TEST(ShrinkingBall, BadInputAndSettersThatRefuse)
{
  ShrinkingBallEstimation estimation;
  pcl::PointCloud<MedialPoint> balls;
  EXPECT_FALSE(estimation.compute(balls));
  estimation.setInputCloud(sphereCloud(1).toPointNormal());
  EXPECT_FALSE(estimation.compute(balls)); // one point
  estimation.setInputCloud(sphereCloud(100).toPointNormal());
  estimation.setIndices(std::make_shared<std::vector<int>>(std::vector<int>{0, 100}));
  EXPECT_FALSE(estimation.compute(balls));
  EXPECT_TRUE(balls.empty());
  estimation.setMaxIterations(0);
  EXPECT_EQ(estimation.getMaxIterations(), 30);
  estimation.setDenoisePlanarAngle(-1.0f);
  EXPECT_NEAR(estimation.getDenoisePlanarAngle(), 32.0 * M_PI / 180.0, 1e-6);
  estimation.setInitialRadius(std::nanf(""));
  EXPECT_EQ(estimation.getInitialRadius(), 0.0f);
}
