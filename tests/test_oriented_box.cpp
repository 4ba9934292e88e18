// Oriented bounding boxes: exact answers on boxes, rotated boxes, an L of two boxes and a
// cylinder; containment; never larger than the axis-aligned box; box output read back.
#include <segmat/common/error.h>
#include <segmat/evaluation/part_box_estimation.h>
#include <segmat/geometry/oriented_box.h>
#include <segmat/io/boxes.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/mesh.h>

#include <util/synthetic_mesh.h>
#include <util/temp_files.h>

#include <gtest/gtest.h>
#include <pcl/console/print.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

using namespace segmat;

namespace {
Eigen::Matrix3d
randomRotation(unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

TriangleMesh
transformed(TriangleMesh mesh, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift)
{
  for (Eigen::Vector3d& v : mesh.vertices)
    v = rotation * v + shift;
  return mesh;
}

// Every point inside (0.1 % of the diagonal) and no larger than the axis-aligned box.
void
expectHoldsAndNotLargerThanAabb(const OrientedBox& box, const std::vector<Eigen::Vector3d>& pts)
{
  const OrientedBox aabb = computeAxisAlignedBox(pts);
  const double tolerance = 1e-3 * aabb.extents.norm();
  for (const Eigen::Vector3d& p : pts)
    ASSERT_TRUE(box.contains(p, tolerance)) << p.transpose();
  EXPECT_LE(box.volume(), aabb.volume() * (1.0 + 1e-12));
  EXPECT_NEAR((box.axes * box.axes.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(box.axes.determinant(), 1.0, 1e-9);
  EXPECT_GE(box.extents[0], box.extents[1] - 1e-12 * tolerance);
  EXPECT_GE(box.extents[1], box.extents[2] - 1e-12 * tolerance);
}
} // namespace

TEST(MinimumVolumeBox, AxisAlignedBoxIsItself)
{
  const TriangleMesh mesh = test::box({-1, 2, 0}, {2, 3, 0.5}, 3);
  const OrientedBox box = computeMinimumVolumeBox(mesh.vertices);
  EXPECT_NEAR(box.volume(), 3.0 * 1.0 * 0.5, 1.5 * 0.01);
  EXPECT_NEAR(box.extents[0], 3.0, 1e-9);
  EXPECT_NEAR(box.extents[1], 1.0, 1e-9);
  EXPECT_NEAR(box.extents[2], 0.5, 1e-9);
  EXPECT_TRUE(box.center.isApprox(Eigen::Vector3d(0.5, 2.5, 0.25), 1e-9));
  expectHoldsAndNotLargerThanAabb(box, mesh.vertices);
}

TEST(MinimumVolumeBox, RandomlyRotatedBoxesAreFound)
{
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Eigen::Matrix3d r = randomRotation(seed);
    const TriangleMesh mesh =
        transformed(test::box({0, 0, 0}, {3, 1.5, 0.5}, 2), r, Eigen::Vector3d(5, -2, 1));
    const OrientedBox box = computeMinimumVolumeBox(mesh.vertices);
    EXPECT_NEAR(box.volume(), 2.25, 2.25 * 0.01) << "seed " << seed;
    // The longest axis is the box's 3-long edge, r's first column.
    EXPECT_GT(std::abs(box.axes.row(0).dot(r.col(0))), 0.9999) << "seed " << seed;
    expectHoldsAndNotLargerThanAabb(box, mesh.vertices);
    // A rotated box's axis-aligned box is strictly larger (no rotation here is axis-aligned).
    EXPECT_GT(computeAxisAlignedBox(mesh.vertices).volume(), 1.1 * box.volume());
  }
}

TEST(MinimumVolumeBox, RotatedCylinderGetsItsSquarePrism)
{
  // A 48-gon prism of circumradius 1 and length 4: its minimal box is 4 long with a square
  // section between 2 cos(π/48) and 2 wide, volume in [15.93, 16].
  const Eigen::Matrix3d r = randomRotation(42);
  const TriangleMesh mesh =
    transformed(test::cylinder(1.0, 4.0, 48, 4), r, Eigen::Vector3d::Ones());
  const OrientedBox box = computeMinimumVolumeBox(mesh.vertices);
  EXPECT_NEAR(box.volume(), 16.0, 16.0 * 0.01);
  EXPECT_LE(box.volume(), 16.0 * (1.0 + 1e-9));
  EXPECT_GT(std::abs(box.axes.row(0).dot(r.col(2))), 0.9999);
  EXPECT_NEAR(box.extents[0], 4.0, 1e-9);
  expectHoldsAndNotLargerThanAabb(box, mesh.vertices);
}

TEST(MinimumVolumeBox, BeatsThePrincipalAxesOnAnL)
{
  // An L of a 4×1×1 bar and a 1×3×1 bar: its principal axes are diagonal, the minimal box is
  // the 4×4×1 axis-aligned one (volume 16) rotated here.
  const Eigen::Matrix3d r = randomRotation(7);
  const TriangleMesh l = transformed(
      test::merge({test::box({0, 0, 0}, {4, 1, 1}), test::box({0, 1, 0}, {1, 4, 1})}), r,
      Eigen::Vector3d::Zero());
  const OrientedBox box = computeMinimumVolumeBox(l.vertices);
  const OrientedBox pca = computePcaBox(l.vertices);
  EXPECT_NEAR(box.volume(), 16.0, 16.0 * 0.01);
  EXPECT_GT(pca.volume(), 1.2 * box.volume());
  expectHoldsAndNotLargerThanAabb(box, l.vertices);
  expectHoldsAndNotLargerThanAabb(pca, l.vertices);
}

TEST(MinimumVolumeBox, RegularTetrahedronGetsItsCube)
{
  // The minimal box of a regular tetrahedron of edge √2 is the unit cube through its vertices:
  // each cube face holds one tetrahedron edge, no cube face is flush with a tetrahedron face.
  for (unsigned seed = 20; seed < 24; ++seed) {
    const Eigen::Matrix3d r = randomRotation(seed);
    std::vector<Eigen::Vector3d> tetrahedron;
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0),
                                     Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)})
      tetrahedron.push_back(r * p);
    const OrientedBox box = computeMinimumVolumeBox(tetrahedron);
    EXPECT_NEAR(box.volume(), 1.0, 0.01) << "seed " << seed;
    expectHoldsAndNotLargerThanAabb(box, tetrahedron);
  }
}

TEST(MinimumVolumeBox, FlatCollinearAndTinyInputs)
{
  const Eigen::Matrix3d r = randomRotation(3);
  std::vector<Eigen::Vector3d> square;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 2; ++j)
      square.push_back(r * Eigen::Vector3d(i, 0.5 * j, 0.0));
  const OrientedBox flat = computeMinimumVolumeBox(square);
  EXPECT_NEAR(flat.extents[0], 4.0, 1e-9);
  EXPECT_NEAR(flat.extents[1], 1.0, 1e-9);
  EXPECT_NEAR(flat.extents[2], 0.0, 1e-9);
  expectHoldsAndNotLargerThanAabb(flat, square);

  const std::vector<Eigen::Vector3d> line{ r * Eigen::Vector3d(0, 0, 0),
                                           r * Eigen::Vector3d(2, 0, 0),
                                           r * Eigen::Vector3d(5, 0, 0) };
  const OrientedBox segment = computeMinimumVolumeBox(line);
  EXPECT_NEAR(segment.extents[0], 5.0, 1e-9);
  EXPECT_NEAR(segment.extents[1], 0.0, 1e-9);
  expectHoldsAndNotLargerThanAabb(segment, line);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const OrientedBox single = computeMinimumVolumeBox({{1, 2, 3}, {nan, 0, 0}});
  EXPECT_TRUE(single.center.isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_EQ(single.volume(), 0.0);
  EXPECT_EQ(computeMinimumVolumeBox({}).volume(), 0.0);
}

TEST(OrientedBox, MeshIsClosedOutwardAndHasTheBoxVolume)
{
  OrientedBox box;
  box.axes = randomRotation(5).transpose();
  box.center = Eigen::Vector3d(1, 2, 3);
  box.extents = Eigen::Vector3d(3, 2, 0.5);
  const TriangleMesh mesh = box.toMesh();
  ASSERT_EQ(mesh.numFaces(), 12u);
  EXPECT_NEAR(test::signedVolume(mesh), 3.0, 1e-9);
  for (const Eigen::Vector3d& c : box.corners())
    EXPECT_TRUE(box.contains(c, 1e-12));
  EXPECT_FALSE(box.contains(box.center + 1.01 * Eigen::Vector3d(box.axes.row(0)) * 1.5));
}

TEST(PartBoxEstimation, LOfTwoBoxesGivesOneExactBoxPerPart)
{
  const Eigen::Matrix3d r = randomRotation(11);
  const TriangleMesh a = test::box({0, 0, 0}, {4, 1, 1}, 2);
  const TriangleMesh b = test::box({0, 1, 0}, {1, 4, 1}, 2);
  auto l =
    std::make_shared<TriangleMesh>(transformed(test::merge({ a, b }), r, Eigen::Vector3d(1, 1, 1)));
  std::vector<int> labels(l->numFaces(), 7);
  std::fill(labels.begin(), labels.begin() + a.numFaces(), 2);
  PartBoxEstimation estimation;
  estimation.setInputMesh(l, labels);
  std::vector<PartBox> boxes;
  estimation.compute(boxes);
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0].part, 2);
  EXPECT_EQ(boxes[1].part, 7);
  EXPECT_NEAR(boxes[0].box.volume(), 4.0, 0.04);
  EXPECT_NEAR(boxes[1].box.volume(), 3.0, 0.03);
  for (const PartBox& part : boxes) {
    std::vector<Eigen::Vector3d> vertices;
    for (std::size_t f = 0; f < l->numFaces(); ++f)
      if (labels[f] == part.part)
        for (int k = 0; k < 3; ++k)
          vertices.push_back(l->vertices[l->faces[f][k]]);
    expectHoldsAndNotLargerThanAabb(part.box, vertices);
  }
  EXPECT_THROW(estimation.setInputMesh(l, std::vector<int>(3, 0)), Error);
}

TEST(PartBoxEstimation, CloudPartsAndUnlabelledPoints)
{
  std::vector<Eigen::Vector3d> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {9, 9, 9}};
  PartBoxEstimation estimation;
  estimation.setInputPoints(points, {0, 0, 0, 0, -1});
  std::vector<PartBox> boxes;
  estimation.compute(boxes);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0].points, 4u);
  EXPECT_FALSE(boxes[0].box.contains({9, 9, 9}, 1e-6));
  expectHoldsAndNotLargerThanAabb(boxes[0].box, {points.begin(), points.begin() + 4});
  EXPECT_THROW(estimation.setInputPoints(points, {0}), Error);
}

TEST(BoxOutput, PlyReadsBackWithPartColoursAndJsonHasEveryField)
{
  std::vector<PartBox> boxes(2);
  boxes[0].part = 3;
  boxes[0].box.extents = Eigen::Vector3d(1, 2, 3);
  boxes[1].part = 0;
  boxes[1].box.axes = randomRotation(2).transpose();
  boxes[1].box.center = Eigen::Vector3d(4, 0, 0);
  boxes[1].box.extents = Eigen::Vector3d(0.5, 0.5, 0.25);
  const std::string ply = test::scratchDir() + "/boxes.ply";
  io::saveBoxesPly(ply, boxes);
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); // PCL's reader names the colours
  const TriangleMesh back = io::loadMesh(ply);
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
  ASSERT_EQ(back.numVertices(), 16u);
  ASSERT_EQ(back.numFaces(), 24u);
  EXPECT_NEAR(test::signedVolume(back), 6.0 + 0.0625, 1e-9);
  // Face lines: "3 a b c r g b"; the first 12 carry part 3's colour, the next 12 part 0's.
  std::istringstream text(test::readWholeFile(ply));
  std::string line;
  while (std::getline(text, line) && line != "end_header") {
  }
  for (int v = 0; v < 16; ++v)
    std::getline(text, line);
  for (int f = 0; f < 24; ++f) {
    ASSERT_TRUE(std::getline(text, line));
    std::istringstream words(line);
    int n, a, b, c, red, green, blue;
    ASSERT_TRUE(words >> n >> a >> b >> c >> red >> green >> blue) << line;
    const io::Rgb expected = io::labelColor(f < 12 ? 3 : 0);
    EXPECT_EQ(red, expected[0]);
    EXPECT_EQ(green, expected[1]);
    EXPECT_EQ(blue, expected[2]);
  }

  const std::string json_path = test::scratchDir() + "/boxes.json";
  io::saveBoxesJson(json_path, boxes);
  const std::string json = test::readWholeFile(json_path);
  EXPECT_EQ(json.rfind("{\"boxes\": [", 0), 0u);
  EXPECT_NE(json.find("{\"part\": 3, \"center\": [0, 0, 0], \"axes\": [[1, 0, 0], [0, 1, 0], "
                      "[0, 0, 1]], \"extents\": [1, 2, 3], \"volume\": 6}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"part\": 0"), std::string::npos);
  EXPECT_NE(json.find("\"volume\": 0.0625"), std::string::npos);

  boxes[0].box.center[1] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(test::throwsFileError([&] { io::saveBoxesJson(json_path, boxes); }, json_path, 0,
                                    "non-finite"));
  EXPECT_EQ(test::readWholeFile(json_path), json); // the old file is left whole
}
