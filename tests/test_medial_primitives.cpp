// Slab tangent planes and cone slopes on hand-worked configurations.
#include <segmat/geometry/medial_primitives.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace segmat;

TEST(MedialPrimitives, EqualRadiiSlabSidesAreOffsetPlanes)
{
  const Eigen::Vector3d c[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double r[3] = {0.5, 0.5, 0.5};
  SlabSides s;
  ASSERT_TRUE(computeSlabSides(c, r, Eigen::Vector3d(0, 0, 2), s));
  EXPECT_TRUE(s.normal[0].isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(s.normal[1].isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_TRUE(s.tangent[0][1].isApprox(Eigen::Vector3d(1, 0, 0.5)));
  EXPECT_TRUE(s.tangent[1][2].isApprox(Eigen::Vector3d(0, 1, -0.5)));
  // The orientation only decides which side is side 0.
  ASSERT_TRUE(computeSlabSides(c, r, Eigen::Vector3d(0, 0, -1), s));
  EXPECT_TRUE(s.normal[0].isApprox(Eigen::Vector3d(0, 0, -1)));
}

TEST(MedialPrimitives, LinearRadiusSlabSidesTilt)
{
  // r = 1 − 0.25·x in the plane z = 0. A side normal m solves m·(c1−c0) = r0−r1 → 2·m_x = 0.5,
  // m·(c2−c0) = r0−r2 → 2·m_y = 0, so m = (0.25, 0, ±sqrt(1 − 1/16)) = (0.25, 0, ±0.9682458).
  const Eigen::Vector3d c[3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const double r[3] = {1.0, 0.5, 1.0};
  SlabSides s;
  ASSERT_TRUE(computeSlabSides(c, r, Eigen::Vector3d(0, 0, 1), s));
  EXPECT_NEAR(s.normal[0].x(), 0.25, 1e-12);
  EXPECT_NEAR(s.normal[0].y(), 0.0, 1e-12);
  EXPECT_NEAR(s.normal[0].z(), 0.9682458365518543, 1e-12);
  EXPECT_NEAR(s.normal[1].z(), -0.9682458365518543, 1e-12);
  // Every tangent point lies on its plane m·x = m·c_k + r_k = 0 + 1 = 1.
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(s.normal[0].dot(s.tangent[0][k]), 1.0, 1e-12);
}

TEST(MedialPrimitives, SlabFailureCases)
{
  SlabSides s;
  const Eigen::Vector3d n(0, 0, 1);
  // Coincident centres.
  const Eigen::Vector3d c1[3] = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}};
  const double r1[3] = {1, 1, 1};
  EXPECT_FALSE(computeSlabSides(c1, r1, n, s));
  // Collinear centres.
  const Eigen::Vector3d c2[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_FALSE(computeSlabSides(c2, r1, n, s));
  // A sphere swallowing another: |r0 − r1| = 3 > |c1 − c0| = 1, no common tangent plane.
  const Eigen::Vector3d c3[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double r3[3] = {4, 1, 4};
  EXPECT_FALSE(computeSlabSides(c3, r3, n, s));
  // NaN radius.
  const double r4[3] = {1, NAN, 1};
  EXPECT_FALSE(computeSlabSides(c3, r4, n, s));
}

TEST(MedialPrimitives, ConeSlope)
{
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0);
  EXPECT_NEAR(coneSlopeAngle(a, 0.5, b, 0.4), std::asin(0.1), 1e-15);
  EXPECT_NEAR(coneSlopeAngle(a, 0.4, b, 0.5), -std::asin(0.1), 1e-15);
  EXPECT_EQ(coneSlopeAngle(a, 0.3, b, 0.3), 0.0);      // sign(0) = 0, no 0/0
  EXPECT_NEAR(coneSlopeAngle(a, 3.0, b, 0.5), M_PI / 2, 1e-15); // clamped asin
  EXPECT_EQ(coneSlopeAngle(a, 0.3, a, 0.5), 0.0);      // coincident centres
  EXPECT_NEAR(clampedAcos(1.0 + 1e-12), 0.0, 0.0);
  EXPECT_NEAR(clampedAcos(-1.0 - 1e-12), M_PI, 0.0);
}
