// MST normal orientation and the cloud pre-processing that uses it.
#include "util/cloud_sampler.h"

#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/medial/normal_orientation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

using namespace segmat;
using namespace segmat::test;

namespace {

/// The cloud with about half of its normals reversed, chosen by a seeded engine.
pcl::PointCloud<pcl::PointNormal>::Ptr
withShuffledSigns(const SampledCloud& sampled, std::uint32_t seed)
{
  auto cloud = sampled.toPointNormal();
  std::mt19937 rng(seed);
  for (auto& p : *cloud)
    if (rng() & 1u)
      p.getNormalVector3fMap() *= -1.0f;
  return cloud;
}

/// Points whose normal agrees in sign with the true outward normal.
std::size_t
countOutward(const pcl::PointCloud<pcl::PointNormal>& cloud, const SampledCloud& truth,
             const std::vector<int>& index_in_truth)
{
  std::size_t outward = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    outward += cloud[i].getNormalVector3fMap().dot(truth.normals[index_in_truth[i]]) > 0.0f;
  return outward;
}

std::vector<int>
identity(std::size_t n)
{
  std::vector<int> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = static_cast<int>(i);
  return v;
}

} // namespace

TEST(NormalOrientation, ShuffledSignsOnClosedSurfacesComeOutOutward)
{
  for (const SampledCloud& shape : {sphereCloud(3000, 11), torusCloud(4000, 12)}) {
    auto cloud = withShuffledSigns(shape, 5);
    NormalOrientation orientation;
    ASSERT_TRUE(orientation.orient(*cloud));
    EXPECT_EQ(orientation.getNumberOfComponents(), 1u);
    EXPECT_EQ(countOutward(*cloud, shape, identity(shape.size())), shape.size());
    // About half were reversed by the shuffle, and only those are reversed back.
    EXPECT_NEAR(double(orientation.getNumberOfReversed()), shape.size() / 2.0,
                0.05 * shape.size());
  }
}

TEST(NormalOrientation, AllInwardIsReversedAndSeparateComponentsAreEachOriented)
{
  // Two spheres far apart with every normal pointing inward: two components, all reversed.
  SampledCloud a = sphereCloud(1500, 1), b = sphereCloud(1500, 2);
  SampledCloud both;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both.points.push_back(a.points[i]);
    both.normals.push_back(a.normals[i]);
    both.points.push_back(b.points[i] + Eigen::Vector3f(10, 0, 0));
    both.normals.push_back(b.normals[i]);
  }
  auto cloud = both.toPointNormal();
  for (auto& p : *cloud)
    p.getNormalVector3fMap() *= -1.0f;
  NormalOrientation orientation;
  ASSERT_TRUE(orientation.orient(*cloud));
  EXPECT_EQ(orientation.getNumberOfComponents(), 2u);
  EXPECT_EQ(orientation.getNumberOfReversed(), both.size());
  EXPECT_EQ(countOutward(*cloud, both, identity(both.size())), both.size());
}

TEST(NormalOrientation, BadInputIsRefused)
{
  NormalOrientation orientation;
  pcl::PointCloud<pcl::PointNormal> empty;
  EXPECT_FALSE(orientation.orient(empty));
  auto cloud = sphereCloud(50).toPointNormal();
  (*cloud)[7].normal_y = std::numeric_limits<float>::quiet_NaN();
  const auto before = *cloud;
  EXPECT_FALSE(orientation.orient(*cloud));
  EXPECT_EQ((*cloud)[3].getNormalVector3fMap(), before[3].getNormalVector3fMap());
  (*cloud)[7].getNormalVector3fMap().setZero();
  EXPECT_FALSE(orientation.orient(*cloud));
  // A single point: its normal is turned towards +x.
  pcl::PointCloud<pcl::PointNormal> one;
  pcl::PointNormal p;
  p.getVector3fMap() = Eigen::Vector3f(1, 2, 3);
  p.getNormalVector3fMap() = Eigen::Vector3f(-1, 0, 0);
  one.push_back(p);
  ASSERT_TRUE(orientation.orient(one));
  EXPECT_EQ(one[0].normal_x, 1.0f);
}

TEST(CloudPreprocessing, EstimatedNormalsOfAnXyzTorusAndDumbbellPointOutward)
{
  for (const SampledCloud& shape : {torusCloud(8000, 3), dumbbellCloud(8000, 4)}) {
    auto cloud = shape.toPointNormal();
    for (auto& p : *cloud)
      p.normal_x = p.normal_y = p.normal_z = std::numeric_limits<float>::quiet_NaN();
    CloudPreprocessing pre;
    pre.setInputCloud(cloud);
    pre.setUseInputNormalsFlag(false);
    pcl::PointCloud<pcl::PointNormal> working;
    ASSERT_TRUE(pre.compute(working));
    EXPECT_TRUE(pre.getNormalsEstimated());
    ASSERT_EQ(working.size(), shape.size());
    EXPECT_EQ(countOutward(working, shape, pre.getWorkingIndices()), shape.size());
  }
}

TEST(CloudPreprocessing, ResamplesDropsNonFiniteAndDuplicatesAndIsThreadIndependent)
{
  const SampledCloud shape = torusCloud(30000, 8);
  auto cloud = shape.toPointNormal();
  (*cloud)[5].x = std::numeric_limits<float>::quiet_NaN();
  (*cloud)[6].z = std::numeric_limits<float>::infinity();
  CloudPreprocessing pre;
  pre.setInputCloud(cloud);
  pre.setWorkingSize(5000);
  pre.setUseInputNormalsFlag(false);
  pre.setNumberOfThreads(1);
  pcl::PointCloud<pcl::PointNormal> one, two;
  ASSERT_TRUE(pre.compute(one));
  const std::vector<int> indices = pre.getWorkingIndices();
  EXPECT_NEAR(double(one.size()), 5000.0, 500.0);
  for (int i : indices)
    EXPECT_TRUE(i != 5 && i != 6);
  EXPECT_EQ(countOutward(one, shape, indices), one.size());
  pre.setNumberOfThreads(2);
  ASSERT_TRUE(pre.compute(two));
  ASSERT_EQ(two.size(), one.size());
  EXPECT_EQ(pre.getWorkingIndices(), indices);
  for (std::size_t i = 0; i < one.size(); ++i)
    ASSERT_EQ(one[i].getNormalVector3fMap(), two[i].getNormalVector3fMap());

  // Exact duplicates collapse onto the first copy; input normals are kept (normalised). Dense
  // enough to be clean: 400 points of a unit sphere would read its curvature as noise, and a
  // noisy cloud's normals are set aside.
  auto doubled = sphereCloud(4000, 2).toPointNormal();
  const std::size_t n = doubled->size();
  for (std::size_t i = 0; i < n; ++i) {
    auto p = (*doubled)[i];
    p.getNormalVector3fMap() *= 3.0f;
    doubled->push_back(p);
  }
  pre.setInputCloud(doubled);
  pre.setWorkingSize(20000); // every distinct point
  pre.setUseInputNormalsFlag(true);
  pcl::PointCloud<pcl::PointNormal> dedup;
  ASSERT_TRUE(pre.compute(dedup));
  EXPECT_FALSE(pre.getNormalsEstimated());
  EXPECT_EQ(dedup.size(), n);
  for (std::size_t i = 0; i < dedup.size(); ++i) {
    EXPECT_LT(pre.getWorkingIndices()[i], int(n));
    EXPECT_NEAR(dedup[i].getNormalVector3fMap().norm(), 1.0f, 1e-6f);
  }
}

TEST(CloudPreprocessing, DegenerateInputsFailCleanly)
{
  CloudPreprocessing pre;
  pcl::PointCloud<pcl::PointNormal> working;
  EXPECT_FALSE(pre.compute(working)); // no input
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointNormal>>();
  pre.setInputCloud(cloud);
  EXPECT_FALSE(pre.compute(working)); // empty
  pcl::PointNormal nan_point;
  nan_point.x = nan_point.y = nan_point.z = std::numeric_limits<float>::quiet_NaN();
  cloud->resize(100, nan_point);
  EXPECT_FALSE(pre.compute(working)); // all NaN
  // Two distinct positions, repeated: too few for a normal.
  cloud->clear();
  pcl::PointNormal p;
  p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
  for (int i = 0; i < 10; ++i) {
    p.getVector3fMap() = Eigen::Vector3f(float(i % 2), 0, 0);
    cloud->push_back(p);
  }
  EXPECT_FALSE(pre.compute(working));
  EXPECT_TRUE(working.empty());
  // Collinear points: PCA normals exist (any direction across the line); no crash.
  cloud->clear();
  for (int i = 0; i < 10; ++i) {
    p.getVector3fMap() = Eigen::Vector3f(float(i), 0, 0);
    cloud->push_back(p);
  }
  pre.setUseInputNormalsFlag(false);
  pre.compute(working);
  SUCCEED();
}

namespace {
/// A closed box [−1, 1]² × [−h, h] as 12 outward triangles.
TriangleMesh
slab(double h)
{
  TriangleMesh box;
  for (int i = 0; i < 8; ++i)
    box.vertices.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? h : -h);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    box.faces.emplace_back(q[0], q[1], q[2]);
    box.faces.emplace_back(q[0], q[2], q[3]);
  }
  return box;
}
} // namespace

TEST(CloudPreprocessing, CleanCloudKeepsItsPositionsWhenNormalsAreEstimated)
{
  const SampledCloud shape = torusCloud(8000, 3);
  CloudPreprocessing pre;
  pre.setInputCloud(shape.toPointNormal());
  pre.setUseInputNormalsFlag(false);
  pcl::PointCloud<pcl::PointNormal> working;
  ASSERT_TRUE(pre.compute(working));
  ASSERT_EQ(working.size(), shape.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < working.size(); ++i)
    moved += working[i].getVector3fMap() != shape.points[pre.getWorkingIndices()[i]];
  EXPECT_EQ(moved, 0u); // no smoothing: the cloud is not noisy
}

TEST(CloudPreprocessing, NoisyThinSlabIsDenoisedAndKeepsItsTwoSides)
{
  // A 2 × 2 × 0.07 slab, 20 000 points, Gaussian noise σ = 0.5 % of the diagonal (2.829):
  // σ = 0.0141, the two big faces at z = ±0.035 are 5σ apart, closer than the 32 neighbours a
  // point is fitted to (radius ≈ 0.045). A plain height fit lands in the middle (|z| → 0); the
  // sided fit keeps each point on its face and takes a third of the noise off.
  const double half = 0.035;
  const SampledCloud clean = sampleMesh(slab(half), 20000, 5);
  SampledCloud noisy = clean;
  addGaussianNoise(noisy, 0.005, 6);
  CloudPreprocessing pre;
  pre.setInputCloud(noisy.toPointNormal());
  pre.setUseInputNormalsFlag(false);
  pcl::PointCloud<pcl::PointNormal> working;
  ASSERT_TRUE(pre.compute(working));
  ASSERT_TRUE(pre.getNormalsEstimated());
  double before = 0, after = 0, mean_abs_z = 0;
  std::size_t count = 0, same_side = 0, outward = 0;
  for (std::size_t i = 0; i < working.size(); ++i) {
    const int source = pre.getWorkingIndices()[i];
    const Eigen::Vector3f& truth = clean.points[source];
    if (std::abs(truth.x()) > 0.8f || std::abs(truth.y()) > 0.8f || std::abs(truth.z()) < half / 2)
      continue; // big faces only, away from the rims
    const float side = truth.z() > 0 ? 1.0f : -1.0f;
    const float z = working[i].z;
    before += std::pow(noisy.points[source].z() - truth.z(), 2);
    after += std::pow(z - truth.z(), 2);
    mean_abs_z += std::abs(z);
    same_side += z * side > 0;
    outward += working[i].normal_z * side > 0;
    ++count;
  }
  ASSERT_GT(count, 10000u);
  before = std::sqrt(before / count);
  after = std::sqrt(after / count);
  mean_abs_z /= count;
  EXPECT_NEAR(before, 0.0141, 0.001); // the noise that was added, across the faces
  EXPECT_LT(after, 0.75 * before); // measured 0.67
  EXPECT_NEAR(mean_abs_z, half, 0.006);
  EXPECT_GT(same_side, 0.97 * count);
  EXPECT_GT(outward, 0.95 * count); // measured 99.2 % and 97.4 %
}

TEST(NormalOrientation, MirrorRelationOrientsBothSidesOfAThinPlate)
{
  // A 2 × 2 × 0.02 plate, 6000 points: spacing ≈ √(8 / 6000) = 0.037, nearly twice the
  // thickness, so a point's 10 neighbours include points of the other side. Exact normals with
  // shuffled signs. Hoppe's relation (n_i·n_j, tangent-plane term off) sees the two sides as one
  // sheet and orients them alike; the mirror relation reflects n_j in the bisector plane of
  // p_i p_j (here z = 0 for a point straight across), which maps one side's outward normal onto
  // the other's.
  const SampledCloud plate = sampleMesh(slab(0.01), 6000, 7);
  std::size_t hoppe_outward = 0;
  {
    auto cloud = withShuffledSigns(plate, 8);
    NormalOrientation orientation;
    orientation.setTangentPlaneTermFlag(false);
    ASSERT_TRUE(orientation.orient(*cloud));
    hoppe_outward = countOutward(*cloud, plate, identity(plate.size()));
  }
  auto cloud = withShuffledSigns(plate, 8);
  NormalOrientation orientation;
  orientation.setMirrorRelationFlag(true);
  ASSERT_TRUE(orientation.orient(*cloud));
  EXPECT_EQ(orientation.getNumberOfComponents(), 1u);
  const std::size_t mirror_outward = countOutward(*cloud, plate, identity(plate.size()));
  EXPECT_GT(mirror_outward, 0.99 * plate.size()); // measured 5996 of 6000 (the rims)
  EXPECT_LT(hoppe_outward, 0.6 * plate.size());   // measured 2984: one side is inward

  // Where Hoppe's relation is right the mirror relation agrees: closed smooth surfaces.
  for (const SampledCloud& shape : {sphereCloud(3000, 11), torusCloud(4000, 12)}) {
    auto shuffled = withShuffledSigns(shape, 5);
    ASSERT_TRUE(orientation.orient(*shuffled));
    EXPECT_EQ(countOutward(*shuffled, shape, identity(shape.size())), shape.size());
  }
}

TEST(CloudPreprocessing, WarnsWhenFloatCoordinatesAreTooCoarseForTheCloud)
{
  // A unit sphere 10^5 out: floats step by 2^-7 ≈ 0.008 there, 0.2 % of its diagonal (3.5).
  auto cloud = sphereCloud(400, 2).toPointNormal();
  CloudPreprocessing pre;
  pre.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointNormal> working;
  ::testing::internal::CaptureStderr();
  ASSERT_TRUE(pre.compute(working));
  EXPECT_EQ(::testing::internal::GetCapturedStderr().find("from the origin"), std::string::npos);
  for (pcl::PointNormal& p : *cloud)
    p.x += 1e5f;
  ::testing::internal::CaptureStderr();
  ASSERT_TRUE(pre.compute(working)); // still segmentable, but the user is told why it is coarse
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("from the origin"), std::string::npos) << warning;
  EXPECT_NE(warning.find("grid"), std::string::npos) << warning;
}

TEST(CloudPreprocessing, SetsIsolatedPointsAsideButKeepsSparseRegions)
{
  // A unit sphere whose upper half is sampled 25 times more sparsely (5 times the spacing, as
  // a scan's far side), plus five flying points 3 units out, each on its own. (A clump of flying
  // points close together is not isolated and stays.)
  const auto sphere = sphereCloud(20000, 4).toPointNormal();
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  std::size_t upper = 0;
  for (const pcl::PointNormal& p : *sphere)
    if (p.z < 0.0f || upper++ % 25 == 0)
      cloud->push_back(p);
  const std::size_t surface = cloud->size();
  for (int i = 0; i < 5; ++i) {
    pcl::PointNormal p = (*cloud)[i];
    const float a = 1.2566f * float(i); // 72° apart around z
    p.getVector3fMap() = Eigen::Vector3f(3.0f * std::cos(a), 3.0f * std::sin(a), 0.5f);
    cloud->push_back(p);
  }
  CloudPreprocessing pre;
  pre.setInputCloud(cloud);
  pre.setWorkingSize(100000); // no resampling: every point is a working point unless set aside
  pcl::PointCloud<pcl::PointNormal> working;
  ASSERT_TRUE(pre.compute(working));
  const std::vector<int>& kept = pre.getWorkingIndices();
  std::size_t sparse = 0, sparse_kept = 0;
  for (std::size_t i = 0; i < surface; ++i)
    sparse += (*cloud)[i].z >= 0.0f;
  for (int i : kept) {
    EXPECT_LT(i, int(surface)) << "flying point kept";
    sparse_kept += i < int(surface) && (*cloud)[i].z >= 0.0f;
  }
  // The sparse half stays; only a few points on its border with the dense half, whose nearest
  // neighbours are dense, look isolated (3 of 402 here).
  EXPECT_GE(sparse_kept, sparse - sparse / 50) << sparse_kept << " of " << sparse;
  EXPECT_GE(kept.size(), surface - sparse / 50);
  // The flying points still get a stand-in (the nearest working point) for their label.
  for (std::size_t i = surface; i < cloud->size(); ++i)
    EXPECT_GE(pre.getInputToWorking()[i], 0) << i;
}

namespace {

/// Largest angle (degrees) between a working normal and the line from the centre through its
/// point, and how many working normals point away from the centre (a unit sphere's cloud).
std::pair<double, std::size_t>
radialDeviation(const pcl::PointCloud<pcl::PointNormal>& working)
{
  double worst = 0.0;
  std::size_t outward = 0;
  for (const auto& p : working) {
    const Eigen::Vector3d radial = p.getVector3fMap().cast<double>().normalized();
    const Eigen::Vector3d n = p.getNormalVector3fMap().cast<double>();
    worst = std::max(worst, std::acos(std::min(1.0, std::abs(n.dot(radial)))) * 180.0 / M_PI);
    outward += n.dot(radial) > 0.0;
  }
  return {worst, outward};
}

/// \a pre run on \a cloud into \a working, with the cloud's normals or without.
void
preprocess(CloudPreprocessing& pre, const pcl::PointCloud<pcl::PointNormal>::Ptr& cloud,
           bool use_normals, pcl::PointCloud<pcl::PointNormal>& working)
{
  pre.setInputCloud(cloud);
  pre.setUseInputNormalsFlag(use_normals);
  ASSERT_TRUE(pre.compute(working));
}

} // namespace

// A clean cloud keeps the normals it came with, and its noise is still measured and reported:
// a unit sphere whose given normals lean 40° off the radius keeps them as given.
TEST(CloudPreprocessing, CleanCloudKeepsItsInputNormalsAndIsMeasured)
{
  auto cloud = sphereCloud(20000, 5).toPointNormal();
  for (auto& p : *cloud) {
    const Eigen::Vector3f radial = p.getVector3fMap().normalized();
    const float lean = 40.0f * float(M_PI) / 180.0f;
    p.getNormalVector3fMap() = std::cos(lean) * radial + std::sin(lean) * radial.unitOrthogonal();
  }
  CloudPreprocessing pre;
  pcl::PointCloud<pcl::PointNormal> working;
  preprocess(pre, cloud, true, working);
  EXPECT_FALSE(pre.getNormalsEstimated());
  EXPECT_EQ(pre.getSmoothingPassesApplied(), 0);
  // Clean samples sit off the plane of their 8 nearest neighbours by a few percent of the
  // spacing (the sphere's curvature): measured, below the 10 % that makes a cloud noisy.
  EXPECT_GT(pre.getEstimatedNoise(), 0.0);
  EXPECT_LT(pre.getEstimatedNoise(), 0.1 * pre.getEstimatedSpacing());
  const auto [worst, outward] = radialDeviation(working);
  EXPECT_NEAR(worst, 40.0, 0.01);
  EXPECT_EQ(outward, working.size());
}

// A noisy cloud's normals are set aside: smoothing carries points across thin walls, where
// their own normals point the wrong way. All given normals reversed, the noisy sphere still
// comes out with outward normals, oriented as for a cloud without normals.
TEST(CloudPreprocessing, NoisyCloudSetsItsInputNormalsAside)
{
  SampledCloud sphere = sphereCloud(20000, 6);
  addGaussianNoise(sphere, 0.005, 3);
  auto cloud = sphere.toPointNormal();
  for (auto& p : *cloud)
    p.getNormalVector3fMap() *= -1.0f;
  CloudPreprocessing pre, without;
  pcl::PointCloud<pcl::PointNormal> working, same;
  preprocess(pre, cloud, true, working);
  EXPECT_TRUE(pre.getNormalsEstimated());
  EXPECT_GE(pre.getSmoothingPassesApplied(), 1);
  EXPECT_EQ(radialDeviation(working).second, working.size());

  preprocess(without, cloud, false, same);
  ASSERT_EQ(same.size(), working.size());
  for (std::size_t i = 0; i < same.size(); ++i) {
    EXPECT_EQ(same[i].getVector3fMap(), working[i].getVector3fMap());
    EXPECT_EQ(same[i].getNormalVector3fMap(), working[i].getNormalVector3fMap());
  }
}
