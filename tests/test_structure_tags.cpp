// Thin-part detection on a structured MAT and transfer to base nodes (SEG-MAT §4.2).
#include <segmat/geometry/medial_mesh.h>
#include <segmat/io/ma.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/structure_tags.h>

#include <gtest/gtest.h>
#include <pcl/console/print.h>

#include <cmath>
#include <string>

using namespace segmat;

namespace {

/** Structured MAT: a fat square sheet on x ∈ [−2, 0], y ∈ [−1, 1] (two triangles, radius 1) and a
 * thin line of 4 pure edges from (0,0,0) to (8,0,0) (radius 0.5 unless given), touching the
 * sheet at sphere 0.
 *  - sheet: A = 4, r_max = 1 → ρ = √4 / 1 = 2 ≤ 8 → normal (tag 0);
 *  - line: L = 8, r_max = 0.5 → ρ = 16 > 8 → thin part 0, tag 1, tag_ratio = log2 16 = 4.
 * A line never joins a sheet, so sphere 0 (shared) does not merge them.
 */
MedialMesh
sheetAndLine(double line_radius = 0.5)
{
  std::vector<Eigen::Vector3d> c{{0, -1, 0}, {-2, -1, 0}, {-2, 1, 0}, {0, 1, 0}, {0, 0, 0},
                                 {2, 0, 0},  {4, 0, 0},   {6, 0, 0},  {8, 0, 0}};
  std::vector<double> r{1, 1, 1, 1};
  r.resize(9, line_radius);
  // The line starts at (0,0,0), on the sheet's edge x = 0 but not at a sheet vertex.
  return MedialMesh(c, r, {{4, 5}, {5, 6}, {6, 7}, {7, 8}}, {{0, 1, 2}, {0, 2, 3}});
}

/** Base graph whose node centroids are chosen by hand: one pure edge per probe point. */
MatGraph
probes(const std::vector<Eigen::Vector3d>& at)
{
  std::vector<Eigen::Vector3d> c;
  std::vector<double> r;
  std::vector<Eigen::Vector2i> e;
  for (const Eigen::Vector3d& p : at) {
    c.push_back(p - Eigen::Vector3d(0, 0, 0.01));
    c.push_back(p + Eigen::Vector3d(0, 0, 0.01));
    r.push_back(0.1);
    r.push_back(0.1);
    e.emplace_back(static_cast<int>(c.size()) - 2, static_cast<int>(c.size()) - 1);
  }
  return MatGraph::fromMedialMesh(MedialMesh(c, r, e, {}));
}

} // namespace

TEST(StructureTags, ThinLineAndFatSheet)
{
  const MatGraph base = probes({{5.0, 0.3, 0}, {-1, 0, 0.2}, {0.3, 0.0, 0}, {-0.2, 0.0, 0}});
  const StructureTags tags = computeStructureTags(sheetAndLine(), base);
  ASSERT_EQ(tags.numThinParts(), 1);
  EXPECT_EQ(tags.tag_ratio[0], 0.0);
  EXPECT_DOUBLE_EQ(tags.tag_ratio[1], 4.0);
  ASSERT_EQ(tags.node_tag.size(), 4u);
  EXPECT_EQ(tags.node_tag[0], 1); // beside the line
  EXPECT_EQ(tags.node_tag[1], 0); // inside the sheet
  // (0.3, 0, 0): the nearest densified line point is (2·2/13, 0, 0) = (0.3077, 0, 0), 0.008 away;
  // the sheet's nearest sample (0, 1/13, 0) is 0.31 away. (−0.2, 0, 0): the sheet's sample
  // (−2/13, 1/13, 0) is 0.09 away, nearer than the line's start (0, 0, 0) at 0.2.
  EXPECT_EQ(tags.node_tag[2], 1);
  EXPECT_EQ(tags.node_tag[3], 0);
}

TEST(StructureTags, BranchPointCutsUnlessCollinear)
{
  // A cross of lines through sphere 0 (4 spheres share it): x-arms collinear (|cos| = 1 > 0.95)
  // join into one line of length 10 (ρ = 10/0.5 = 20, thin, log2 20); the y-arms are collinear
  // too (length 2, ρ = 4: normal). So one thin part.
  std::vector<Eigen::Vector3d> c{{0, 0, 0}, {-5, 0, 0}, {5, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  const MedialMesh s(c, {0.5, 0.5, 0.5, 0.5, 0.5}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}, {});
  const MatGraph base = probes({{-4, 0.1, 0}, {4, 0.1, 0}, {0.1, 0.9, 0}});
  const StructureTags tags = computeStructureTags(s, base);
  ASSERT_EQ(tags.numThinParts(), 1);
  EXPECT_DOUBLE_EQ(tags.tag_ratio[1], std::log2(20.0));
  EXPECT_EQ(tags.node_tag, (std::vector<int>{1, 1, 0}));
  // Bend the +x arm by 90° (to +z): no longer collinear, so the three remaining pieces are cut
  // apart: −x arm alone has ρ = 5/0.5 = 10 > 8 (thin), +z arm 10 (thin), y-line ρ = 4 (normal).
  c[2] = Eigen::Vector3d(0, 0, 5);
  const MedialMesh bent(c, {0.5, 0.5, 0.5, 0.5, 0.5}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}, {});
  const StructureTags t2 = computeStructureTags(bent, probes({{-4, 0.1, 0}, {0.1, 0, 4}}));
  ASSERT_EQ(t2.numThinParts(), 2);
  EXPECT_EQ(t2.node_tag, (std::vector<int>{1, 2}));
}

TEST(StructureTags, BulkyLinesCarryTheirDirection)
{
  // An L of two pure edges through a simple joint (sphere 1 shared by 2 nodes): one line,
  // L = 4, r = 0.5, ρ = 8 — not > 8, so bulky. Its nodes carry the direction of their segment
  // (c[v1] − c[v0], normalised); a thin line or a sheet carries none.
  const MedialMesh l_shape({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}}, {0.5, 0.5, 0.5}, {{0, 1}, {1, 2}},
                           {});
  const StructureTags tags = computeStructureTags(l_shape, probes({{1, 0.1, 0}, {2.1, 1.5, 0}}));
  ASSERT_EQ(tags.numThinParts(), 0);
  ASSERT_EQ(tags.node_axis.size(), 2u);
  EXPECT_TRUE(tags.node_axis[0].isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(tags.node_axis[1].isApprox(Eigen::Vector3d(0, 1, 0)));
  // sheetAndLine(): the line is thin (tag 1), the sheet is a sheet: no direction anywhere.
  const StructureTags t2 =
      computeStructureTags(sheetAndLine(), probes({{5.0, 0.3, 0}, {-1, 0, 0.2}}));
  ASSERT_EQ(t2.node_axis.size(), 2u);
  EXPECT_TRUE(t2.node_axis[0].isZero());
  EXPECT_TRUE(t2.node_axis[1].isZero());
  EXPECT_TRUE(computeStructureTags(MedialMesh(), probes({{0, 0, 0}})).node_axis.empty());
}

TEST(StructureTags, VeryLongLinesAreDropped)
{
  // A single line with ρ = 60/0.5 = 120 > 100 takes no part; the sheet is the only component left.
  std::vector<Eigen::Vector3d> c{{0, -1, 0}, {-2, -1, 0}, {-2, 1, 0}, {10, 0, 0}, {70, 0, 0}};
  const MedialMesh s(c, {1, 1, 1, 0.5, 0.5}, {{3, 4}}, {{0, 1, 2}});
  const StructureTags tags = computeStructureTags(s, probes({{40, 0, 0}}));
  EXPECT_EQ(tags.numThinParts(), 0);
  EXPECT_EQ(tags.node_tag, std::vector<int>{0});
}

TEST(StructureTags, NonManifoldSheetIsNeverThin)
{
  // Three triangles on edge (0,1) plus two connectors (0,2,3) and (1,3,4) that chain them into
  // one component across manifold edges. Area is large against r = 0.1, but edge (0,1) is used
  // three times inside the component, so it is normal. Without T3 = (0,1,4) it would be thin.
  std::vector<Eigen::Vector3d> c{{0, 0, 0}, {10, 0, 0}, {5, 10, 0}, {5, 0, 10}, {5, -10, 0}};
  const std::vector<double> r(5, 0.1);
  const MedialMesh nm(c, r, {}, {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 2, 3}, {1, 3, 4}});
  EXPECT_EQ(computeStructureTags(nm, probes({{5, 1, 0}})).numThinParts(), 0);
  const MedialMesh manifold(c, r, {}, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}});
  const StructureTags tags = computeStructureTags(manifold, probes({{5, 1, 0}}));
  EXPECT_EQ(tags.numThinParts(), 1);
  // Its one probe is the whole shape, but ρ = √161.2 / 0.1 = 127 > 10: tagged all the same.
  EXPECT_EQ(tags.node_tag, std::vector<int>{1});
}

TEST(StructureTags, BarelyThinWholeShapeIsUntagged)
{
  // sheetAndLine(r): the line (L = 8) is thin for r < 1. Probes along it take tag 1, a probe in
  // the fat sheet takes 0. With r = 0.9 (ρ = 8.9, barely thin, like a noisy bird's merged
  // body-and-wings sheet at 8.2): 5 line probes of 6 hold 0.83 ≤ 0.85 of the nodes, the tag
  // stays; 9 of 10 hold 0.9 of the shape: untagged. With r = 0.5 (ρ = 16 > 10; the dumbbell's
  // sheet is 13, a cup's wall 24–34) the part keeps its tag however much of the shape it holds.
  std::vector<Eigen::Vector3d> at{{-1, 0, 0.2}};
  for (int k = 1; k <= 5; ++k)
    at.emplace_back(1.0 * k + 0.5, 0.1, 0.0);
  const StructureTags kept = computeStructureTags(sheetAndLine(0.9), probes(at));
  EXPECT_DOUBLE_EQ(kept.tag_ratio[1], std::log2(8.0 / 0.9));
  EXPECT_EQ(kept.node_tag, (std::vector<int>{0, 1, 1, 1, 1, 1}));
  for (int k = 6; k <= 9; ++k)
    at.emplace_back(0.7 * k - 2.0, -0.1, 0.0);
  const StructureTags untagged = computeStructureTags(sheetAndLine(0.9), probes(at));
  EXPECT_EQ(untagged.numThinParts(), 1);
  EXPECT_EQ(untagged.node_tag, std::vector<int>(10, 0));
  const StructureTags slender = computeStructureTags(sheetAndLine(), probes(at));
  EXPECT_DOUBLE_EQ(slender.tag_ratio[1], 4.0);
  EXPECT_EQ(slender.node_tag, (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1, 1, 1}));
}

TEST(StructureTags, EmptyStructuredMatTagsEverythingBulky)
{
  const MatGraph base = probes({{0, 0, 0}, {1, 1, 1}});
  const StructureTags tags = computeStructureTags(MedialMesh(), base);
  EXPECT_EQ(tags.numThinParts(), 0);
  EXPECT_EQ(tags.node_tag, (std::vector<int>{0, 0}));
  EXPECT_EQ(computeStructureTags(sheetAndLine(), MatGraph()).node_tag.size(), 0u);
}

TEST(StructureTags, TeddyHasNoThinPart)
{
  // The authors' program on teddy: teddy's structured MAT (4 triangles + 9 pure edges) has
  // 8 normal components and no thin part, so every base tag is 0.
  const std::string dir = std::string(SEGMAT_DATA_DIR) + "/teddy/";
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR); // the smat's header is wrong
  const MedialMesh smat = io::loadMa(dir + "teddy_smat.ma");
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
  const MatGraph base = MatGraph::fromMedialMesh(io::loadMa(dir + "teddy_mat.ma"));
  EXPECT_EQ(smat.numTriangles(), 4u);
  const StructureTags tags = computeStructureTags(smat, base);
  EXPECT_EQ(tags.numThinParts(), 0);
  EXPECT_EQ(tags.node_tag, std::vector<int>(3747, 0));
}

TEST(StructureTags, BranchSphereRadiusDoesNotMakeALineBulky)
{
  // A fat sheet (radius 2; ρ = √4 / 2 = 1: normal) with a line of 4 pure edges (radius 0.5,
  // L = 8) growing out of its corner sphere 0 — a finger on a palm. Sphere 0 is shared by two
  // triangles and one edge (a branch point), so its radius 2 is the palm's, not the finger's:
  // ρ = 8 / 0.5 = 16 > 8 (thin, log2 16 = 4). The reference's r_max over all endpoints gave
  // 8 / 2 = 4 (normal).
  std::vector<Eigen::Vector3d> c{{0, -1, 0}, {-2, -1, 0}, {-2, 1, 0}, {0, 1, 0},
                                 {2, -1, 0}, {4, -1, 0},  {6, -1, 0}, {8, -1, 0}};
  const MedialMesh s(c, {2, 2, 2, 2, 0.5, 0.5, 0.5, 0.5}, {{0, 4}, {4, 5}, {5, 6}, {6, 7}},
                     {{0, 1, 2}, {0, 2, 3}});
  const MatGraph base = probes({{5.0, -0.8, 0}, {-1, 0, 0.2}});
  const StructureTags tags = computeStructureTags(s, base);
  ASSERT_EQ(tags.numThinParts(), 1);
  EXPECT_DOUBLE_EQ(tags.tag_ratio[1], 4.0);
  EXPECT_EQ(tags.node_tag, (std::vector<int>{1, 0}));
}

TEST(StructureTags, ANodeHalfwayBetweenTwoThinPartsTakesTheFirst)
{
  // Two parallel thin lines (L = 8, r = 0.5, ρ = 16), 2 apart; the probe at (4, 1, 0) is exactly
  // 1 from the sphere centres (4, 0, 0) and (4, 2, 0), both densified points. The tie goes to
  // the thin part found first (the one whose edges come first), whichever of the two it is.
  for (const bool lower_first : {true, false}) {
    std::vector<Eigen::Vector3d> c;
    for (const double y : lower_first ? std::vector<double>{0, 2} : std::vector<double>{2, 0})
      for (int k = 0; k <= 4; ++k)
        c.emplace_back(2.0 * k, y, 0.0);
    const std::vector<double> r(c.size(), 0.5);
    const MedialMesh structured(c, r,
                                {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {5, 6}, {6, 7}, {7, 8}, {8, 9}},
                                {});
    const StructureTags tags =
        computeStructureTags(structured, probes({{4, 1, 0}, {4, 0.9, 0}, {4, 1.1, 0}}));
    ASSERT_EQ(tags.numThinParts(), 2);
    EXPECT_EQ(tags.node_tag[0], 1) << (lower_first ? "lower" : "upper") << " line first";
    // Off the middle, the nearer line wins.
    EXPECT_EQ(tags.node_tag[1], lower_first ? 1 : 2);
    EXPECT_EQ(tags.node_tag[2], lower_first ? 2 : 1);
  }
}
