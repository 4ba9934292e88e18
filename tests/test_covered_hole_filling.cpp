/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Filling the holes of a medial sheet that its rim balls cover, on flat triangulated sheets
 * whose holes are known.
 */
#include "../src/medial/covered_hole_filling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

namespace {

using segmat::MedialMesh;

/// A flat n × n grid of spheres (spacing 1, radius \a radius) in the plane z = 0, each square
/// split into two triangles, without the triangles that touch a vertex in \a removed (those
/// vertices keep no edge either: a rejected Voronoi vertex leaves nothing behind).
MedialMesh
sheet(int n, double radius, const std::set<int>& removed)
{
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      centers.emplace_back(x, y, 0.0);
      radii.push_back(radius);
    }
  std::vector<Eigen::Vector3i> triangles;
  auto keep = [&](int a, int b, int c) {
    if (!removed.count(a) && !removed.count(b) && !removed.count(c))
      triangles.emplace_back(a, b, c);
  };
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int v = y * n + x;
      keep(v, v + 1, v + n + 1);
      keep(v, v + n + 1, v + n);
    }
  std::set<std::pair<int, int>> edge_set;
  for (const Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k)
      edge_set.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  std::vector<Eigen::Vector2i> edges;
  for (const auto& [a, b] : edge_set)
    edges.emplace_back(a, b);
  return MedialMesh(centers, radii, edges, triangles);
}

/// Euler characteristic V − E + F over the vertices that have an edge.
long
eulerCharacteristic(const MedialMesh& m)
{
  long used = 0;
  for (std::size_t v = 0; v < m.numVertices(); ++v)
    used += m.vertexEdges(int(v)).empty() ? 0 : 1;
  return used - long(m.numEdges()) + long(m.numTriangles());
}

TEST(CoveredHoleFilling, HoleOfOneMissingVertexIsClosedWhenItsRimBallsCoverIt)
{
  // The vertex at (4, 4) of a 9 × 9 grid takes its six triangles along: a hexagonal hole whose
  // farthest point from the rim, (4, 4), lies 1 from the nearest rim vertices; balls of radius
  // 1.2 cover it. An annulus has χ = 0, the closed disc 1.
  MedialMesh m = sheet(9, 1.2, {4 * 9 + 4});
  ASSERT_EQ(eulerCharacteristic(m), 0);
  const std::size_t triangles = m.numTriangles();
  EXPECT_EQ(segmat::detail::fillCoveredHoles(m), 1);
  EXPECT_EQ(eulerCharacteristic(m), 1);
  EXPECT_EQ(m.numTriangles(), triangles + 4); // a hexagon's fan
  for (std::size_t e = 0; e < m.numEdges(); ++e)
    EXPECT_LE(m.edgeTriangleCount(int(e)), 2) << "the fill must not stack on the sheet";
}

TEST(CoveredHoleFilling, HoleWiderThanItsRimBallsStays)
{
  // The same hole with balls of radius 0.9: the point (4, 4) lies 1 or more from every rim
  // vertex, outside every ball, so the shape has a hole there.
  MedialMesh m = sheet(9, 0.9, {4 * 9 + 4});
  EXPECT_EQ(segmat::detail::fillCoveredHoles(m), 0);
  EXPECT_EQ(eulerCharacteristic(m), 0);
  // A 3 × 3 block of missing vertices: a hole 4 wide, whose centre lies 2 from the rim, outside
  // balls of radius 1.2.
  std::set<int> block;
  for (int y = 3; y <= 5; ++y)
    for (int x = 3; x <= 5; ++x)
      block.insert(y * 9 + x);
  MedialMesh wide = sheet(9, 1.2, block);
  EXPECT_EQ(segmat::detail::fillCoveredHoles(wide), 0);
}

TEST(CoveredHoleFilling, IslandAndOuterBoundaryAreNotHoles)
{
  // A 3 × 3 sheet with huge balls: its outline is a loop whose fan the balls cover, but the
  // sheet's own triangles lie inside it.
  MedialMesh island = sheet(3, 5.0, {});
  const std::size_t triangles = island.numTriangles();
  EXPECT_EQ(segmat::detail::fillCoveredHoles(island), 0);
  EXPECT_EQ(island.numTriangles(), triangles);
}

TEST(CoveredHoleFilling, TwoHolesAreBothFilled)
{
  // Two hexagonal holes: χ = 1 − 2 before, a disc after, each closed by a fan of 4 triangles.
  MedialMesh m = sheet(12, 1.2, {3 * 12 + 3, 8 * 12 + 7});
  ASSERT_EQ(eulerCharacteristic(m), -1);
  const std::size_t triangles = m.numTriangles();
  EXPECT_EQ(segmat::detail::fillCoveredHoles(m), 2);
  EXPECT_EQ(eulerCharacteristic(m), 1);
  EXPECT_EQ(m.numTriangles(), triangles + 8);
  for (std::size_t e = 0; e < m.numEdges(); ++e)
    EXPECT_LE(m.edgeTriangleCount(int(e)), 2);
}

} // namespace
