// Core geometry types on hand-built inputs.
#include <segmat/common/error.h>
#include <segmat/common/point_types.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>
#include <segmat/medial/mat_graph.h>

#include <gtest/gtest.h>
#include <pcl/point_cloud.h>

#include <cmath>
#include <set>

using namespace segmat;

namespace {
// Unit tetrahedron, outward-wound.
TriangleMesh
tetrahedron()
{
  return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                      {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}
} // namespace

TEST(TriangleMesh, NormalsAreaCentroidDiagonal)
{
  const TriangleMesh m = tetrahedron();
  EXPECT_TRUE(m.faceNormal(0).isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_TRUE(m.faceNormal(3).isApprox(Eigen::Vector3d(1, 1, 1).normalized()));
  EXPECT_DOUBLE_EQ(m.faceArea(0), 0.5);
  EXPECT_NEAR(m.faceArea(3), std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_TRUE(m.faceCentroid(3).isApprox(Eigen::Vector3d(1, 1, 1) / 3.0));
  EXPECT_DOUBLE_EQ(m.boundingBoxDiagonal(), std::sqrt(3.0));
}

TEST(TriangleMesh, AdjacencyClosedOpenAndNonManifold)
{
  TriangleMesh m = tetrahedron();
  // Closed: 6 edges, each with 2 faces.
  EXPECT_EQ(m.faceAdjacency().size(), 6u);
  // Open: dropping a face leaves 3 interior edges.
  m.faces.pop_back();
  EXPECT_EQ(m.faceAdjacency().size(), 3u);
  // Non-manifold fin: a third face on edge (0,1) pairs with both of its faces.
  m = tetrahedron();
  m.vertices.push_back({0.5, -1, 0});
  m.faces.push_back({0, 1, 4});
  EXPECT_EQ(m.faceAdjacency().size(), 8u);
  // Degenerate face (repeated index): no edges, no crash, zero normal.
  m.faces.push_back({2, 2, 3});
  EXPECT_EQ(m.faceAdjacency().size(), 8u);
  EXPECT_EQ(m.faceNormal(5), Eigen::Vector3d::Zero());
}

TEST(MedialMesh, NormalisesAndDerivesIncidence)
{
  // Two triangles sharing edge (1,2), a pure edge (3,4), a duplicate triangle, a missing side,
  // a self-loop edge and a degenerate triangle.
  std::vector<Eigen::Vector3d> c{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 0}};
  std::vector<double> r{0.1, 0.2, 0.3, 0.4, 0.5};
  MedialMesh m(c, r, {{0, 1}, {2, 1}, {3, 4}, {4, 4}},
               {{0, 1, 2}, {2, 1, 3}, {1, 0, 2}, {1, 1, 2}});
  EXPECT_EQ(m.numTriangles(), 2u);
  EXPECT_EQ(m.numEdges(), 6u); // 01 12 34 + 02 13 23
  EXPECT_EQ(m.edgeTriangleCount(m.findEdge(1, 2)), 2);
  EXPECT_TRUE(m.isPureEdge(m.findEdge(4, 3)));
  EXPECT_FALSE(m.isPureEdge(m.findEdge(0, 2)));
  EXPECT_EQ(m.findEdge(0, 4), -1);
  EXPECT_EQ(m.vertexTriangles(1).size(), 2u);
  EXPECT_EQ(m.vertexEdges(4).size(), 1u);
  EXPECT_DOUBLE_EQ(m.maxRadius(), 0.5);
  EXPECT_DOUBLE_EQ(m.centerBoundingBoxDiagonal(), std::sqrt(8.0));
}

TEST(MedialMesh, TrianglesAloneGrowTheEdgeTableAndKeepFirstAppearanceOrder)
{
  // A 30 × 30 grid of squares, two triangles each, no edges given: the edge table (sized for
  // the given edges plus half the triangle sides) must grow several times. A disk: E = V + F − 1.
  const int k = 30;
  std::vector<Eigen::Vector3d> c;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i)
      c.emplace_back(i, j, 0);
  const std::vector<double> r(c.size(), 0.25);
  std::vector<Eigen::Vector3i> t;
  auto id = [k](int i, int j) { return j * (k + 1) + i; };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      t.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      t.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  const MedialMesh m(c, r, {}, t);
  ASSERT_EQ(m.numTriangles(), t.size());
  EXPECT_EQ(m.numEdges(), c.size() + t.size() - 1); // 961 + 1800 − 1 = 2760
  // Ids in order of first appearance of each side, walking the triangles' sides in order.
  std::vector<std::pair<int, int>> expected;
  std::set<std::pair<int, int>> seen;
  for (const Eigen::Vector3i& f : t)
    for (int s = 0; s < 3; ++s) {
      const std::pair<int, int> e{std::min(f[s], f[(s + 1) % 3]), std::max(f[s], f[(s + 1) % 3])};
      if (seen.insert(e).second)
        expected.push_back(e);
    }
  ASSERT_EQ(expected.size(), m.numEdges());
  for (std::size_t e = 0; e < expected.size(); ++e) {
    ASSERT_EQ(m.edges()[e][0], expected[e].first) << e;
    ASSERT_EQ(m.edges()[e][1], expected[e].second) << e;
  }
  // Interior sides carry two triangles, the 4k border sides one.
  int border = 0;
  for (std::size_t e = 0; e < m.numEdges(); ++e)
    border += m.edgeTriangleCount(static_cast<int>(e)) == 1;
  EXPECT_EQ(border, 4 * k);
}

TEST(MedialMesh, CountsConnectedComponents)
{
  // A triangle 0 1 2 with 3 hanging on the pure edge 2–3; a separate pure edge 4–5; 6 alone; a
  // triangle 7 8 9 given without its sides (they are added, so it is one component).
  std::vector<Eigen::Vector3d> c(10, Eigen::Vector3d::Zero());
  for (int i = 0; i < 10; ++i)
    c[i].x() = i;
  const std::vector<double> r(10, 0.5);
  EXPECT_EQ(MedialMesh(c, r, {{2, 3}, {4, 5}}, {{0, 1, 2}, {7, 8, 9}}).numConnectedComponents(),
            4u); // {0 1 2 3} {4 5} {6} {7 8 9}
  EXPECT_EQ(MedialMesh(c, r, {{2, 3}, {4, 5}, {3, 4}, {5, 6}, {6, 7}}, {{0, 1, 2}, {7, 8, 9}})
                .numConnectedComponents(),
            1u);
  EXPECT_EQ(MedialMesh().numConnectedComponents(), 0u);
}

TEST(MedialMesh, RejectsBadInput)
{
  EXPECT_THROW(MedialMesh({{0, 0, 0}}, {-1.0}, {}, {}), Error);
  EXPECT_THROW(MedialMesh({{0, 0, 0}}, {NAN}, {}, {}), Error);
  EXPECT_THROW(MedialMesh({{0, 0, 0}, {1, 0, 0}}, {1, 1}, {{0, 2}}, {}), Error);
  EXPECT_THROW(MedialMesh({{0, 0, 0}}, {1, 1}, {}, {}), Error);
}

TEST(MatGraph, NodesAndGatedAdjacency)
{
  // Slab (0,1,2), slab (1,2,3) and pure cone (3,4); sphere 4 is 3x fatter than the cone's other end.
  std::vector<Eigen::Vector3d> c{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 0}};
  MedialMesh m(c, {1, 1, 1, 1, 1}, {{3, 4}}, {{0, 1, 2}, {1, 2, 3}});
  MatGraph g = MatGraph::fromMedialMesh(m);
  ASSERT_EQ(g.numNodes(), 3u);
  EXPECT_EQ(g.node(2).kind, MatNodeKind::Cone);
  EXPECT_TRUE(g.node(2).centroid.isApprox(Eigen::Vector3d(1.5, 1.5, 0)));
  EXPECT_EQ(g.numEdges(), 2u); // slab0-slab1 (share 1,2), slab1-cone (share 3)
  EXPECT_TRUE(g.hasPrimitives());
  // Cone mean radius (1+6)/2 = 3.5 vs slab 1: ratio 3.5 >= 2.5, so the gate removes that edge.
  MedialMesh fat(c, {1, 1, 1, 1, 6}, {{3, 4}}, {{0, 1, 2}, {1, 2, 3}});
  EXPECT_EQ(MatGraph::fromMedialMesh(fat).numEdges(), 1u);
}

TEST(MedialPoint, RegisteredWithPcl)
{
  pcl::PointCloud<MedialPoint> cloud;
  MedialPoint p;
  p.x = 1;
  p.radius = 0.5f;
  cloud.push_back(p);
  EXPECT_EQ(cloud.size(), 1u);
  EXPECT_FLOAT_EQ(cloud[0].radius, 0.5f);
}
