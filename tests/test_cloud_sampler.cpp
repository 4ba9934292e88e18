// The test cloud sampler: area-uniform, seeded, true normals and sources.
#include "util/cloud_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace segmat;
using namespace segmat::test;

namespace {
// Two triangles of area 1 and 3 (coplanar, z = 0, normal +z) and one of area 0 (degenerate).
TriangleMesh
threeFaces()
{
  return TriangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {10, 0, 0}, {13, 0, 0}, {10, 2, 0}},
                      {{0, 1, 2}, {3, 4, 5}, {0, 0, 1}});
}
} // namespace

TEST(CloudSampler, MeshSamplesAreOnTheirFaceWithAreaWeights)
{
  const TriangleMesh mesh = threeFaces();
  const SampledCloud cloud = sampleMesh(mesh, 4000, 7);
  ASSERT_EQ(cloud.size(), 4000u);
  int on_first = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const int f = cloud.source[i];
    ASSERT_TRUE(f == 0 || f == 1); // never the degenerate face
    EXPECT_EQ(cloud.points[i].z(), 0.0f);
    EXPECT_TRUE(cloud.normals[i].isApprox(Eigen::Vector3f::UnitZ()));
    const float x = cloud.points[i].x(), y = cloud.points[i].y();
    if (f == 0) {
      ++on_first;
      EXPECT_GE(x, 0.0f);
      EXPECT_GE(y, 0.0f);
      EXPECT_LE(x / 2.0f + y, 1.0f + 1e-6f);
    }
    else {
      EXPECT_GE(x, 10.0f);
      EXPECT_LE((x - 10.0f) / 3.0f + y / 2.0f, 1.0f + 1e-6f);
    }
  }
  // Area 1 against 3: a quarter of the points, binomial sd = sqrt(4000·0.25·0.75) ≈ 27.
  EXPECT_NEAR(on_first, 1000, 5 * 27);
}

TEST(CloudSampler, SeededAndRepeatable)
{
  const SampledCloud a = sampleMesh(threeFaces(), 100, 3), b = sampleMesh(threeFaces(), 100, 3);
  const SampledCloud c = sampleMesh(threeFaces(), 100, 4);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
  EXPECT_TRUE(sampleMesh(TriangleMesh(), 10).points.empty());
}

TEST(CloudSampler, PointLabelsFollowTheSourceFace)
{
  const SampledCloud cloud = sampleMesh(threeFaces(), 50, 1);
  const std::vector<int> labels = cloud.pointLabels({7, 9, 11});
  for (std::size_t i = 0; i < cloud.size(); ++i)
    EXPECT_EQ(labels[i], cloud.source[i] == 0 ? 7 : 9);
}

TEST(CloudSampler, NoiseHasTheRequestedSigma)
{
  SampledCloud cloud = discCloud(20000, 5);
  addGaussianNoise(cloud, 0.01, 6);
  // The disc's bounding-box diagonal is about 2√2 (z extent adds little): sigma ≈ 0.0283.
  double sum2 = 0.0;
  for (const Eigen::Vector3f& p : cloud.points)
    sum2 += double(p.z()) * p.z();
  EXPECT_NEAR(std::sqrt(sum2 / cloud.size()), 0.01 * 2.0 * std::sqrt(2.0), 0.002);
}

TEST(CloudSampler, AnalyticShapesLieOnTheirSurfaces)
{
  for (const SampledCloud& s : {sphereCloud(500), torusCloud(500)})
    ASSERT_EQ(s.size(), 500u);
  for (std::size_t i = 0; i < 500; ++i) {
    const SampledCloud sphere = sphereCloud(500);
    EXPECT_NEAR(sphere.points[i].norm(), 1.0f, 1e-6f);
    EXPECT_TRUE(sphere.points[i].isApprox(sphere.normals[i]));
  }
  const SampledCloud torus = torusCloud(500);
  for (std::size_t i = 0; i < torus.size(); ++i) {
    const Eigen::Vector3f p = torus.points[i];
    const Eigen::Vector3f ring = Eigen::Vector3f(p.x(), p.y(), 0).normalized() * 2.0f;
    EXPECT_NEAR((p - ring).norm(), 0.5f, 1e-5f);
    EXPECT_TRUE(((p - ring) / 0.5f).isApprox(torus.normals[i], 1e-4f));
  }
  // Dumbbell: three parts; balls at distance 1 from (±3,0,0), tube at distance 0.3 from x.
  const SampledCloud db = dumbbellCloud(3000);
  int count[3] = {0, 0, 0};
  for (std::size_t i = 0; i < db.size(); ++i) {
    const Eigen::Vector3f p = db.points[i];
    ++count[db.source[i]];
    if (db.source[i] == 1)
      EXPECT_NEAR(std::hypot(p.y(), p.z()), 0.3f, 1e-5f);
    else
      EXPECT_NEAR((p - Eigen::Vector3f(db.source[i] == 0 ? -3 : 3, 0, 0)).norm(), 1.0f, 1e-5f);
  }
  // Areas: each ball 4π − 2π(1 − √0.91) ≈ 12.29, tube 2π·0.3·2·(3 − √0.91) ≈ 7.52.
  EXPECT_NEAR(count[1] / 3000.0, 7.52 / (2 * 12.29 + 7.52), 0.02);
  // L tube: no point strictly inside either capsule.
  const SampledCloud l = lTubeCloud(2000);
  for (std::size_t i = 0; i < l.size(); ++i) {
    const Eigen::Vector3f p = l.points[i];
    const float dx = std::hypot(p.y(), p.z()) * (p.x() >= 0 && p.x() <= 4) +
                     (p.x() < 0 || p.x() > 4) * (p - Eigen::Vector3f(std::clamp(p.x(), 0.f, 4.f), 0, 0)).norm();
    EXPECT_GE(dx, 0.5f - 1e-5f);
  }
}
