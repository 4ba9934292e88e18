// Detail levels and nested hierarchies: parsing, nesting by construction, and a real shape.
#include <segmat/common/error.h>
#include <segmat/io/ma.h>
#include <segmat/io/off.h>
#include <segmat/segmentation/detail_level.h>
#include <segmat/segmentation/mesh_segmentation.h>
#include <segmat/segmentation/segmentation_hierarchy.h>

#include <util/synthetic_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace segmat;

namespace {
/// One label per face of \a mesh: the number of \a cuts below the face centroid's x.
std::vector<int>
slabs(const TriangleMesh& mesh, const std::vector<double>& cuts)
{
  std::vector<int> labels;
  for (std::size_t f = 0; f < mesh.numFaces(); ++f) {
    const double x = mesh.faceCentroid(static_cast<int>(f)).x();
    int l = 0;
    for (const double c : cuts)
      l += x > c;
    labels.push_back(l);
  }
  return labels;
}

void
expectNested(const std::vector<int>& coarse, const std::vector<int>& nested,
             const std::vector<int>& parents)
{
  ASSERT_EQ(coarse.size(), nested.size());
  for (std::size_t f = 0; f < nested.size(); ++f) {
    ASSERT_GE(nested[f], 0);
    ASSERT_LT(nested[f], static_cast<int>(parents.size()));
    ASSERT_EQ(parents[nested[f]], coarse[f]) << "face " << f;
  }
}
} // namespace

TEST(DetailLevel, NamesNumbersAndErrors)
{
  const DetailLevel d = parseDetailLevel("default");
  EXPECT_EQ(d.growing_threshold, 0.015);
  EXPECT_EQ(d.min_region_fraction, 0.002);
  const DetailLevel coarse = parseDetailLevel("coarse"), fine = parseDetailLevel("fine");
  EXPECT_GT(coarse.growing_threshold, d.growing_threshold);
  EXPECT_LT(fine.growing_threshold, d.growing_threshold);
  EXPECT_EQ(parseDetailLevel("0").growing_threshold, d.growing_threshold);
  EXPECT_NEAR(parseDetailLevel("1").growing_threshold, fine.growing_threshold, 1e-15);
  // Halfway to coarse: the geometric mean.
  EXPECT_NEAR(parseDetailLevel("-0.5").growing_threshold,
              std::sqrt(coarse.growing_threshold * d.growing_threshold), 1e-15);
  for (const char* bad : {"", "medium", "1.5", "-2", "nan", "0x"})
    EXPECT_THROW(parseDetailLevel(bad), Error) << bad;
}

TEST(SegmentationHierarchy, FinerCutsSplitAndSliversMergeInsideTheirParent)
{
  // Unit cube; coarse cut at x = 0.5, fine cuts at x = 0.3 and 0.7 (not at 0.5): the pieces are
  // [0, .3), [.3, .5), [.5, .7), [.7, 1], each a ring or an end cap.
  const TriangleMesh cube = test::box({0, 0, 0}, {1, 1, 1}, 10);
  const std::vector<int> coarse = slabs(cube, {0.5});
  const std::vector<int> fine = slabs(cube, {0.3, 0.7});
  std::vector<int> nested, parents;
  nestSegmentation(cube, coarse, fine, 0.0, nested, parents);
  expectNested(coarse, nested, parents);
  EXPECT_EQ(std::multiset<int>(parents.begin(), parents.end()), (std::multiset<int>{0, 0, 1, 1}));

  // The rings [.3, .5) and [.5, .7) hold 4 × 0.2 / 6 = 13.3 % of the area each: below 15 %,
  // each joins the piece of its own half it borders (not the other ring across x = 0.5).
  nestSegmentation(cube, coarse, fine, 0.15, nested, parents);
  expectNested(coarse, nested, parents);
  ASSERT_EQ(parents.size(), 2u);
  for (std::size_t f = 0; f < nested.size(); ++f) // one piece per half: the coarse parts again
    ASSERT_EQ(parents[nested[f]], coarse[f]);

  EXPECT_THROW(nestSegmentation(cube, coarse, {0, 1}, 0.0, nested, parents), Error);
}

TEST(SegmentationHierarchy, TeddyLevelsNestAndGetFiner)
{
  const std::string dir = std::string(SEGMAT_DATA_DIR) + "/teddy/";
  MeshSegmentation seg;
  seg.setInputMesh(std::make_shared<TriangleMesh>(io::loadOff(dir + "teddy.off")));
  seg.setBaseMat(std::make_shared<MedialMesh>(io::loadMa(dir + "teddy_mat.ma")));
  seg.setStructuredMat(std::make_shared<MedialMesh>(io::loadMa(dir + "teddy_smat.ma")));
  std::vector<HierarchyLevel> levels;
  ASSERT_TRUE(segmentHierarchy(seg, detailLevels(), levels));
  ASSERT_EQ(levels.size(), 3u);
  for (const int p : levels[0].parents)
    EXPECT_EQ(p, -1);
  for (std::size_t k = 1; k < levels.size(); ++k) {
    expectNested(levels[k - 1].labels, levels[k].labels, levels[k].parents);
    EXPECT_GE(levels[k].parents.size(), levels[k - 1].parents.size());
  }
  EXPECT_LT(levels.front().parents.size(), levels.back().parents.size());
  // The medial meshes were given, so no level computed any; the later levels reused the graph.
  for (const auto& stage : seg.getStageSeconds())
    if (stage.name == "mat" || stage.name == "graph" || stage.name == "tags")
      EXPECT_EQ(stage.seconds, 0.0) << stage.name;
}
