/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * The noise estimate and the denoising shared by the mesh and cloud paths, on synthetic inputs
 * whose noise is known.
 */
#include "../src/medial/surface_denoising.h"

#include "util/cloud_sampler.h"
#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using segmat::TriangleMesh;

/// Moves every vertex by N(0, sigma²) in each coordinate (absolute sigma).
void
addNoise(TriangleMesh& mesh, double sigma, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  for (Eigen::Vector3d& v : mesh.vertices)
    for (int k = 0; k < 3; ++k)
      v[k] += sigma * segmat::test::standardNormal(rng);
}

/// Mean distance of the vertices from the unit sphere.
double
sphereError(const std::vector<Eigen::Vector3d>& vertices)
{
  double sum = 0.0;
  for (const Eigen::Vector3d& v : vertices)
    sum += std::abs(v.norm() - 1.0);
  return sum / double(vertices.size());
}

// The vertices of a 10242-vertex unit sphere are ~0.038 apart; for vertex noise of σ the
// estimate is the noise along the normal, which has the same σ. The quadratic fit over two
// rings absorbs the sphere's curvature, so a clean sphere reads as (almost) no noise.
TEST(SurfaceDenoising, MeshNoiseEstimateRecoversKnownSigma)
{
  for (const double sigma : {0.004, 0.008, 0.016}) {
    TriangleMesh mesh = segmat::test::icosphere(5);
    addNoise(mesh, sigma, 7);
    std::vector<Eigen::Vector3d> vertices = mesh.vertices;
    const auto result =
        segmat::detail::denoiseMeshSurface(vertices, mesh.faces, 32, 5, 1, 4.0);
    EXPECT_NEAR(result.noise.sigma, sigma, 0.15 * sigma) << "sigma " << sigma;
  }
  TriangleMesh clean = segmat::test::icosphere(5);
  std::vector<Eigen::Vector3d> vertices = clean.vertices;
  const auto result = segmat::detail::denoiseMeshSurface(vertices, clean.faces, 32, 5, 1, 4.0);
  EXPECT_LT(result.noise.sigma, 0.0005);
}

// A clean sphere's triangles turn ~2° from their neighbours; noise of a fifth of the spacing
// tilts them by far more. Clean meshes are left bit for bit; noisy ones come closer to the
// sphere.
TEST(SurfaceDenoising, MeshIsSmoothedOnlyWhenNoisy)
{
  TriangleMesh clean = segmat::test::icosphere(5);
  std::vector<Eigen::Vector3d> vertices = clean.vertices;
  const auto kept = segmat::detail::denoiseMeshSurface(vertices, clean.faces, 32, 5, 1, 4.0);
  EXPECT_LT(kept.face_turn_degrees, 4.0);
  EXPECT_EQ(kept.passes, 0);
  EXPECT_EQ(vertices, clean.vertices);

  TriangleMesh noisy = clean;
  addNoise(noisy, 0.008, 11);
  vertices = noisy.vertices;
  const auto smoothed = segmat::detail::denoiseMeshSurface(vertices, noisy.faces, 32, 5, 1, 4.0);
  EXPECT_GT(smoothed.face_turn_degrees, 4.0);
  EXPECT_GE(smoothed.passes, 1);
  // Noise of 0.008 puts the vertices ~0.8 σ·sqrt(2/π) ≈ 0.0064 from the sphere on average.
  EXPECT_NEAR(sphereError(noisy.vertices), 0.0064, 0.0008);
  EXPECT_LT(sphereError(vertices), 0.5 * sphereError(noisy.vertices));
}

// Clouds: the 8-neighbour plane estimate, on 20 k points of a unit sphere (spacing ~0.025)
// with Gaussian noise of σ in each coordinate. The nearest neighbours of a displaced point are
// chosen in 3D, so they lean towards its side of the surface: the estimate reads low, the more
// so the larger σ is against the spacing (~0.8 σ at σ = 0.3 spacing, ~0.55 σ at 0.7 spacing).
// It still grows with σ, and the smoothing's residual band (1.5 estimates) stays near σ.
TEST(SurfaceDenoising, CloudNoiseEstimateRecoversKnownSigma)
{
  for (const double fraction : {0.002, 0.005}) {
    segmat::test::SampledCloud cloud = segmat::test::sphereCloud(20000, 3);
    segmat::test::addGaussianNoise(cloud, fraction, 5);
    const double sigma = fraction * 2.0 * std::sqrt(3.0); // the cube's diagonal
    std::vector<Eigen::Vector3f> points(cloud.points.begin(), cloud.points.end());
    const auto result = segmat::detail::denoiseCloudSurface(points, 32, 5, 1);
    EXPECT_GT(result.noise.sigma, 0.45 * sigma) << "fraction " << fraction;
    EXPECT_LT(result.noise.sigma, 0.95 * sigma) << "fraction " << fraction;
    EXPECT_GE(result.passes, 1);
  }
}

// Vertex noise moves a vertex along the normal as much as any other way; a smooth surface's
// denoised vertices should end much closer to it than that. The bilateral normal filter before
// the quadratic passes leaves them about a sixth of the noisy error from the unit sphere, at
// noise of a quarter and of half the spacing (0.038); the passes alone leave over a fifth
// (0.24 and 0.21).
TEST(SurfaceDenoising, NoisySphereComesBackToWithinASixthOfItsNoise)
{
  for (const double sigma : {0.25 * 0.038, 0.5 * 0.038}) {
    TriangleMesh mesh = segmat::test::icosphere(5);
    addNoise(mesh, sigma, 17);
    std::vector<Eigen::Vector3d> vertices = mesh.vertices;
    segmat::detail::denoiseMeshSurface(vertices, mesh.faces, 32, 5, 1, 4.0);
    EXPECT_LT(sphereError(vertices), 0.19 * sphereError(mesh.vertices)) << "sigma " << sigma;
  }
}

/// Root mean square distance of the points from the unit sphere.
double
sphereRms(const std::vector<Eigen::Vector3f>& points)
{
  double sum = 0.0;
  for (const Eigen::Vector3f& p : points)
    sum += std::pow(double(p.norm()) - 1.0, 2);
  return std::sqrt(sum / double(points.size()));
}

// A scan denser than the working cloud: 160 k noisy points of the unit sphere, thinned to every
// eighth. The working samples' own fits see 32 neighbours; fitted to the dense samples over the
// same area they see 8 times as many, so the fitted heights' variance falls about 8 times and
// their error about sqrt(8) ≈ 2.8 times, less what the fit's bias keeps.
TEST(SurfaceDenoising, DenseSamplesBringTheWorkingSamplesCloser)
{
  segmat::test::SampledCloud cloud = segmat::test::sphereCloud(160000, 3);
  segmat::test::addGaussianNoise(cloud, 0.002, 5); // σ ≈ 0.0069, about a third of the spacing
  const std::vector<Eigen::Vector3f> dense(cloud.points.begin(), cloud.points.end());
  std::vector<Eigen::Vector3f> working;
  for (std::size_t i = 0; i < dense.size(); i += 8)
    working.push_back(dense[i]);
  std::vector<Eigen::Vector3f> alone = working, helped = working;
  const auto a = segmat::detail::denoiseCloudSurface(alone, 32, 5, 1);
  const auto b = segmat::detail::denoiseCloudSurface(helped, 32, 5, 1, &dense);
  EXPECT_EQ(a.noise.sigma, b.noise.sigma); // the estimate reads the working samples either way
  EXPECT_GE(b.passes, 1);
  EXPECT_LT(sphereRms(alone), 0.6 * sphereRms(working));
  EXPECT_LT(sphereRms(helped), 0.5 * sphereRms(alone));
}

} // namespace
