// Generalised winding number, face orientation repair and point welding on hand-built meshes.
#include <segmat/geometry/face_orientation.h>
#include <segmat/geometry/weld_points.h>
#include <segmat/geometry/winding_number.h>

#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;
using segmat::test::box;
using segmat::test::icosphere;
using segmat::test::signedVolume;
using segmat::test::tetrahedron;

namespace {
// Deterministic points in [-s, s]^3 (a fixed 64-bit LCG; no std distributions).
std::vector<Eigen::Vector3d>
scatter(int n, double s, std::uint64_t seed = 12345)
{
  std::vector<Eigen::Vector3d> points;
  std::uint64_t x = seed;
  auto next = [&x]() {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(x >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < n; ++i) {
    const double a = next(), b = next(), c = next();
    points.emplace_back(s * (2 * a - 1), s * (2 * b - 1), s * (2 * c - 1));
  }
  return points;
}
} // namespace

TEST(SyntheticMesh, OutwardAndClosed)
{
  // Volumes worked out by hand: 1/6, 2·3·4, and the icosphere's inscribed polyhedron < 4π/3.
  EXPECT_NEAR(signedVolume(tetrahedron()), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(signedVolume(box({0, 0, 0}, {2, 3, 4}, 3)), 24.0, 1e-12);
  const double sphere = signedVolume(icosphere(3));
  EXPECT_GT(sphere, 0.97 * 4.0 / 3.0 * M_PI);
  EXPECT_LT(sphere, 4.0 / 3.0 * M_PI);
  // Capsule r = 0.5, length 2: π r² L + 4/3 π r³, and a torus 2π² R r².
  EXPECT_NEAR(signedVolume(test::capsule(0.5, 2.0, 64, 16, 16)),
              M_PI * 0.25 * 2.0 + 4.0 / 3.0 * M_PI * 0.125, 0.01);
  // Torus: Pappus, 2π² R r², times the polygon/circle ratios sin(x)/x of both circles.
  const double sinc96 = std::sin(2 * M_PI / 96) / (2 * M_PI / 96);
  const double sinc48 = std::sin(2 * M_PI / 48) / (2 * M_PI / 48);
  EXPECT_NEAR(signedVolume(test::torus(2.0, 0.5, 96, 48)),
              2 * M_PI * M_PI * 2.0 * 0.25 * sinc96 * sinc48, 2e-3);
  EXPECT_NEAR(signedVolume(test::cylinder(1.0, 2.0, 96, 4)), 2 * M_PI, 0.01);
  // Every edge of a closed mesh has exactly two faces: 3F/2 adjacencies.
  for (const TriangleMesh& m : {icosphere(2), box({0, 0, 0}, {1, 1, 1}, 4), test::capsule(1, 1),
                                test::torus(2, 1), test::cylinder(1, 2)})
    EXPECT_EQ(m.faceAdjacency().size() * 2, m.faces.size() * 3);
}

TEST(WindingNumber, ExactValuesOnTetrahedronAndCube)
{
  const WindingNumber tet(tetrahedron());
  EXPECT_NEAR(tet({0.1, 0.1, 0.1}), 1.0, 1e-12);
  EXPECT_NEAR(tet({0.2, 0.3, 0.4}), 1.0, 1e-12);
  EXPECT_NEAR(tet({1.0, 1.0, 1.0}), 0.0, 1e-12);
  EXPECT_NEAR(tet({-0.1, 0.1, 0.1}), 0.0, 1e-12);
  // Just below the middle of the bottom face: outside, the bottom face cancels the other three.
  EXPECT_NEAR(tet.exact({0.25, 0.25, -1e-9}), 0.0, 1e-6);
  EXPECT_NEAR(tet.exact({0.25, 0.25, 1e-9}), 1.0, 1e-6);
  // A vertex of the tetrahedron sees the opposite face only: solid angle of the octant corner,
  // 4π/8, so w = 1/8.
  EXPECT_NEAR(tet.exact({0.0, 0.0, 0.0}), 0.125, 1e-12);

  // Exact sums are exact; the hierarchy (β = 2) is within a few 1e-3.
  const WindingNumber cube(box({-1, -1, -1}, {1, 1, 1}, 6));
  EXPECT_NEAR(cube.exact({0, 0, 0}), 1.0, 1e-12);
  EXPECT_NEAR(cube.exact({0.9, -0.95, 0.99}), 1.0, 1e-12);
  EXPECT_NEAR(cube.exact({1.01, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(cube({0, 0, 0}), 1.0, 5e-3);
  EXPECT_NEAR(cube({0.9, -0.95, 0.99}), 1.0, 5e-3);
  EXPECT_NEAR(cube({1.01, 0, 0}), 0.0, 5e-3);
  EXPECT_NEAR(cube({5, 5, 5}), 0.0, 5e-3);
  EXPECT_TRUE(cube.inside({0.5, 0.5, 0.5}));
  EXPECT_FALSE(cube.inside({1.5, 0.5, 0.5}));
  EXPECT_EQ(cube.numFlippedFaces(), 0u);
}

TEST(WindingNumber, HierarchyAgreesWithExactSum)
{
  const TriangleMesh sphere = icosphere(4); // 5120 faces, leaves far below the root
  WindingNumber w(sphere);
  const std::vector<Eigen::Vector3d> queries = scatter(1000, 2.0);
  std::vector<double> reference;
  for (const Eigen::Vector3d& q : queries)
    reference.push_back(w.exact(q));
  // Error of the second-order far field shrinks quickly with β.
  const double beta[] = {2.0, 4.0, 8.0};
  const double bound[] = {1e-2, 1e-3, 1e-5};
  for (int i = 0; i < 3; ++i) {
    w.setAccuracy(beta[i]);
    double max_error = 0.0;
    for (std::size_t k = 0; k < queries.size(); ++k)
      max_error = std::max(max_error, std::abs(w(queries[k]) - reference[k]));
    EXPECT_LT(max_error, bound[i]) << "beta " << beta[i];
  }
  // β = 0 is the exact sum; the batch evaluation gives the same values as single queries.
  w.setAccuracy(0.0);
  EXPECT_EQ(w(queries[7]), w.exact(queries[7]));
  w.setAccuracy(2.0);
  std::vector<double> batch;
  w.evaluate(queries, batch, 2);
  int checked = 0;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    EXPECT_EQ(batch[k], w(queries[k]));
    // Away from the surface the classification is unambiguous.
    if (std::abs(queries[k].norm() - 1.0) > 0.02) {
      EXPECT_EQ(batch[k] > 0.5, queries[k].norm() < 1.0) << queries[k].transpose();
      ++checked;
    }
  }
  EXPECT_GT(checked, 900);
}

TEST(WindingNumber, SmallHoleStillClassifies)
{
  TriangleMesh sphere = icosphere(3); // 1280 faces
  sphere.faces.erase(sphere.faces.begin() + 100, sphere.faces.begin() + 104); // 4 faces missing
  const WindingNumber w(sphere);
  // The centre misses the hole's solid angle, 4/1280 of the sphere on average.
  EXPECT_NEAR(w.exact({0, 0, 0}), 1.0 - 4.0 / 1280.0, 1e-3);
  for (const Eigen::Vector3d& q : scatter(500, 1.5, 99)) {
    if (std::abs(q.norm() - 1.0) < 0.05)
      continue;
    EXPECT_EQ(w.inside(q), q.norm() < 1.0) << q.transpose();
  }
}

TEST(WindingNumber, InvertedFacesAreRepaired)
{
  TriangleMesh sphere = icosphere(3);
  // Whole mesh inside out: without repair the centre has w = -1.
  TriangleMesh inverted = sphere;
  for (auto& f : inverted.faces)
    std::swap(f[1], f[2]);
  EXPECT_NEAR(WindingNumber(inverted, false).exact({0, 0, 0}), -1.0, 1e-9);
  const WindingNumber repaired(inverted);
  EXPECT_NEAR(repaired.exact({0, 0, 0}), 1.0, 1e-9);
  EXPECT_EQ(repaired.numFlippedFaces(), sphere.faces.size());

  // Every third face flipped: mixed orientation.
  TriangleMesh mixed = sphere;
  std::size_t flipped = 0;
  for (std::size_t f = 0; f < mixed.faces.size(); f += 3, ++flipped)
    std::swap(mixed.faces[f][1], mixed.faces[f][2]);
  const WindingNumber fixed(mixed);
  EXPECT_EQ(fixed.numFlippedFaces(), flipped);
  EXPECT_NEAR(fixed.exact({0.3, -0.2, 0.1}), 1.0, 1e-9);
  EXPECT_NEAR(fixed.exact({1.3, -0.2, 0.1}), 0.0, 1e-9);
}

TEST(FaceOrientation, SoupAndSeveralComponents)
{
  // An unwelded soup (every face has its own corners), mixed orientation: welding exactly equal
  // positions reconnects it.
  const TriangleMesh sphere = icosphere(2);
  TriangleMesh soup;
  for (std::size_t f = 0; f < sphere.faces.size(); ++f) {
    Eigen::Vector3i g;
    for (int k = 0; k < 3; ++k) {
      g[k] = static_cast<int>(soup.vertices.size());
      soup.vertices.push_back(sphere.vertices[sphere.faces[f][k]]);
    }
    if (f % 2)
      std::swap(g[1], g[2]);
    soup.faces.push_back(g);
  }
  TriangleMesh repaired = soup;
  EXPECT_EQ(orientFacesOutward(repaired), sphere.faces.size() / 2);
  EXPECT_GT(signedVolume(repaired), 4.0);

  // Two spheres, the second inside out, plus a degenerate face and an out-of-range index.
  TriangleMesh second = icosphere(2, 0.5, {3, 0, 0});
  for (auto& f : second.faces)
    std::swap(f[1], f[2]);
  TriangleMesh both = test::merge({sphere, second});
  both.faces.emplace_back(0, 0, 1);
  both.faces.emplace_back(0, 1, 100000);
  const WindingNumber w(both);
  EXPECT_EQ(w.numFlippedFaces(), second.faces.size());
  EXPECT_NEAR(w.exact({0, 0, 0}), 1.0, 1e-9);
  EXPECT_NEAR(w.exact({3, 0, 0}), 1.0, 1e-9);
  EXPECT_NEAR(w.exact({1.5, 0, 0}), 0.0, 1e-9);
  EXPECT_TRUE(w.inside({0.5, 0, 0}));
  EXPECT_TRUE(w.inside({3.2, 0, 0}));
  EXPECT_FALSE(w.inside({1.5, 0, 0}));
}

TEST(WindingNumber, EmptyAndNonFiniteInput)
{
  const WindingNumber empty{TriangleMesh()};
  EXPECT_EQ(empty({0, 0, 0}), 0.0);
  EXPECT_EQ(empty.numFaces(), 0u);
  TriangleMesh bad = tetrahedron();
  bad.vertices[3] = {std::numeric_limits<double>::quiet_NaN(), 0, 0};
  const WindingNumber w(bad);
  EXPECT_EQ(w.numFaces(), 1u); // only the face without the NaN corner
  EXPECT_TRUE(std::isfinite(w({0.1, 0.1, 0.1})));
  const WindingNumber tet(tetrahedron());
  EXPECT_EQ(tet({std::numeric_limits<double>::quiet_NaN(), 0, 0}), 0.0);
}

TEST(WeldPoints, ExactAndTolerance)
{
  const std::vector<Eigen::Vector3d> p{{0, 0, 0}, {1, 0, 0}, {0, 0, 0},  {1, 1e-10, 0},
                                       {-0.0, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0, 0},
                                       {2, 0, 0}};
  EXPECT_EQ(weldPoints(p, 0.0), (std::vector<int>{0, 1, 0, 3, 0, 5, 6}));
  EXPECT_EQ(weldPoints(p, 1e-9), (std::vector<int>{0, 1, 0, 1, 0, 5, 6}));
  // Greedy, not transitive: (2,0,0) is 2 from representative 0, so it stays on its own.
  EXPECT_EQ(weldPoints(p, 1.5), (std::vector<int>{0, 0, 0, 0, 0, 5, 6}));
}

TEST(WindingNumber, CrossingCountsMatchWindingNumbers)
{
  // Torus (genus 1) and two nested-but-separate shapes: for every segment whose count is certain,
  // the signed number of crossings equals the difference of the exact winding numbers.
  for (const TriangleMesh& mesh :
       {test::torus(2.0, 0.5, 48, 16),
        test::merge({test::capsule(0.5, 1.0, 24, 8, 6), icosphere(2, 0.4, {2.5, 0, 0})})}) {
    const WindingNumber w(mesh);
    ASSERT_TRUE(w.isClosed());
    const std::vector<Eigen::Vector3d> a = scatter(400, 3.0, 5), b = scatter(400, 3.0, 6);
    int certain = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      int change = 0;
      if (!w.windingNumberChange(a[i], b[i], change))
        continue;
      ++certain;
      EXPECT_EQ(change, std::lround(w.exact(b[i])) - std::lround(w.exact(a[i])));
    }
    EXPECT_GT(certain, 390);
    // Straight through a vertex and along an edge: uncertain, or right.
    for (std::size_t v = 0; v < 20; ++v) {
      const Eigen::Vector3d p = mesh.vertices[v];
      int change = 0;
      if (w.windingNumberChange(1.5 * p, 0.5 * p, change))
        EXPECT_EQ(change, std::lround(w.exact(0.5 * p)) - std::lround(w.exact(1.5 * p)));
    }
  }
  // An open mesh has no piecewise-constant winding number.
  TriangleMesh open = icosphere(2);
  open.faces.pop_back();
  const WindingNumber w(open);
  EXPECT_FALSE(w.isClosed());
  int change = 0;
  EXPECT_FALSE(w.windingNumberChange({0, 0, 0}, {2, 0, 0}, change));
  // Crossing the unit sphere once, outward: −1; inward: +1; twice: 0.
  const WindingNumber sphere(icosphere(2));
  ASSERT_TRUE(sphere.windingNumberChange({0.1, 0.05, 0.02}, {2, 0.3, 0.1}, change));
  EXPECT_EQ(change, -1);
  ASSERT_TRUE(sphere.windingNumberChange({2, 0.3, 0.1}, {0.1, 0.05, 0.02}, change));
  EXPECT_EQ(change, 1);
  ASSERT_TRUE(sphere.windingNumberChange({-2, 0.3, 0.1}, {2, 0.05, 0.02}, change));
  EXPECT_EQ(change, 0);
}
