/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Tangential relaxation (src/geometry/tangential_relaxation.*) on a box whose surface is known:
 * vertices shaken along the box's sides get their even spacing back without leaving the sides,
 * the edges and corners stay where they are, and no vertex moves farther than allowed.
 */
#include "../src/geometry/tangential_relaxation.h"

#include "util/cloud_sampler.h"
#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using segmat::TriangleMesh;

constexpr double kSpacing = 1.0 / 12.0;

/// Distance of a vertex on the unit box [0, 1]³ from the box's surface, and how many of its
/// coordinates are 0 or 1 (1: inside a side, 2: on an edge, 3: a corner), to 1e-12.
int
boundCoordinates(const Eigen::Vector3d& v)
{
  int count = 0;
  for (int k = 0; k < 3; ++k)
    count += std::abs(v[k]) < 1e-12 || std::abs(v[k] - 1.0) < 1e-12;
  return count;
}

double
longestEdge(const TriangleMesh& mesh)
{
  double longest = 0.0;
  for (const Eigen::Vector3i& f : mesh.faces)
    for (int c = 0; c < 3; ++c)
      longest = std::max(longest, (mesh.vertices[f[c]] - mesh.vertices[f[(c + 1) % 3]]).norm());
  return longest;
}

/// Moves every vertex by N(0, sigma²) along the free coordinates of its side (those not 0 or 1),
/// so that it stays on the box: pure tangential noise.
void
shakeAlongSides(TriangleMesh& mesh, double sigma, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  for (Eigen::Vector3d& v : mesh.vertices) {
    if (boundCoordinates(v) != 1)
      continue;
    for (int k = 0; k < 3; ++k)
      if (std::abs(v[k]) > 1e-12 && std::abs(v[k] - 1.0) > 1e-12)
        v[k] = std::clamp(v[k] + sigma * segmat::test::standardNormal(rng), 0.02, 0.98);
  }
}

// 12 × 12 quads per side, inner vertices shaken by 0.3 spacings along their side: some edges
// grow to about twice the spacing's diagonal. Relaxed, the longest edge comes back close to the
// grid's own (the quad diagonal, 1.41 spacings), every vertex is still on its side of the box
// (its bound coordinates untouched, to rounding): vertices on the box's edges slide along
// their edge only, and the corners, whose faces turn by 90° in every direction, do not move.
TEST(TangentialRelaxation, ShakenBoxGetsEvenSpacingBackOnItsSides)
{
  const TriangleMesh grid = segmat::test::box({0, 0, 0}, {1, 1, 1}, 12);
  TriangleMesh mesh = grid;
  shakeAlongSides(mesh, 0.3 * kSpacing, 7);
  const double shaken = longestEdge(mesh);
  EXPECT_GT(shaken, 2.2 * kSpacing);
  segmat::detail::relaxTangentially(mesh.vertices, mesh.faces, 1.0, 5, 1);
  EXPECT_LT(longestEdge(mesh), 1.8 * kSpacing);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const int bound = boundCoordinates(grid.vertices[i]);
    ASSERT_EQ(boundCoordinates(mesh.vertices[i]), bound) << "vertex " << i;
    if (bound == 3)
      ASSERT_EQ(mesh.vertices[i], grid.vertices[i]) << "vertex " << i;
  }
}

// The same box without its top (z = 1) is open: the rim's vertices have neighbours on one side
// only and must stay, or the hole would widen; the other vertices still move.
TEST(TangentialRelaxation, RimOfAnOpenBoxStays)
{
  TriangleMesh mesh = segmat::test::box({0, 0, 0}, {1, 1, 1}, 12);
  std::vector<Eigen::Vector3i> kept;
  for (const Eigen::Vector3i& f : mesh.faces) {
    bool top = true;
    for (int c = 0; c < 3; ++c)
      top = top && std::abs(mesh.vertices[f[c]].z() - 1.0) < 1e-12;
    if (!top)
      kept.push_back(f);
  }
  mesh.faces = kept;
  shakeAlongSides(mesh, 0.3 * kSpacing, 13);
  const std::vector<Eigen::Vector3d> start = mesh.vertices;
  segmat::detail::relaxTangentially(mesh.vertices, mesh.faces, 1.0, 5, 1);
  int rim = 0, moved = 0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (std::abs(start[i].z() - 1.0) < 1e-12) {
      ++rim;
      EXPECT_EQ(mesh.vertices[i], start[i]) << "rim vertex " << i;
    }
    else if (mesh.vertices[i] != start[i])
      ++moved;
  }
  EXPECT_EQ(rim, 4 * 12 + 11 * 11); // the top's vertices: its rim (48) and its inner grid (unused)
  EXPECT_GT(moved, 5 * 11 * 11);     // at least the five sides' inner vertices
}

// No vertex ends farther than max_move from where it started, and the result does not depend on
// the thread count.
TEST(TangentialRelaxation, MovesAtMostTheAllowedDistanceOnAnyThreadCount)
{
  TriangleMesh mesh = segmat::test::box({0, 0, 0}, {1, 1, 1}, 12);
  shakeAlongSides(mesh, 0.3 * kSpacing, 11);
  const std::vector<Eigen::Vector3d> start = mesh.vertices;
  std::vector<Eigen::Vector3d> one = start, two = start;
  const double max_move = 0.1 * kSpacing;
  segmat::detail::relaxTangentially(one, mesh.faces, max_move, 5, 1);
  segmat::detail::relaxTangentially(two, mesh.faces, max_move, 5, 2);
  double largest = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i)
    largest = std::max(largest, (one[i] - start[i]).norm());
  EXPECT_LE(largest, max_move * (1.0 + 1e-12));
  EXPECT_GT(largest, 0.9 * max_move); // the shaken vertices wanted to move farther
  EXPECT_EQ(one, two);
}

} // namespace
