// Exact point-to-mesh distance on hand-worked configurations.
#include <segmat/geometry/mesh_distance.h>

#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace segmat;

TEST(MeshDistance, ClosestPointOnTriangleRegions)
{
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // Face region: straight down.
  EXPECT_TRUE(
      closestPointOnTriangle({0.5, 0.5, 3}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  // Vertex regions.
  EXPECT_EQ(closestPointOnTriangle({-1, -1, 1}, a, b, c), a);
  EXPECT_EQ(closestPointOnTriangle({3, -1, 0}, a, b, c), b);
  EXPECT_EQ(closestPointOnTriangle({-1, 5, 0}, a, b, c), c);
  // Edge regions: below ab, left of ac, beyond bc.
  EXPECT_TRUE(closestPointOnTriangle({1, -1, 0}, a, b, c).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(closestPointOnTriangle({-1, 1, 2}, a, b, c).isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(closestPointOnTriangle({2, 2, 0}, a, b, c).isApprox(Eigen::Vector3d(1, 1, 0)));
  // Degenerate triangles: a segment and a point.
  EXPECT_TRUE(closestPointOnTriangle({1, 1, 0}, a, b, Eigen::Vector3d(1, 0, 0))
                  .isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_EQ(closestPointOnTriangle({1, 1, 1}, a, a, a), a);
}

TEST(MeshDistance, TetrahedronByHandAndAgainstBruteForce)
{
  const TriangleMesh tet = test::tetrahedron();
  const MeshDistance d(tet);
  EXPECT_EQ(d.size(), 4u);
  Eigen::Vector3d closest;
  EXPECT_NEAR(d.distance({0.25, 0.25, -1.0}, &closest), 1.0, 1e-15);
  EXPECT_TRUE(closest.isApprox(Eigen::Vector3d(0.25, 0.25, 0.0)));
  EXPECT_NEAR(d.distance({3, 0, 0}), 2.0, 1e-15);              // vertex (1, 0, 0)
  EXPECT_NEAR(d.distance({0.1, 0.1, 0.2}), 0.1, 1e-15);       // inside: faces x = 0, y = 0
  EXPECT_NEAR(d.distance({1, 1, 1}), 2.0 / std::sqrt(3.0), 1e-15); // slanted face

  // A finer mesh: the hierarchy must agree with trying every face.
  const TriangleMesh sphere = test::icosphere(3);
  const MeshDistance tree(sphere);
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d q(rng() / 2147483648.0 - 1.0, rng() / 2147483648.0 - 1.0,
                            rng() / 2147483648.0 - 1.0);
    double brute = 1e300;
    for (std::size_t f = 0; f < sphere.numFaces(); ++f) {
      const Eigen::Vector3i& t = sphere.faces[f];
      const Eigen::Vector3d c = closestPointOnTriangle(q, sphere.vertices[t[0]],
                                                       sphere.vertices[t[1]], sphere.vertices[t[2]]);
      brute = std::min(brute, (c - q).norm());
    }
    EXPECT_DOUBLE_EQ(tree.distance(q), brute);
  }
  EXPECT_TRUE(std::isinf(MeshDistance().distance({0, 0, 0})));
}
