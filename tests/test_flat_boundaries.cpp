// Joining parts whose boundary crosses flat surface: the crossing curvature of two surface
// elements and the weighted-median rule of joinFlatBoundaries().
#include "../src/segmentation/flat_boundaries.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

using namespace segmat;
using detail::BoundaryEdge;

namespace {
/// A unit normal turned by \a degrees from +z towards +x.
Eigen::Vector3d
tilted(double degrees)
{
  const double a = degrees * M_PI / 180.0;
  return {std::sin(a), 0.0, std::cos(a)};
}
} // namespace

TEST(FlatBoundaries, CrossingCurvatureIsTheTurnOverTheDistance)
{
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0);
  // Coplanar: no turn.
  EXPECT_EQ(detail::crossingCurvature(a, tilted(0), b, tilted(0)), 0.0);
  // b's normal leans back towards a: the surface folds inwards (a valley), concave, +30° / 2.
  EXPECT_NEAR(detail::crossingCurvature(a, tilted(0), b, tilted(-30)), M_PI / 6.0 / 2.0, 1e-12);
  // Leaning away: a ridge, convex, the same magnitude with the sign turned.
  EXPECT_NEAR(detail::crossingCurvature(a, tilted(0), b, tilted(30)), -M_PI / 6.0 / 2.0, 1e-12);
  // Symmetric in the two elements, and free of the normals' lengths.
  EXPECT_NEAR(detail::crossingCurvature(b, 3.0 * tilted(-30), a, tilted(0)), M_PI / 12.0, 1e-12);
  // Nothing to measure: coincident centres, a zero (degenerate face's) or a NaN normal.
  EXPECT_TRUE(std::isnan(detail::crossingCurvature(a, tilted(0), a, tilted(-30))));
  EXPECT_TRUE(std::isnan(detail::crossingCurvature(a, Eigen::Vector3d::Zero(), b, tilted(-30))));
  EXPECT_TRUE(std::isnan(
      detail::crossingCurvature(a, Eigen::Vector3d::Constant(std::nan("")), b, tilted(0))));
}

TEST(FlatBoundaries, JoinsOnlyBoundariesFlatterThanTheBoundingSphere)
{
  // Six elements in a row labelled 0 0 1 1 2 2; diagonal 1, so the limit is |curvature| <= 2.
  const std::vector<int> labels{0, 0, 1, 1, 2, 2};
  // Boundary 0|1 curves at 1.9 (flatter than the bounding sphere), 1|2 at 2.1 (not).
  std::vector<BoundaryEdge> edges{{0, 1, 50.0, 1.0}, {1, 2, 1.9, 1.0}, {2, 3, -50.0, 1.0},
                                  {3, 4, -2.1, 1.0}, {4, 5, 0.0, 1.0}};
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 1.0), (std::vector<int>{0, 0, 1}));
  // Convex counts as curved: |−1.9| joins as 1.9 does, |−2.1| does not.
  edges[1].curvature = -1.9;
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 1.0), (std::vector<int>{0, 0, 1}));
  // The diagonal sets the scale: at diagonal 2 the boundary 0|1 curves at 3.8.
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 2.0), (std::vector<int>{0, 1, 2}));
  // Both flat: everything becomes one label.
  edges[3].curvature = 0.5;
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 1.0), (std::vector<int>{0, 0, 0}));
  // Edges of unknown curvature do not count: a boundary of degenerate faces only stays.
  EXPECT_EQ(detail::joinFlatBoundaries({0, 1}, 2, {{0, 1, std::nan(""), 1.0}}, 1.0),
            (std::vector<int>{0, 1}));
  EXPECT_EQ(detail::joinFlatBoundaries({0, 1, 0, 1}, 2,
                                       {{0, 1, std::nan(""), 5.0}, {2, 3, 50.0, 1.0}}, 1.0),
            (std::vector<int>{0, 1}));
  // No boundary, one label or no diagonal: nothing to join.
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, {}, 1.0), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(detail::joinFlatBoundaries({0, 0}, 1, {{0, 1, 0.0, 1.0}}, 1.0),
            (std::vector<int>{0}));
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 0.0), (std::vector<int>{0, 1, 2}));
}

TEST(FlatBoundaries, TheWeightedMedianDecides)
{
  // Two labels; their boundary has flat edges (curvature 0) and crease edges (curvature 100,
  // e.g. where a flat boundary meets a fold). The median, weighted by edge length, decides.
  const std::vector<int> labels{0, 1, 0, 1, 0, 1};
  std::vector<BoundaryEdge> edges{{0, 1, 0.0, 1.0}, {2, 3, 0.0, 1.0}, {4, 5, 100.0, 1.0}};
  // Two thirds of the boundary flat: joined, whatever the crease's curvature.
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 2, edges, 1.0), (std::vector<int>{0, 0}));
  // The crease edge three times as long as both flat ones together: kept apart.
  edges[2].weight = 6.0;
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 2, edges, 1.0), (std::vector<int>{0, 1}));
}

TEST(FlatBoundaries, FlattestFirstThenMeasuredAgain)
{
  // Labels 0 | 1 | 2 in a row, with 1|2 the flattest; after that join, the boundary between 0
  // and the joined {1, 2} is measured again over all of its edges: 0|1 alone is curved (3.0),
  // but 0|2 adds two flat edges, and the join {0, 1, 2} follows.
  const std::vector<int> labels{0, 1, 2, 0, 2, 0, 2};
  const std::vector<BoundaryEdge> edges{{0, 1, 3.0, 1.0},
                                        {1, 2, 0.0, 1.0},
                                        {3, 4, 1.0, 1.0},
                                        {5, 6, 1.0, 1.0}};
  // Before any join, 0|2 (median of 1.0 and 1.0) and 1|2 (0.0) are flat, 0|1 (3.0) is not;
  // 1|2 goes first, then {0} | {1, 2} has edges 3.0, 1.0, 1.0: median 1.0, joined.
  EXPECT_EQ(detail::joinFlatBoundaries(labels, 3, edges, 1.0), (std::vector<int>{0, 0, 0}));
  // Groups are numbered by their lowest label.
  const std::vector<int> apart{2, 0, 1};
  const std::vector<BoundaryEdge> one_flat{{0, 1, 5.0, 1.0}, {1, 2, 0.0, 1.0}};
  // Elements 0, 1, 2 carry labels 2, 0, 1: the flat boundary joins labels 0 and 1.
  EXPECT_EQ(detail::joinFlatBoundaries(apart, 3, one_flat, 1.0), (std::vector<int>{0, 0, 1}));
}

namespace {
/// A 51 × 51 grid of points 0.02 apart over the unit square of the xy-plane, each joined to its
/// 8 neighbours; points with x > 0.5 are label 1, the others label 0. With \a fold_degrees the
/// half x > 0.5 rises at that slope. Every normal is the surface's, tilted by a random turn of
/// \a noise_degrees (standard deviation per axis, fixed seed).
struct GridSurface
{
  std::vector<Eigen::Vector3d> positions, normals;
  std::vector<int> labels;
  std::vector<BoundaryEdge> edges;
};

GridSurface
gridSurface(double fold_degrees, double noise_degrees)
{
  constexpr int kSide = 51;
  constexpr double kStep = 0.02;
  const double slope = std::tan(fold_degrees * M_PI / 180.0);
  std::mt19937 random(7);
  std::normal_distribution<double> turn(0.0, noise_degrees * M_PI / 180.0);
  GridSurface s;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const double x = i * kStep, y = j * kStep;
      const bool raised = x > 0.5;
      s.positions.emplace_back(x, y, raised ? slope * (x - 0.5) : 0.0);
      const Eigen::Vector3d n =
          raised ? Eigen::Vector3d(-slope, 0.0, 1.0).normalized() : Eigen::Vector3d::UnitZ();
      const double tx = turn(random), ty = turn(random);
      s.normals.push_back((n + Eigen::Vector3d(tx, ty, 0.0)).normalized());
      s.labels.push_back(raised ? 1 : 0);
    }
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j)
      for (const auto& [di, dj] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}}) {
        const int k = i + di, l = j + dj;
        if (k < kSide && l >= 0 && l < kSide) {
          const int a = i * kSide + j, b = k * kSide + l;
          s.edges.push_back({a, b,
                             detail::crossingCurvature(s.positions[a], s.normals[a],
                                                       s.positions[b], s.normals[b]),
                             1.0});
        }
      }
  return s;
}

std::vector<BoundaryEdge>
measureSides(const GridSurface& s)
{
  detail::BoundaryGraph graph{s.edges, s.normals, {}, {}};
  detail::indexNeighbours(graph, static_cast<int>(s.labels.size()));
  return detail::measureSideCurvatures(graph, s.labels, s.positions);
}
} // namespace

TEST(FlatBoundaries, SideMeansTellNoisyNormalsFromAFold)
{
  const double diagonal = std::sqrt(2.0);
  // A flat boundary with normals turned by 3° of noise: pair by pair, neighbouring normals
  // differ by about 4° over 0.02, a curvature of about 5 diagonals⁻¹, and nothing is joined.
  GridSurface flat = gridSurface(0.0, 3.0);
  EXPECT_EQ(detail::joinFlatBoundaries(flat.labels, 2, flat.edges, diagonal),
            (std::vector<int>{0, 1}));
  // Between the means of the two sides the noise averages out: the boundary is flat.
  const std::vector<BoundaryEdge> measured = measureSides(flat);
  EXPECT_EQ(detail::joinFlatBoundaries(flat.labels, 2, measured, diagonal),
            (std::vector<int>{0, 0}));
  // The boundary's edges, and only those: straight and diagonal edges across x = 0.5.
  EXPECT_EQ(measured.size(), 3u * 51u - 2u);
  for (const BoundaryEdge& e : measured)
    EXPECT_NE(flat.labels[e.a], flat.labels[e.b]);

  // A 20° fold under the same noise stays a boundary: each side keeps its own plane.
  GridSurface fold = gridSurface(20.0, 3.0);
  EXPECT_EQ(detail::joinFlatBoundaries(fold.labels, 2, measureSides(fold), diagonal),
            (std::vector<int>{0, 1}));
}
