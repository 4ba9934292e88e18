// Growing-cost terms (SEG-MAT §4.3) on hand-worked node pairs.
#include <segmat/geometry/medial_mesh.h>
#include "../src/segmentation/growing_cost.h"
#include <segmat/medial/mat_graph.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;

namespace {

const double kAsin01 = std::asin(0.1); // 0.1001674211615598

/** Graph of a medial mesh: nodes are the triangles, then the pure edges, in input order. */
MatGraph
graphOf(std::vector<Eigen::Vector3d> c, std::vector<double> r, std::vector<Eigen::Vector2i> e,
        std::vector<Eigen::Vector3i> t)
{
  return MatGraph::fromMedialMesh(MedialMesh(std::move(c), std::move(r), e, t));
}

double
costTerms(const MatGraph& g, int i, int j, double& c_r, double& c_theta, double& c_mp)
{
  c_r = radiusCost(g.node(i), g.node(j));
  c_theta = angleCost(g.node(i), g.node(j), g.centers());
  c_mp = primitiveCost(g.node(i), g.node(j), g.centers(), g.radii());
  return growingCost(g, i, j, GrowingCostWeights());
}

} // namespace

TEST(GrowingCost, CoplanarSlabsEqualRadii)
{
  // Unit square split along (1,2); all radii 0.5. Same plane, same tangent planes z = ±0.5.
  const MatGraph g = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {.5, .5, .5, .5}, {},
                             {{0, 1, 2}, {1, 3, 2}});
  double c_r, c_t, c_mp;
  EXPECT_EQ(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.0);
  EXPECT_EQ(c_r, 0.0);
  EXPECT_NEAR(c_t, 0.0, 1e-12); // not 1: the coplanar sign flip of the reference is fixed
  EXPECT_NEAR(c_mp, 0.0, 1e-12);
  // Same result when the second triangle is wound the other way.
  const MatGraph h = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {.5, .5, .5, .5}, {},
                             {{0, 1, 2}, {1, 2, 3}});
  EXPECT_NEAR(costTerms(h, 0, 1, c_r, c_t, c_mp), 0.0, 1e-12);
  EXPECT_NEAR(c_t, 0.0, 1e-12);
  EXPECT_NEAR(c_mp, 0.0, 1e-12);
}

TEST(GrowingCost, SlabsBentNinetyDegrees)
{
  // A in z = 0, B in y = 0, sharing edge (0,1). Reference vector from sphere 0 to the midpoint of
  // the centroids (1/3,1/3,0) and (1/3,0,1/3): (1/3,1/6,1/6); it turns n_A to +z and n_B to +y.
  // C_θ = acos(z·y)/π = 90/180 = 0.5. Equal radii 0.1: the sides are ±n, so both side pairs
  // meet at 90°: C_mp = (π/2 + π/2)/2π = 0.5. Cost = min(0 + 0.05·0.5, 1.5·0.5) = 0.025.
  const MatGraph g = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {.1, .1, .1, .1}, {},
                             {{0, 1, 2}, {0, 1, 3}});
  double c_r, c_t, c_mp;
  EXPECT_NEAR(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.025, 1e-12);
  EXPECT_EQ(c_r, 0.0);
  EXPECT_NEAR(c_t, 0.5, 1e-12);
  EXPECT_NEAR(c_mp, 0.5, 1e-12);
}

TEST(GrowingCost, SlabsFoldedOpenAndClosed)
{
  // A = (0,1,2) spans the half-plane towards +y of z = 0; B shares edge (0,1) (the x-axis).
  // Closed fold: B's third sphere at (0,1,1): the half-planes make a 45° dihedral, bend 135°.
  // ref = midpoint of the centroids (1/3,1/3,0), (1/3,1/3,1/3) minus sphere 0 = (1/3,1/3,1/6);
  // n_A → (0,0,1) (dot 1/6), n_B → (0,1,−1)/√2 (dot 1/(6√2)); n_A·n_B = −1/√2 → 135° → C_θ = 0.75.
  const MatGraph g = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 1}}, {.1, .1, .1, .1}, {},
                             {{0, 1, 2}, {0, 1, 3}});
  double c_r, c_t, c_mp;
  costTerms(g, 0, 1, c_r, c_t, c_mp);
  EXPECT_NEAR(c_t, 0.75, 1e-12);
  // Open fold: third sphere at (0,−1,1): 135° dihedral, bend 45° → C_θ = 0.25. With equal radii
  // the sides are ±n, so each side pair meets at 45° too: C_mp = (π/4 + π/4)/2π = 0.25.
  const MatGraph h = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 1}}, {.1, .1, .1, .1}, {},
                             {{0, 1, 2}, {0, 1, 3}});
  costTerms(h, 0, 1, c_r, c_t, c_mp);
  EXPECT_NEAR(c_t, 0.25, 1e-12);
  EXPECT_NEAR(c_mp, 0.25, 1e-12);
}

TEST(GrowingCost, RadiusTerm)
{
  MatNode a, b;
  a.mean_radius = 1.0;
  b.mean_radius = 2.0;
  EXPECT_EQ(radiusCost(a, b), 1.0); // 2/1 − 1
  EXPECT_EQ(radiusCost(b, a), 1.0);
  b.mean_radius = 1.015;
  EXPECT_NEAR(radiusCost(a, b), 0.015, 1e-15);
  a.mean_radius = 0.0;
  EXPECT_EQ(radiusCost(a, b), std::numeric_limits<double>::infinity());
  b.mean_radius = 0.0;
  EXPECT_EQ(radiusCost(a, b), 0.0);
}

// A tolerance takes its length off the radius difference before dividing: 1 against 1.015 with
// 0.01 of tolerance is 0.005, with 0.02 nothing; a difference far above it keeps its cost
// less the tolerance. growingCost passes the weights' tolerance on.
TEST(GrowingCost, RadiusToleranceTakesItsLengthOffTheDifference)
{
  MatNode a, b;
  a.mean_radius = 1.0;
  b.mean_radius = 1.015;
  EXPECT_NEAR(radiusCost(a, b, 0.01), 0.005, 1e-12);
  EXPECT_NEAR(radiusCost(b, a, 0.01), 0.005, 1e-12);
  EXPECT_EQ(radiusCost(a, b, 0.02), 0.0);
  b.mean_radius = 3.0;
  EXPECT_NEAR(radiusCost(a, b, 0.5), 1.5, 1e-12);
  EXPECT_EQ(radiusCost(a, b, 0.0), 2.0);
  a.mean_radius = 0.0;
  EXPECT_EQ(radiusCost(a, b, 0.5), std::numeric_limits<double>::infinity());
}

TEST(GrowingCost, LinearRadiusFieldGrowsThroughPrimitiveTerm)
{
  // r = 1 − 0.25·x on the plane z = 0: both slabs have the tangent planes (0.25, 0, ±0.968)·x = 1.
  // r̄_A = (1 + 0.5 + 1)/3 = 5/6, r̄_B = (0.5 + 1 + 0.5)/3 = 2/3: C_r = (5/6)/(2/3) − 1 = 0.25,
  // C_θ = 0, C_mp = 0 → cost = min(0.25, 0) = 0: a wedge grows although its radius changes.
  const MatGraph g = graphOf({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}}, {1.0, 0.5, 1.0, 0.5},
                             {}, {{0, 1, 2}, {1, 3, 2}});
  double c_r, c_t, c_mp;
  EXPECT_NEAR(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.0, 1e-12);
  EXPECT_NEAR(c_r, 0.25, 1e-12);
  EXPECT_NEAR(c_t, 0.0, 1e-12);
  EXPECT_NEAR(c_mp, 0.0, 1e-12);
  // Without the primitive term the radius change stops growth: cost = C_r + α·0 = 0.25.
  GrowingCostWeights w;
  w.use_primitive_term = false;
  EXPECT_NEAR(growingCost(g, 0, 1, w), 0.25, 1e-12);
}

TEST(GrowingCost, ConeNeck)
{
  // Straight tube along x: radii 0.5, 0.4 (joint), 0.5 at x = −1, 0, 1. β = π;
  // φ_k = sign(0.4 − 0.5)·asin(0.1/1) = −0.1001674. A = B = (π − 0.2003348)/π = 0.9362314 < 1,
  // both below 1 → C_mp = (A + B)/2 = 1 + (φ0 + φ1)/π = 1 − 0.0637686 = 0.9362314.
  // C_r = 0.45/0.45 − 1 = 0 and C_θ = 0: the cost is 0, C_mp cannot lower it.
  const MatGraph g = graphOf({{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}}, {0.5, 0.4, 0.5}, {{0, 1}, {1, 2}},
                             {});
  double c_r, c_t, c_mp;
  EXPECT_EQ(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.0);
  EXPECT_NEAR(c_mp, 1.0 - 2.0 * kAsin01 / M_PI, 1e-12);
  EXPECT_NEAR(c_mp, 0.9362314391414801, 1e-12);
  EXPECT_NEAR(c_t, 0.0, 1e-12);
}

TEST(GrowingCost, ConeBulgeAndStraightContinuation)
{
  double c_r, c_t, c_mp;
  // Cylinder: A = B = 1 exactly → C_mp = 0; straight → C_θ = 0.
  const MatGraph cyl = graphOf({{-1, 0, 0}, {0, 0, 0}, {2, 0, 0}}, {0.3, 0.3, 0.3},
                               {{0, 1}, {1, 2}}, {});
  EXPECT_EQ(costTerms(cyl, 0, 1, c_r, c_t, c_mp), 0.0);
  EXPECT_NEAR(c_mp, 0.0, 1e-15);
  // Straight cone, radius linear in x (0.5, 0.4, 0.3): φ0 = −asin 0.1, φ1 = +asin 0.1, A = B = 1
  // up to rounding → C_mp = 0 (the 1e-9 flat tolerance keeps it from jumping to ½).
  // C_r = 0.45/0.35 − 1 = 2/7, so the cost is min(2/7, 1.5·0) = 0.
  const MatGraph cone = graphOf({{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}}, {0.5, 0.4, 0.3},
                                {{0, 1}, {1, 2}}, {});
  EXPECT_NEAR(costTerms(cone, 0, 1, c_r, c_t, c_mp), 0.0, 1e-12);
  EXPECT_NEAR(c_r, 2.0 / 7.0, 1e-12);
  EXPECT_NEAR(c_mp, 0.0, 1e-12);
  // Bulge (joint larger): φ = +asin 0.1 each, A = B = 1.0637686 ≥ 1 → C_mp = (A+B−2)/2 = 0.0637686.
  const MatGraph bulge = graphOf({{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}}, {0.5, 0.6, 0.5},
                                 {{0, 1}, {1, 2}}, {});
  costTerms(bulge, 0, 1, c_r, c_t, c_mp);
  EXPECT_NEAR(c_mp, 2.0 * kAsin01 / M_PI, 1e-12);
}

TEST(GrowingCost, ConesBentNinetyDegrees)
{
  // Joint at the origin, far ends on +x and +y, equal radii. C_θ = (180 − 90)/180 = 0.5.
  // β = π/2, φ = 0: A = 0.5 < 1, B = 1.5 → exactly one below 1 → C_mp = (A+B−1)/2 = 0.5.
  // Cost = min(0 + 0.05·0.5, 1.5·0.5) = 0.025 > δ0 = 0.015: an elbow stops growth.
  const MatGraph g = graphOf({{1, 0, 0}, {0, 0, 0}, {0, 1, 0}}, {0.2, 0.2, 0.2}, {{0, 1}, {1, 2}},
                             {});
  double c_r, c_t, c_mp;
  EXPECT_NEAR(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.025, 1e-12);
  EXPECT_NEAR(c_t, 0.5, 1e-12);
  EXPECT_NEAR(c_mp, 0.5, 1e-12);
}

TEST(GrowingCost, LineAgainstTriangle)
{
  // Triangle (0,1,2) in z = 0; pure edge (0,3) leaving along x in the plane, pure edge (0,4)
  // along z. In-plane line: 180° − acos(|d·n|) = 180 − 90 = 90° → C_θ = 0.5. Perpendicular
  // line: 180 − 0 = 180° → C_θ = 1. C_mp (undefined in the reference) = 1.
  // Equal radii: cost = min(0 + 0.05·C_θ, 1.5).
  const MatGraph g = graphOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}},
                             {.2, .2, .2, .2, .2}, {{0, 3}, {0, 4}}, {{0, 1, 2}});
  ASSERT_EQ(g.numNodes(), 3u);
  double c_r, c_t, c_mp;
  EXPECT_NEAR(costTerms(g, 0, 1, c_r, c_t, c_mp), 0.025, 1e-12);
  EXPECT_NEAR(c_t, 0.5, 1e-12);
  EXPECT_EQ(c_mp, 1.0);
  EXPECT_NEAR(costTerms(g, 2, 0, c_r, c_t, c_mp), 0.05, 1e-12);
  EXPECT_NEAR(c_t, 1.0, 1e-12);
}

TEST(GrowingCost, PointPairsUseUndirectedNormals)
{
  // Medial points (cloud path): C_θ = acos(|n_a·n_b|)/π, no primitive term.
  MatNode a, b;
  a.v = Eigen::Vector3i(0, -1, -1);
  b.v = Eigen::Vector3i(1, -1, -1);
  a.mean_radius = 1.0;
  b.mean_radius = 1.01;
  a.normal = Eigen::Vector3d(0, 0, 1);
  b.normal = Eigen::Vector3d(std::sqrt(3.0) / 2, 0, 0.5); // 60° → 1/3
  a.centroid = Eigen::Vector3d(0, 0, 0);
  b.centroid = Eigen::Vector3d(1, 0, 0);
  const std::vector<Eigen::Vector3d> centers{a.centroid, b.centroid};
  EXPECT_NEAR(angleCost(a, b, centers), 1.0 / 3.0, 1e-12);
  b.normal = -b.normal; // PCA normals have no sign
  EXPECT_NEAR(angleCost(a, b, centers), 1.0 / 3.0, 1e-12);
  const MatGraph g(centers, {1.0, 1.01}, {a, b}, {{1}});
  EXPECT_FALSE(g.hasPrimitives());
  GrowingCostWeights w;
  w.use_primitive_term = false;
  // 0.01 + 0.05/3 = 0.0266667
  EXPECT_NEAR(growingCost(g, 0, 1, w), 0.01 + 0.05 / 3.0, 1e-12);
  EXPECT_EQ(primitiveCost(a, b, centers, {1.0, 1.01}), 1.0);
}

TEST(GrowingCost, NaNNeverGrows)
{
  const double inf = std::numeric_limits<double>::infinity();
  GrowingCostWeights w;
  EXPECT_EQ(combineGrowingCost(NAN, 0.0, 1.0, w), inf);
  EXPECT_EQ(combineGrowingCost(0.0, 0.0, NAN, w), inf);
  EXPECT_EQ(combineGrowingCost(0.0, 0.0, 0.5, w), 0.0);
  w.use_primitive_term = false;
  EXPECT_EQ(combineGrowingCost(0.0, NAN, 0.0, w), inf);
  EXPECT_EQ(combineGrowingCost(0.0, 0.0, NAN, w), 0.0); // the unused term does not matter
  // NaN data: radius, then normal.
  MatNode a, b;
  a.mean_radius = 0.1;
  b.mean_radius = NAN;
  EXPECT_TRUE(std::isnan(radiusCost(a, b)));
  EXPECT_TRUE(std::isnan(radiusCost(b, a)));
  b.mean_radius = 0.1;
  a.normal = Eigen::Vector3d(0, 0, 1);
  b.normal = Eigen::Vector3d(NAN, 0, 0);
  EXPECT_TRUE(std::isnan(angleCost(a, b, {})));
}

TEST(GrowingCost, Thresholds)
{
  const std::vector<double> ratio{0.0, 4.0, 3.5};
  EXPECT_EQ(growingThreshold(0.015, 0, 0, ratio), 0.015);
  EXPECT_NEAR(growingThreshold(0.015, 1, 1, ratio), 0.06, 1e-15);
  EXPECT_NEAR(growingThreshold(0.015, 2, 2, ratio), 0.0525, 1e-15);
  EXPECT_EQ(growingThreshold(0.015, 0, 1, ratio), 0.0);
  EXPECT_EQ(growingThreshold(0.015, 2, 1, ratio), 0.0);
  EXPECT_EQ(growingThreshold(0.015, 7, 7, ratio), 0.015); // unknown tag: bulky
}
