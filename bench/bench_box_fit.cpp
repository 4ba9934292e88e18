/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_box_fit: how close computeMinimumVolumeBox gets to the known minimal box of test shapes,
 * each in 50 random orientations, beside the principal-axes box (computePcaBox):
 *  - box 3 × 1.5 × 0.5 (optimum 2.25);
 *  - 48-gon prism of circumradius 1 and length 4 (optimum 4 cos²(π/48) · 4: a side of the
 *    minimal rectangle of a polygon is flush with an edge);
 *  - L of a 4 × 1 × 1 and a 1 × 3 × 1 bar (optimum 16);
 *  - regular tetrahedron of edge √2 (optimum 1: the unit cube through its vertices, whose faces
 *    each hold one tetrahedron edge — no face flush with a hull face).
 * Prints the mean and worst ratio volume / optimum and the mean seconds per box.
 *
 *   build/bin/bench_box_fit
 */
#include "bench_common.h"

#include <segmat/geometry/oriented_box.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {
using Points = std::vector<Eigen::Vector3d>;

Points
cuboid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
  Points p;
  for (int k = 0; k < 8; ++k)
    p.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  return p;
}

Points
prism(int sides, double radius, double length)
{
  const double kPi = 3.14159265358979323846;
  Points p;
  for (int i = 0; i < sides; ++i)
    for (const double z : {-0.5 * length, 0.5 * length})
      p.emplace_back(radius * std::cos(2 * kPi * i / sides), radius * std::sin(2 * kPi * i / sides),
                     z);
  return p;
}
} // namespace

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  const double kPi = 3.14159265358979323846;
  Points l = cuboid({0, 0, 0}, {4, 1, 1});
  for (const Eigen::Vector3d& p : cuboid({0, 1, 0}, {1, 4, 1}))
    l.push_back(p);
  const struct
  {
    const char* name;
    Points points;
    double optimum;
  } shapes[] = {
      {"box", cuboid({0, 0, 0}, {3, 1.5, 0.5}), 2.25},
      {"prism48", prism(48, 1.0, 4.0), 16.0 * std::pow(std::cos(kPi / 48), 2)},
      {"L", l, 16.0},
      {"tetrahedron", {{0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}}, 1.0},
  };
  std::mt19937 rng(2024);
  std::normal_distribution<double> normal;
  std::printf("%-12s %9s %9s %9s %9s %10s\n", "shape", "mean", "worst", "pca_mean", "pca_worst",
              "seconds");
  for (const auto& shape : shapes) {
    double sum = 0, worst = 0, pca_sum = 0, pca_worst = 0, seconds = 0;
    const int runs = 50;
    for (int r = 0; r < runs; ++r) {
      const Eigen::Matrix3d rotation =
          Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
              .normalized()
              .toRotationMatrix();
      Points points;
      for (const Eigen::Vector3d& p : shape.points)
        points.push_back(rotation * p + Eigen::Vector3d(3, -1, 2));
      const auto start = std::chrono::steady_clock::now();
      const double ratio = segmat::computeMinimumVolumeBox(points).volume() / shape.optimum;
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double pca = segmat::computePcaBox(points).volume() / shape.optimum;
      sum += ratio;
      worst = std::max(worst, ratio);
      pca_sum += pca;
      pca_worst = std::max(pca_worst, pca);
    }
    std::printf("%-12s %9.5f %9.5f %9.4f %9.4f %10.6f\n", shape.name, sum / runs, worst,
                pca_sum / runs, pca_worst, seconds / runs);
  }
  return 0;
}
