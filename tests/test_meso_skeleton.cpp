// Meso-skeletons of analytic clouds, for every instantiated point type, and bad inputs.
#include "util/cloud_sampler.h"

#include <segmat/medial/meso_skeleton_estimation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;
using namespace segmat::test;

namespace {

template <typename PointT>
bool
skeletonOf(const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
           pcl::PointCloud<MedialPoint>& out, unsigned threads = 0)
{
  MesoSkeletonEstimation<PointT> estimation;
  estimation.setInputCloud(cloud);
  estimation.setNumberOfThreads(threads);
  return estimation.compute(out);
}

/// Checks a dumbbell skeleton: the medial axis is the x axis from −3 to 3; the radius is 0.3
/// along the tube (|x| < 1.8) and 1 at the balls' centres (|x| ≈ 3; with estimated normals the
/// centres of a ball's balls scatter by a few hundredths, and the radius of a centre d off
/// the ball's centre is 1 − d). Where the tube meets a ball (the concave crease at
/// |x| = 3 − √0.91 ≈ 2.05) a few centres may stray: at least 95 % must be on the axis.
void
expectDumbbell(const pcl::PointCloud<MedialPoint>& skeleton, std::size_t input_size)
{
  ASSERT_FALSE(skeleton.empty());
  std::size_t in_balls = 0, on_tube = 0, on_axis = 0;
  for (const MedialPoint& m : skeleton) {
    const float off_axis = std::hypot(m.y, m.z);
    on_axis += off_axis < 0.05f;
    EXPECT_LT(std::abs(m.x), 3.2f);
    if (std::abs(std::abs(m.x) - 3.0f) < 0.05f) {
      EXPECT_NEAR(m.radius, 1.0f, 0.07f);
      ++in_balls;
    }
    if (std::abs(m.x) < 1.8f) {
      EXPECT_LT(off_axis, 0.02f);
      EXPECT_NEAR(m.radius, 0.3f, 0.02f);
      ++on_tube;
    }
    EXPECT_GE(m.surface_index, 0);
    EXPECT_LT(m.surface_index, int(input_size));
    EXPECT_LT(m.contact_index, int(input_size));
    EXPECT_NEAR(m.getNormalVector3fMap().norm(), 1.0f, 1e-4f);
  }
  EXPECT_GE(on_axis, skeleton.size() * 95 / 100);
  EXPECT_GE(in_balls, 2u);
  EXPECT_GE(on_tube, 10u);
}

} // namespace

TEST(MesoSkeleton, DumbbellWithTrueNormals)
{
  const SampledCloud shape = dumbbellCloud(15000, 1);
  pcl::PointCloud<MedialPoint> skeleton;
  ASSERT_TRUE(skeletonOf<pcl::PointNormal>(shape.toCloud<pcl::PointNormal>(), skeleton));
  expectDumbbell(skeleton, shape.size());
  // Tube points are curve-like: their normal slot holds the curve direction, x.
  for (const MedialPoint& m : skeleton)
    if (std::abs(m.x) < 1.5f)
      EXPECT_GT(std::abs(m.normal_x), 0.9f);
}

TEST(MesoSkeleton, DumbbellWithoutNormalsAndWithColour)
{
  const SampledCloud shape = dumbbellCloud(20000, 2);
  pcl::PointCloud<MedialPoint> skeleton;
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(shape.toCloud<pcl::PointXYZ>(), skeleton));
  expectDumbbell(skeleton, shape.size());
  ASSERT_TRUE(
      skeletonOf<pcl::PointXYZRGBNormal>(shape.toCloud<pcl::PointXYZRGBNormal>(), skeleton));
  expectDumbbell(skeleton, shape.size());
}

TEST(MesoSkeleton, SphereIsOneBlobAtTheCentre)
{
  pcl::PointCloud<MedialPoint> skeleton;
  ASSERT_TRUE(skeletonOf<pcl::PointNormal>(sphereCloud(10000, 3).toCloud<pcl::PointNormal>(),
                                           skeleton));
  // Every ball lands within the sampling error of the centre; the minimum spacing
  // (0.005 × diagonal ≈ 0.017) leaves at most the 8 cells around it.
  EXPECT_GE(skeleton.size(), 1u);
  EXPECT_LE(skeleton.size(), 8u);
  for (const MedialPoint& m : skeleton) {
    EXPECT_LT(m.getVector3fMap().norm(), 0.02f);
    EXPECT_NEAR(m.radius, 1.0f, 0.02f);
  }
}

TEST(MesoSkeleton, LargeCloudIsResampledAndIndicesPointIntoTheInput)
{
  const SampledCloud shape = torusCloud(60000, 4);
  MesoSkeletonEstimation<pcl::PointNormal> estimation;
  estimation.setInputCloud(shape.toCloud<pcl::PointNormal>());
  estimation.setWorkingSize(8000);
  estimation.setTargetSize(500);
  pcl::PointCloud<MedialPoint> skeleton;
  ASSERT_TRUE(estimation.compute(skeleton));
  const MesoSkeletonStatistics& stats = estimation.getStatistics();
  EXPECT_EQ(stats.input_points, 60000u);
  EXPECT_NEAR(double(stats.working_points), 8000.0, 800.0);
  EXPECT_NEAR(double(skeleton.size()), 500.0, 100.0);
  for (const MedialPoint& m : skeleton) {
    EXPECT_NEAR(std::hypot(m.x, m.y), 2.0f, 0.02f);
    EXPECT_NEAR(m.radius, 0.5f, 0.02f);
    // The nearest input point is on the torus, 0.5 away (up to the working-cloud spacing).
    EXPECT_NEAR((shape.points[m.surface_index] - m.getVector3fMap()).norm(), 0.5f, 0.02f);
  }
}

TEST(MesoSkeleton, DeterministicAcrossRunsAndThreads)
{
  const auto cloud = lTubeCloud(8000, 5).toCloud<pcl::PointXYZ>();
  pcl::PointCloud<MedialPoint> a, b, c;
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(cloud, a, 1));
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(cloud, b, 1));
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(cloud, c, 2));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), c.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (const auto* other : {&b, &c}) {
      ASSERT_EQ(a[i].getVector3fMap(), (*other)[i].getVector3fMap());
      ASSERT_EQ(a[i].radius, (*other)[i].radius);
      ASSERT_EQ(a[i].getNormalVector3fMap(), (*other)[i].getNormalVector3fMap());
      ASSERT_EQ(a[i].surface_index, (*other)[i].surface_index);
    }
  }
}

TEST(MesoSkeleton, DegenerateCloudsFailWithoutCrashing)
{
  pcl::PointCloud<MedialPoint> skeleton;
  MesoSkeletonEstimation<pcl::PointXYZ> estimation;
  EXPECT_FALSE(estimation.compute(skeleton)); // no input
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  estimation.setInputCloud(cloud);
  EXPECT_FALSE(estimation.compute(skeleton)); // empty
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->resize(50, pcl::PointXYZ(nan, nan, nan));
  EXPECT_FALSE(estimation.compute(skeleton)); // all NaN
  cloud->clear();
  for (int i = 0; i < 5; ++i)
    cloud->push_back(pcl::PointXYZ(float(i % 2), float(i / 2), float(i * i % 3)));
  EXPECT_FALSE(estimation.compute(skeleton)); // 5 points: no interior ball
  EXPECT_TRUE(skeleton.empty());
  // A flat disc encloses nothing.
  estimation.setInputCloud(discCloud(3000, 6).toCloud<pcl::PointXYZ>());
  EXPECT_FALSE(estimation.compute(skeleton));
  EXPECT_TRUE(skeleton.empty());
  // Duplicated points: the same skeleton as without the copies.
  const SampledCloud sphere = sphereCloud(4000, 7);
  auto doubled = sphere.toCloud<pcl::PointXYZ>();
  for (std::size_t i = 0; i < sphere.size(); ++i)
    doubled->push_back((*doubled)[i]);
  pcl::PointCloud<MedialPoint> once, twice;
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(sphere.toCloud<pcl::PointXYZ>(), once));
  ASSERT_TRUE(skeletonOf<pcl::PointXYZ>(doubled, twice));
  ASSERT_EQ(once.size(), twice.size());
  for (std::size_t i = 0; i < once.size(); ++i)
    EXPECT_EQ(once[i].getVector3fMap(), twice[i].getVector3fMap());
}

TEST(MesoSkeleton, IndicesSelectTheInputAndSettersRefuseBadValues)
{
  // The input is two dumbbells; indices select the first only.
  const SampledCloud shape = dumbbellCloud(10000, 8);
  auto cloud = shape.toCloud<pcl::PointNormal>();
  auto indices = std::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < shape.size(); ++i) {
    indices->push_back(int(cloud->size()));
    cloud->push_back((*cloud)[i]);
    cloud->back().y += 100.0f; // decoy far away, not selected
    std::swap(cloud->back(), (*cloud)[i]);
  }
  MesoSkeletonEstimation<pcl::PointNormal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setIndices(indices);
  pcl::PointCloud<MedialPoint> skeleton;
  ASSERT_TRUE(estimation.compute(skeleton));
  expectDumbbell(skeleton, cloud->size());
  for (const MedialPoint& m : skeleton)
    EXPECT_GE(m.surface_index, int(shape.size())); // only selected points are touched
  estimation.setWorkingSize(0);
  estimation.setTargetSize(0);
  estimation.setContractionIterations(-1);
  estimation.setNormalKSearch(2);
  estimation.setMinSeparationAngle(4.0f);
  const MesoSkeletonParameters defaults;
  EXPECT_EQ(estimation.getParameters().working_size, defaults.working_size);
  EXPECT_EQ(estimation.getParameters().target_size, defaults.target_size);
  EXPECT_EQ(estimation.getParameters().contraction_iterations, defaults.contraction_iterations);
  EXPECT_EQ(estimation.getParameters().normal_k, defaults.normal_k);
  EXPECT_EQ(estimation.getParameters().min_separation_angle, defaults.min_separation_angle);
}
