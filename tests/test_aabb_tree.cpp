// Segment–surface intersection with the AABB tree, against hand cases and an independent
// half-space (Cyrus–Beck) test on a convex polyhedron.
#include <segmat/geometry/aabb_tree.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace segmat;

namespace {

/** Axis-aligned unit cube [0,1]³, 12 outward triangles. */
TriangleMesh
unitCube()
{
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i)
    v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<Eigen::Vector3i> f{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return TriangleMesh(v, f);
}

/** Convex UV sphere (radius 1) with `rings` × `sectors` quads split into triangles. */
TriangleMesh
uvSphere(int rings, int sectors)
{
  TriangleMesh m;
  m.vertices.emplace_back(0, 0, 1);
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / sectors;
      m.vertices.emplace_back(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                              std::cos(th));
    }
  m.vertices.emplace_back(0, 0, -1);
  const int south = static_cast<int>(m.vertices.size()) - 1;
  const auto at = [&](int i, int j) { return 1 + (i - 1) * sectors + (j % sectors); };
  for (int j = 0; j < sectors; ++j) {
    m.faces.emplace_back(0, at(1, j), at(1, j + 1));
    m.faces.emplace_back(south, at(rings - 1, j + 1), at(rings - 1, j));
    for (int i = 1; i + 1 < rings; ++i) {
      m.faces.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.faces.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return m;
}

/** Independent answer for a closed convex mesh: clip the segment by every face's half-space
 * (Cyrus–Beck). The segment meets the surface unless it lies strictly inside, or misses the
 * solid entirely. */
bool
convexMeetsSurface(const TriangleMesh& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  double t0 = 0.0, t1 = 1.0;
  bool a_inside = true, b_inside = true;
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const Eigen::Vector3d n = m.faceNormal(static_cast<int>(f));
    const Eigen::Vector3d& p = m.vertices[m.faces[f][0]];
    const double da = n.dot(a - p), db = n.dot(b - p);
    a_inside = a_inside && da < 0;
    b_inside = b_inside && db < 0;
    if (da >= 0 && db >= 0)
      return false; // wholly outside this face's plane
    if (da > 0 || db > 0) {
      const double t = da / (da - db);
      if (da > 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  if (a_inside && b_inside)
    return false;
  return t0 <= t1;
}

} // namespace

TEST(AabbTree, CubeHandCases)
{
  const AabbTree tree(unitCube());
  EXPECT_EQ(tree.numTriangles(), 12u);
  const Eigen::Vector3d in(0.5, 0.5, 0.5), in2(0.2, 0.7, 0.4);
  EXPECT_FALSE(tree.segmentIntersects(in, in2));                       // inside → inside
  EXPECT_TRUE(tree.segmentIntersects(in, Eigen::Vector3d(2, 0.5, 0.5))); // leaves through x = 1
  EXPECT_TRUE(tree.segmentIntersects(Eigen::Vector3d(-1, 0.3, 0.6), Eigen::Vector3d(2, 0.3, 0.6)));
  EXPECT_FALSE(tree.segmentIntersects(Eigen::Vector3d(-1, 2, 0.5), Eigen::Vector3d(2, 2, 0.5)));
  EXPECT_FALSE(tree.segmentIntersects(in, in)); // degenerate: nothing
  // Ends exactly on the face x = 1 (closed segment): a hit.
  EXPECT_TRUE(tree.segmentIntersects(in, Eigen::Vector3d(1, 0.5, 0.5)));
  // Stops just short of it: no hit.
  EXPECT_FALSE(tree.segmentIntersects(in, Eigen::Vector3d(0.999, 0.5, 0.5)));
}

TEST(AabbTree, AgreesWithHalfSpaceClippingOnASphere)
{
  const TriangleMesh sphere = uvSphere(24, 48); // 2208 triangles, several tree levels
  const AabbTree tree(sphere);
  EXPECT_EQ(tree.numTriangles(), sphere.numFaces());
  std::mt19937 engine(3);
  const auto coord = [&engine]() { return (engine() / 4294967296.0) * 3.0 - 1.5; };
  int hits = 0, checked = 0;
  for (int k = 0; k < 4000; ++k) {
    const Eigen::Vector3d a(coord(), coord(), coord()), b(coord(), coord(), coord());
    const bool expected = convexMeetsSurface(sphere, a, b);
    ASSERT_EQ(tree.segmentIntersects(a, b), expected) << "segment " << k;
    hits += expected;
    ++checked;
  }
  // Both outcomes were exercised.
  EXPECT_GT(hits, checked / 10);
  EXPECT_LT(hits, checked - checked / 10);
}

TEST(AabbTree, EmptyAndDegenerateMeshes)
{
  const AabbTree empty{TriangleMesh()};
  EXPECT_TRUE(empty.empty());
  EXPECT_FALSE(empty.segmentIntersects(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)));
  // Only a degenerate (collinear) face: left out.
  const AabbTree flat(TriangleMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}));
  EXPECT_TRUE(flat.empty());
  EXPECT_FALSE(flat.segmentIntersects(Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(1, 1, 0)));
}
