/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Teddy (PSB 180) from the mesh alone, with Gaussian vertex noise of σ = 0, 0.2, 0.5 and 1 % of
 * its bounding-box diagonal (the SEG-MAT paper's robustness test): the parts stay those people
 * draw (scored against the 13 human segmentations), the noise is found and removed, and the
 * labels are golden (part count and checksum per level).
 */
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include "util/cloud_sampler.h"
#include "util/flat_join_scoring.h"
#include "util/label_hash.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using namespace segmat;

const std::string kTeddy = std::string(SEGMAT_DATA_DIR) + "/teddy/";

struct Level
{
  double percent;   ///< σ in % of the diagonal
  int parts;        ///< golden part count
  std::uint64_t hash; ///< golden label checksum
};

class NoisyTeddy : public ::testing::TestWithParam<Level>
{};

TEST_P(NoisyTeddy, KeepsItsPartsAndFindsTheNoise)
{
  const Level level = GetParam();
  const TriangleMesh clean = io::loadOff(kTeddy + "teddy.off");
  auto mesh = std::make_shared<TriangleMesh>(clean);
  if (level.percent > 0.0)
    // The seed bench_noise gives this shape and level (model id · 1000 + σ in 1/10000).
    test::addGaussianNoise(*mesh, level.percent / 100.0,
                           180u * 1000u + std::uint32_t(level.percent * 10000.0));
  MeshSegmentation seg;
  seg.setInputMesh(mesh);
  seg.setNumberOfThreads(1);
  std::vector<int> labels;
  ASSERT_TRUE(seg.segment(labels));
  ASSERT_EQ(labels.size(), clean.numFaces());

  // Found noisy exactly when noise was added; the estimate is σ along the normal, which for
  // isotropic noise of σ per coordinate is σ (within a third: teddy's curvature and the
  // estimate's spread).
  const double sigma = level.percent / 100.0 * clean.boundingBoxDiagonal();
  if (level.percent == 0.0) {
    EXPECT_EQ(seg.getDenoisingPasses(), 0);
  }
  else {
    EXPECT_GE(seg.getDenoisingPasses(), 1);
    EXPECT_NEAR(seg.getEstimatedNoise(), sigma, sigma / 3.0);
  }

  // Against the humans, on the clean mesh: people agree among themselves at ~0.10 on PSB; the
  // clean teddy scores ~0.05 and noise may not cost more than 0.04.
  std::vector<std::vector<int>> humans;
  for (int k = 0; k < 13; ++k)
    humans.push_back(io::loadSeg(kTeddy + "seg/180_" + std::to_string(k) + ".seg", 19092));
  PsbEvaluator evaluator;
  ASSERT_TRUE(evaluator.setInputMesh(clean));
  PsbScores mean;
  ASSERT_TRUE(evaluator.scoreAgainstAll(labels, humans, mean));
  EXPECT_LT(mean.RI, 0.09) << "sigma " << level.percent << " %";

  const int parts = int(std::set<int>(labels.begin(), labels.end()).size());
  EXPECT_EQ(parts, level.parts) << "sigma " << level.percent << " %";
  EXPECT_EQ(test::labelHash(labels), level.hash) << "sigma " << level.percent << " %";
}

// The structured MAT describes the shape, so noise may not grow it (nor shrink it by much). Its automatic size is 0.1 %
// of the initial spheres, and vertex noise along the surface stretches edges that the surface
// sampler then fills: without the tangential relaxation PSB 61 (an airplane; clean: 17
// structured spheres) gets 32 at σ = 0.5 % and 31 at 1 %. Noise as bench_noise draws it.
TEST(NoisyMesh, NoiseDoesNotGrowTheStructuredMat)
{
  const std::string path = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev/off/61.off";
  const TriangleMesh clean = io::loadOff(path);
  auto structuredSpheres = [&](double percent) {
    auto mesh = std::make_shared<TriangleMesh>(clean);
    if (percent > 0.0)
      test::addGaussianNoise(*mesh, percent / 100.0,
                             61u * 1000u + std::uint32_t(percent * 10000.0 + 0.5));
    MeshSegmentation seg;
    seg.setInputMesh(mesh);
    seg.setNumberOfThreads(1);
    std::vector<int> labels;
    EXPECT_TRUE(seg.segment(labels));
    return seg.getStructuredMat() ? int(seg.getStructuredMat()->numVertices()) : -1;
  };
  const int reference = structuredSpheres(0.0);
  EXPECT_EQ(reference, 17);
  for (const double percent : {0.5, 1.0}) {
    const int spheres = structuredSpheres(percent);
    EXPECT_NEAR(spheres, reference, 3) << "sigma " << percent << " %";
  }
}

// The legs of an ant (PSB 86) are tubes a few noise σ thick. Denoised, their radius still
// wobbles by the noise that remains, and without a tolerance every wobble above δ0 of the radius
// starts a new region: at σ = 1 % the ant had 19 parts against 12 clean, its legs cut in two or
// three. With radius differences up to the remaining noise not counted it keeps the clean part
// count within two. The remaining noise is reported, and is a small part of the input's.
TEST(NoisyMesh, ThinLegsStayWholeUnderNoise)
{
  const std::string path = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev/off/86.off";
  const TriangleMesh clean = io::loadOff(path);
  auto segment = [&](double percent, MeshSegmentation& seg) {
    auto mesh = std::make_shared<TriangleMesh>(clean);
    if (percent > 0.0)
      test::addGaussianNoise(*mesh, percent / 100.0,
                             86u * 1000u + std::uint32_t(percent * 10000.0 + 0.5));
    seg.setInputMesh(mesh);
    seg.setNumberOfThreads(1);
    std::vector<int> labels;
    EXPECT_TRUE(seg.segment(labels));
    return int(std::set<int>(labels.begin(), labels.end()).size());
  };
  MeshSegmentation clean_seg, noisy_seg;
  const int clean_parts = segment(0.0, clean_seg);
  EXPECT_EQ(clean_seg.getRemainingNoise(), 0.0);
  const int noisy_parts = segment(1.0, noisy_seg);
  EXPECT_EQ(clean_parts, 12);
  EXPECT_LE(noisy_parts, clean_parts + 2);
  EXPECT_GT(noisy_seg.getRemainingNoise(), 0.0);
  EXPECT_LT(noisy_seg.getRemainingNoise(), 0.2 * noisy_seg.getEstimatedNoise());
}

// PSB Mech 326, a box on a cylinder, with noise of σ = 0.5 % of the diagonal (bench_noise's
// first draw): the cut splits the cylinder around its side. Edge by edge, such a boundary
// curves as the cylinder does around it; between the mean normals of its two sides it is flat
// along the axis, and the parts become one. Without the rule: five parts, 1 − RI 0.23 against
// the first four humans; with it the box and the cylinder, 0.10 (the edge-by-edge measure
// leaves three parts here).
TEST(NoisyMesh, CylinderCutAroundItsSideIsJoined)
{
  const std::string dir = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev/";
  auto mesh = std::make_shared<TriangleMesh>(io::loadOff(dir + "off/326.off"));
  const auto humans = test::loadHumans(dir + "seg/Benchmark/326/326_", 4, mesh->numFaces());
  PsbEvaluator evaluator;
  ASSERT_TRUE(evaluator.setInputMesh(*mesh));
  test::addGaussianNoise(*mesh, 0.005, 326u * 1000u + 50u);
  double apart = 0.0, joined = 0.0;
  EXPECT_EQ(test::segmentWithFlatJoin(mesh, evaluator, humans, false, 0, apart), 5u);
  EXPECT_EQ(test::segmentWithFlatJoin(mesh, evaluator, humans, true, 0, joined), 2u);
  EXPECT_GT(apart, 0.2);
  EXPECT_LT(joined, 0.12);
}

// Noise leaves slivers: parts that win a handful of faces. A part below the minimal share is
// dropped and only its own faces are cut again, so every face of a kept part keeps that part.
// PSB 286 (an armadillo, 50 212 faces) at σ = 1 % of the diagonal, bench_noise's first draw: the cut
// leaves four parts below 0.2 % of the surface. Cut again as a whole, the surface also moves
// some faces of kept parts to other kept parts.
TEST(NoisyMesh, DroppedSliversGiveAwayOnlyTheirOwnFaces)
{
  const std::string path = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev/off/286.off";
  auto mesh = std::make_shared<TriangleMesh>(io::loadOff(path));
  test::addGaussianNoise(*mesh, 0.01, 286u * 1000u + 10000u);
  MeshSegmentation seg;
  seg.setInputMesh(mesh);
  seg.setNumberOfThreads(1);
  seg.setJoinFlatBoundaries(false); // parts as the cut leaves them
  seg.setMinPartFraction(0.0);
  std::vector<int> all, kept;
  ASSERT_TRUE(seg.segment(all));
  const auto all_parts = seg.getMatParts();
  seg.setMinPartFraction(0.002); // the default; the medial stages are reused
  ASSERT_TRUE(seg.segment(kept));
  const auto kept_parts = seg.getMatParts();
  ASSERT_EQ(all.size(), kept.size());
  // A part is the same part when it holds the same MAT nodes.
  auto nodes = [](const std::vector<pcl::PointIndices>& parts) {
    std::vector<std::set<int>> sets;
    for (const pcl::PointIndices& part : parts)
      sets.emplace_back(part.indices.begin(), part.indices.end());
    return sets;
  };
  const auto all_nodes = nodes(all_parts), kept_nodes = nodes(kept_parts);
  std::vector<int> same(all_parts.size(), -1); // label in `all` → its label in `kept`
  for (std::size_t a = 0; a < all_nodes.size(); ++a)
    for (std::size_t k = 0; k < kept_nodes.size(); ++k)
      if (all_nodes[a] == kept_nodes[k])
        same[a] = int(k);
  const int dropped = int(std::count(same.begin(), same.end(), -1));
  EXPECT_EQ(dropped, 4);
  EXPECT_EQ(all_parts.size(), kept_parts.size() + std::size_t(dropped));
  std::size_t moved = 0, relabelled = 0;
  for (std::size_t f = 0; f < all.size(); ++f) {
    if (same[all[f]] < 0)
      ++relabelled;
    else if (kept[f] != same[all[f]])
      ++moved;
  }
  EXPECT_GT(relabelled, 0u);
  EXPECT_EQ(moved, 0u) << "faces of kept parts that changed part";
}

// Golden values: update only with a deliberate change of the algorithm, saying why.
INSTANTIATE_TEST_SUITE_P(Levels, NoisyTeddy,
                         ::testing::Values(Level{0.0, 8, 810418089236768783ull},
                                           Level{0.2, 8, 1387668962000827905ull},
                                           Level{0.5, 8, 6604146909086544458ull},
                                           Level{1.0, 8, 5997229730377992350ull}),
                         [](const ::testing::TestParamInfo<Level>& info) {
                           return "sigma_" + std::to_string(int(info.param.percent * 10)) +
                                  "_permille";
                         });

} // namespace
