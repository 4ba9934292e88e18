// Which medial spheres touch the surface over at least a right angle (the spike test of the
// merging on noisy clouds, MatRegionGrowing::setSurfaceSamples).
#include "../src/segmentation/spanning_spheres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;

namespace {

/** Two half-planes through the x axis, each at φ/2 from the +y axis (a wedge of interior angle
 * φ), sampled every 0.01 over x in [-0.5, 0.5] and 1 along each. */
std::vector<Eigen::Vector3d>
wedge(double phi_degrees)
{
  const double half = phi_degrees * M_PI / 360.0;
  std::vector<Eigen::Vector3d> samples;
  for (int i = -50; i <= 50; ++i)
    for (int j = 0; j <= 100; ++j)
      for (const double side : {-1.0, 1.0})
        samples.emplace_back(0.01 * i, 0.01 * j * std::cos(half),
                             side * 0.01 * j * std::sin(half));
  return samples;
}

/** The ball centred on the wedge's bisector at 0.5 from its edge that touches both planes: its
 * touching points are 180° − φ apart as seen from its centre. */
char
wedgeBallSpans(double phi_degrees)
{
  const double radius = 0.5 * std::sin(phi_degrees * M_PI / 360.0);
  return detail::spheresSpanningRightAngle({Eigen::Vector3d(0.0, 0.5, 0.0)}, {radius},
                                           wedge(phi_degrees), 0.005)[0];
}

} // namespace

TEST(SpanningSpheres, EdgeSheetSpheresSpanWhenTheirTouchingPointsAreARightAngleApart)
{
  EXPECT_EQ(wedgeBallSpans(60.0), 1);  // touching points 120° apart
  EXPECT_EQ(wedgeBallSpans(80.0), 1);  // 100°
  EXPECT_EQ(wedgeBallSpans(100.0), 0); // 80°
  EXPECT_EQ(wedgeBallSpans(140.0), 0); // 40°: a blunt crease, or the flanks of a bump
}

TEST(SpanningSpheres, TubeAxisSpansAndABallOnAPlaneDoesNot)
{
  std::vector<Eigen::Vector3d> samples;
  for (int i = -50; i <= 50; ++i)
    for (int k = 0; k < 120; ++k) {
      const double a = 2.0 * M_PI * k / 120.0;
      samples.emplace_back(0.01 * i, 0.3 * std::cos(a), 0.3 * std::sin(a)); // tube, radius 0.3
      samples.emplace_back(0.01 * i, 0.01 * (k - 60), -1.0);                // plane z = -1
    }
  const std::vector<char> spans = detail::spheresSpanningRightAngle(
      {Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, -0.8)}, {0.3, 0.2}, samples, 0.005);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0], 1); // touches a ring
  EXPECT_EQ(spans[1], 0); // touches one disc around its foot point
}

TEST(SpanningSpheres, WhatCannotBeToldCountsAsSpanning)
{
  const std::vector<Eigen::Vector3d> samples = wedge(140.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double radius = 0.5 * std::sin(140.0 * M_PI / 360.0);
  const std::vector<Eigen::Vector3d> centers{Eigen::Vector3d(0.0, 0.5, 0.0),
                                             Eigen::Vector3d(0.0, 5.0, 0.0),
                                             Eigen::Vector3d(nan, 0.5, 0.0),
                                             Eigen::Vector3d(0.0, 0.5, 0.0)};
  const std::vector<double> radii{radius, radius, radius, nan};
  // The spike-like ball is flagged; one touching nothing, a non-finite one are not.
  EXPECT_EQ(detail::spheresSpanningRightAngle(centers, radii, samples, 0.005),
            (std::vector<char>{0, 1, 1, 1}));
  // Without a tolerance or samples nothing is flagged.
  EXPECT_EQ(detail::spheresSpanningRightAngle(centers, radii, samples, 0.0),
            (std::vector<char>(4, 1)));
  EXPECT_EQ(detail::spheresSpanningRightAngle(centers, radii, {}, 0.005),
            (std::vector<char>(4, 1)));
  // A non-finite sample is left out of the touching set.
  std::vector<Eigen::Vector3d> with_nan = samples;
  with_nan.emplace_back(nan, 0.0, 0.0);
  EXPECT_EQ(detail::spheresSpanningRightAngle(centers, radii, with_nan, 0.005),
            (std::vector<char>{0, 1, 1, 1}));
}
