/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * CloudSegmentation on noisy clouds, one segmentation each: bundled PSB models sampled as the
 * benchmarks sample them (20 000 area-uniform points, no normals), clean and with Gaussian
 * noise of 0.2 %, 0.3 %, 0.5 % or 1 % of the diagonal. The noise is found (and only where it
 * was added), the parts stay close to the human segmentations, and the labels are golden (part
 * count and checksum).
 */
#include "util/cloud_sampler.h"
#include "util/label_hash.h"

#include <segmat/io/off.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/cloud_segmentation.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using namespace segmat;

struct NoisyCloudCase
{
  int model;          ///< bundled PSB model (data/psb<N>/)
  double percent;     ///< noise σ in % of the diagonal (0: clean)
  double max_error;   ///< bound on 1 − RI, mean over the first four humans
  int parts;          ///< golden part count
  std::uint64_t hash; ///< golden label checksum
};

class NoisyPsbCloud : public ::testing::TestWithParam<NoisyCloudCase>
{};

/// Bundled PSB model \a model sampled as the benchmarks sample it, with noise of \a percent of
/// the diagonal; the first four humans' labels of its points and its diagonal.
test::SampledCloud
noisyPsbCloud(int model, double percent, std::vector<std::vector<int>>& truths, double& diagonal)
{
  // The teddy is PSB model 180, bundled under its name.
  const std::string id = std::to_string(model), name = model == 180 ? "teddy" : "psb" + id;
  const std::string dir = std::string(SEGMAT_DATA_DIR) + "/" + name + "/";
  const TriangleMesh mesh = io::loadOff(dir + (model == 180 ? name : id) + ".off");
  test::SampledCloud cloud = test::sampleMesh(mesh, 20000, 1);
  truths.clear();
  for (int k = 0; k < 4; ++k)
    truths.push_back(cloud.pointLabels(
        io::loadSeg(dir + "seg/" + id + "_" + std::to_string(k) + ".seg", long(mesh.numFaces()))));
  Eigen::Vector3f lo = cloud.points.front(), hi = lo;
  for (const Eigen::Vector3f& p : cloud.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  diagonal = (hi - lo).cast<double>().norm(); // addGaussianNoise's
  if (percent > 0.0)
    test::addGaussianNoise(cloud, percent / 100.0, 2);
  return cloud;
}

TEST_P(NoisyPsbCloud, KeepsItsPartsAndFindsTheNoise)
{
  const NoisyCloudCase c = GetParam();
  std::vector<std::vector<int>> truths;
  double diagonal = 0.0;
  const test::SampledCloud cloud = noisyPsbCloud(c.model, c.percent, truths, diagonal);

  CloudSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud.toCloud<pcl::PointXYZ>());
  seg.setNumberOfThreads(1);
  std::vector<pcl::PointIndices> parts;
  ASSERT_TRUE(seg.segment(parts));
  const std::vector<int>& labels = seg.getLabels();
  ASSERT_EQ(labels.size(), cloud.size());

  // Smoothed exactly when noise was added. The estimate measures offsets from the plane of 8
  // close noisy neighbours, which absorbs part of the noise: for isotropic noise of σ per
  // coordinate it lands between a quarter of σ and σ.
  const double sigma = c.percent / 100.0 * diagonal;
  EXPECT_GT(seg.getEstimatedSpacing(), 0.0);
  // What smoothing leaves is measured again (the grower's radius tolerance): nothing on a clean
  // cloud, a small fraction of the input's estimate on a smoothed one.
  if (c.percent == 0.0) {
    EXPECT_EQ(seg.getDenoisingPasses(), 0);
    EXPECT_EQ(seg.getRemainingNoise(), 0.0);
  }
  else {
    EXPECT_GE(seg.getDenoisingPasses(), 1);
    EXPECT_GT(seg.getEstimatedNoise(), sigma / 4.0);
    EXPECT_LT(seg.getEstimatedNoise(), sigma);
    EXPECT_GT(seg.getRemainingNoise(), 0.0);
    EXPECT_LT(seg.getRemainingNoise(), 0.2 * seg.getEstimatedNoise());
  }

  // People agree among themselves at ~0.10 of 1 − RI on PSB.
  double error = 0.0;
  for (const auto& truth : truths)
    error += test::randIndexError(labels, truth) / double(truths.size());
  EXPECT_LT(error, c.max_error);

  EXPECT_EQ(int(parts.size()), c.parts);
  EXPECT_EQ(test::labelHash(labels), c.hash);
}

// Golden values: update only with a deliberate change of the algorithm, saying why.
// Chair 101: its seat and back are plates 3–4 σ thick at 0.5 %; the orientation flips patches
// of their normals and the base MAT falls apart, so this case also passes through the retry
// with mirror-related normals. It is a weak case: in about a third of the noise draws seat and
// back still grow into one part (1 − RI near 0.4; bench_noise --kind cloud --models 101
// --levels 0.5 with --seed-offset 0..5), and this draw is one of them. Glasses 41: two thin lens
// plates joined at the bridge. Box 321, a box with a smaller box on top: the medial axis splits
// the box where its thickness changes, and the cut runs across flat faces; measured between
// the mean normals of their two sides, those boundaries are flat and the parts are joined
// (compared pair by pair, the noise in the normals makes them curve 3–4 times the limit, and
// this draw keeps 3 parts). Bearing 346: its
// two shaft cylinders differ by 15 % in radius, and the spikes of the noisy surface fill both
// cylinders' radius histograms with every radius up to theirs. Counted, they bring the two
// histograms within the merging's EMD limit and the shaft becomes one part in this draw;
// merging by the spheres that span a right angle keeps the 3 parts that people see
// (docs/noise.md, "Spikes in the merging"). Cup 26: a wall a few σ thick, whose medial sheet
// the inside test riddles with holes; with them left open this draw gives 12 parts and
// 1 − RI 0.69, with the holes that the rim balls cover closed it keeps body and handle.
// Teddy 180, at every noise level of bench_noise: head, ears, arms, legs and body, 8 parts at
// each level; at 1 % the noise is about the spacing of the 20 000 points, and the estimate
// (0.27 σ) is near the low end of its range.
INSTANTIATE_TEST_SUITE_P(
    Models, NoisyPsbCloud,
    ::testing::Values(NoisyCloudCase{101, 0.0, 0.06, 12, 11170626562616678947ull},
                      NoisyCloudCase{101, 0.5, 0.45, 9, 15228794444371619633ull},
                      NoisyCloudCase{346, 0.0, 0.05, 3, 2476743862870366952ull},
                      NoisyCloudCase{346, 0.5, 0.05, 3, 17811072805317492061ull},
                      NoisyCloudCase{41, 0.5, 0.15, 8, 9745792933633437430ull},
                      NoisyCloudCase{321, 0.5, 0.05, 2, 10989437029408341162ull},
                      NoisyCloudCase{26, 0.3, 0.05, 2, 18237015744876667302ull},
                      NoisyCloudCase{180, 0.0, 0.05, 8, 833405476462752281ull},
                      NoisyCloudCase{180, 0.2, 0.05, 8, 6361257017690697430ull},
                      NoisyCloudCase{180, 0.5, 0.05, 8, 8161058027501342049ull},
                      NoisyCloudCase{180, 1.0, 0.08, 8, 9154322711957936923ull}),
    [](const ::testing::TestParamInfo<NoisyCloudCase>& info) {
      return "psb" + std::to_string(info.param.model) + "_sigma_" +
             std::to_string(int(info.param.percent * 10)) + "_permille";
    });

} // namespace

// The noise figures are lengths in the input's units: a noisy cloud scaled by 8 (a power of two,
// so the working frame and every label stay exactly the same) reports each of them 8 times
// larger, the noise left after smoothing included.
TEST(NoisyCloudNoise, FiguresScaleWithTheInput)
{
  const std::string dir = std::string(SEGMAT_DATA_DIR) + "/psb41/";
  test::SampledCloud cloud = test::sampleMesh(io::loadOff(dir + "41.off"), 20000, 1);
  test::addGaussianNoise(cloud, 0.005, 2);
  test::SampledCloud scaled = cloud;
  for (Eigen::Vector3f& p : scaled.points)
    p *= 8.0f;
  CloudSegmentation<pcl::PointXYZ> a, b;
  std::vector<pcl::PointIndices> parts;
  for (auto [seg, input] : {std::make_pair(&a, &cloud), std::make_pair(&b, &scaled)}) {
    seg->setInputCloud(input->toCloud<pcl::PointXYZ>());
    seg->setNumberOfThreads(1);
    ASSERT_TRUE(seg->segment(parts));
  }
  EXPECT_EQ(a.getLabels(), b.getLabels());
  ASSERT_GT(a.getRemainingNoise(), 0.0);
  EXPECT_DOUBLE_EQ(b.getEstimatedNoise(), 8.0 * a.getEstimatedNoise());
  EXPECT_DOUBLE_EQ(b.getEstimatedSpacing(), 8.0 * a.getEstimatedSpacing());
  EXPECT_DOUBLE_EQ(b.getRemainingNoise(), 8.0 * a.getRemainingNoise());
}

// A noisy cloud's own normals are set aside (docs/noise.md, "Clouds with normals"): the cup 26
// at 0.3 % with the exact normals of its faces gets the labels of the same points without
// normals. Used as given, those normals left the cloud unsmoothed.
TEST(NoisyPsbCloudWithNormals, GetsTheLabelsOfTheSamePointsWithoutNormals)
{
  std::vector<std::vector<int>> truths;
  double diagonal = 0.0;
  const test::SampledCloud cloud = noisyPsbCloud(26, 0.3, truths, diagonal);
  std::vector<int> labels[2];
  for (const bool normals : {false, true}) {
    CloudSegmentation<pcl::PointNormal> seg;
    seg.setInputCloud(cloud.toPointNormal());
    seg.setUseInputNormalsFlag(normals);
    seg.setNumberOfThreads(1);
    std::vector<pcl::PointIndices> parts;
    ASSERT_TRUE(seg.segment(parts));
    EXPECT_EQ(parts.size(), 2u);
    EXPECT_GE(seg.getDenoisingPasses(), 1);
    labels[normals] = seg.getLabels();
  }
  EXPECT_EQ(labels[0], labels[1]);
}
