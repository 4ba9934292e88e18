// The position order of points and meshes (src/geometry/position_order.h): worked out by hand on
// small inputs.
#include "../src/geometry/position_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;

TEST(PositionOrder, SortsByXThenYThenZ)
{
  const std::vector<Eigen::Vector3d> points{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, -1, 0}};
  EXPECT_EQ(detail::positionOrder(points), (std::vector<int>{2, 3, 1, 4, 0}));
}

// Points on an axis-aligned plane share x exactly; rounding them apart in the last bit (what a
// translation does) must not reorder them by that bit.
TEST(PositionOrder, LastBitDifferencesDoNotReorder)
{
  const double x = 0.25;
  const std::vector<Eigen::Vector3d> exact{{x, 0.9, 0}, {x, 0.1, 0}, {x, 0.5, 0}, {-0.5, 0, 0},
                                           {0.5, 1, 0}};
  std::vector<Eigen::Vector3d> rounded = exact;
  rounded[0].x() = std::nextafter(x, 1.0);  // would go last by exact x
  rounded[1].x() = std::nextafter(x, -1.0); // would go first among the three
  const std::vector<int> expected{3, 1, 2, 0, 4};
  EXPECT_EQ(detail::positionOrder(exact), expected);
  EXPECT_EQ(detail::positionOrder(rounded), expected);
}

TEST(PositionOrder, NonFinitePointsGoLastInInputOrder)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector3d> points{{nan, 0, 0}, {1, 0, 0}, {0, 0, nan}, {0, 0, 0}};
  EXPECT_EQ(detail::positionOrder(points), (std::vector<int>{3, 1, 0, 2}));
}

// Two triangles of a square, listed in the "wrong" order: vertices sorted, corners rotated to
// the smallest index with the orientation kept, faces sorted; face_of maps back.
TEST(PositionOrder, MeshIsRenumberedAndFacesMapBack)
{
  TriangleMesh mesh;
  mesh.vertices = {{1, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.faces = {Eigen::Vector3i(0, 3, 1), Eigen::Vector3i(2, 0, 1)};
  const std::vector<int> face_of = detail::sortMeshByPosition(mesh);
  // New numbering: (0,0,0)=0, (0,1,0)=1, (1,0,0)=2, (1,1,0)=3.
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3d(1, 1, 0));
  // Input face 0 (3,1,0 in new indices) → (0,3,1); input face 1 (2,3,0) → (0,2,3).
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[0], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(mesh.faces[1], Eigen::Vector3i(0, 3, 1));
  EXPECT_EQ(face_of, (std::vector<int>{1, 0}));
}
