/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Bilateral normal filtering (src/geometry/bilateral_normal_filter.*) on shapes whose surface is
 * known: a box keeps its flat faces and sharp edges, a sphere gets closer to the sphere, a clean
 * box does not move.
 */
#include "../src/geometry/bilateral_normal_filter.h"

#include "util/cloud_sampler.h"
#include "util/synthetic_mesh.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using segmat::TriangleMesh;

/// Moves every vertex by N(0, sigma²) in each coordinate (absolute sigma).
void
addNoise(TriangleMesh& mesh, double sigma, std::uint32_t seed)
{
  segmat::test::addGaussianNoise(mesh, sigma / mesh.boundingBoxDiagonal(), seed);
}

/// Per face of a box, the angle (degrees) between its normal and the closest axis.
std::vector<double>
axisAngles(const TriangleMesh& mesh)
{
  std::vector<double> angles;
  for (const Eigen::Vector3i& f : mesh.faces) {
    const Eigen::Vector3d n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                                  .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                                  .normalized();
    const double largest = n.cwiseAbs().maxCoeff();
    angles.push_back(std::acos(std::min(1.0, largest)) * 180.0 / M_PI);
  }
  return angles;
}

double
share(const std::vector<double>& values, double below)
{
  return double(std::count_if(values.begin(), values.end(), [&](double v) { return v < below; })) /
         double(values.size());
}

// A unit box of 12 × 12 quads per side (spacing 1/12) with vertex noise of a fifth of the
// spacing: the faces tilt by ~10–20°, few lie within 5° of their side's axis. Filtered, the
// faces of each side agree again and the sides still meet at right angles: nearly all faces
// are within 5° of an axis. A plain average would bend the sides into each other along the
// edges; the range weight keeps the 90° turns.
TEST(BilateralNormalFilter, NoisyBoxGetsFlatSidesAndSharpEdgesBack)
{
  TriangleMesh mesh = segmat::test::box({0, 0, 0}, {1, 1, 1}, 12);
  addNoise(mesh, 0.2 / 12.0, 3);
  const double noisy = share(axisAngles(mesh), 5.0);
  EXPECT_LT(noisy, 0.4);
  const auto result =
      segmat::detail::bilateralNormalFilter(mesh.vertices, mesh.faces, 0.35, 20, 0.5, 10, 1);
  EXPECT_GE(result.normal_iterations, 1);
  // Adjacent centroids are 0.47 (same quad) to 0.75 (next quad) spacings apart.
  EXPECT_GT(result.spatial_sigma, 0.4 / 12.0);
  EXPECT_LT(result.spatial_sigma, 0.8 / 12.0);
  EXPECT_GT(share(axisAngles(mesh), 5.0), 0.9);
}

// A box whose faces are already flat hardly moves: every neighbour's normal equals the face's
// or differs by 90°, whose range weight is e^-8 ≈ 3e-4, and the vertices already lie on their
// faces' planes.
TEST(BilateralNormalFilter, CleanBoxStaysWhereItIs)
{
  TriangleMesh mesh = segmat::test::box({0, 0, 0}, {1, 1, 1}, 6);
  const std::vector<Eigen::Vector3d> before = mesh.vertices;
  segmat::detail::bilateralNormalFilter(mesh.vertices, mesh.faces, 0.35, 20, 0.5, 10, 1);
  double largest = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
    largest = std::max(largest, (mesh.vertices[i] - before[i]).norm());
  EXPECT_LT(largest, 2e-4);
}

// A noisy unit sphere gets closer to the sphere (mean distance of the vertices to it).
TEST(BilateralNormalFilter, NoisySphereGetsCloserToTheSphere)
{
  TriangleMesh mesh = segmat::test::icosphere(4);
  addNoise(mesh, 0.01, 5);
  auto error = [&] {
    double sum = 0.0;
    for (const Eigen::Vector3d& v : mesh.vertices)
      sum += std::abs(v.norm() - 1.0);
    return sum / double(mesh.vertices.size());
  };
  const double noisy = error();
  segmat::detail::bilateralNormalFilter(mesh.vertices, mesh.faces, 0.35, 20, 0.5, 10, 1);
  EXPECT_LT(error(), 0.6 * noisy);
}

} // namespace
