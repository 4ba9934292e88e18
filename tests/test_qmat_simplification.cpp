// Q-MAT simplification: the sphere quadric, the stability ratio, cone tangent planes, and the
// collapse loop on medial meshes with a known answer; MedialMeshEstimation on known shapes.
#include <segmat/geometry/cone_tangent_plane.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/io/ma.h>
#include <segmat/io/off.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/medial/qmat_simplification.h>
#include <segmat/medial/sphere_quadric.h>

#include "util/synthetic_medial.h"
#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace segmat;
using segmat::test::bettiNumbers;

namespace {

MedialMesh::ConstPtr
share(MedialMesh m)
{
  return std::make_shared<const MedialMesh>(std::move(m));
}

/// Runs Q-MAT with the given targets; fails the test when compute() fails.
std::pair<MedialMesh, MedialMesh>
simplify(const MedialMesh& in, int base, int structured, bool preserve_cavities = false)
{
  QmatSimplification q;
  q.setInputMat(share(in));
  q.setBaseTarget(base);
  q.setStructuredTarget(structured);
  q.setPreserveCavitiesFlag(preserve_cavities);
  MedialMesh b, s;
  EXPECT_TRUE(q.compute(b, s));
  return {b, s};
}

double
totalTriangleArea(const MedialMesh& m)
{
  double area = 0.0;
  for (const Eigen::Vector3i& t : m.triangles())
    area += 0.5 * (m.centers()[t[1]] - m.centers()[t[0]])
                      .cross(m.centers()[t[2]] - m.centers()[t[0]])
                      .norm();
  return area;
}

/// A unit sheet of n × n squares (test::planarSheet, radius 0.1), \a islands separate small
/// triangles 0.2 apart along x from 2 (the islands of a noisy Voronoi MAT), and a sphere without
/// an edge at each of \a isolated_x.
MedialMesh
sheetWithIslands(int n, int islands, const std::vector<double>& isolated_x = {})
{
  const MedialMesh sheet = test::planarSheet(n, 1.0, 0.1);
  std::vector<Eigen::Vector3d> centers = sheet.centers();
  std::vector<double> radii = sheet.radii();
  std::vector<Eigen::Vector3i> triangles = sheet.triangles();
  for (int i = 0; i < islands; ++i) {
    const int first = static_cast<int>(centers.size());
    const Eigen::Vector3d corner(2.0 + 0.2 * i, 0.0, 0.0);
    for (const Eigen::Vector3d offset : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.05, 0, 0),
                                         Eigen::Vector3d(0, 0.05, 0)}) {
      centers.push_back(corner + offset);
      radii.push_back(0.01);
    }
    triangles.emplace_back(first, first + 1, first + 2);
  }
  for (const double x : isolated_x) {
    centers.emplace_back(x, 0.0, 0.0);
    radii.push_back(0.02);
  }
  return MedialMesh(centers, radii, {}, triangles);
}

bool
sameMat(const MedialMesh& a, const MedialMesh& b)
{
  return a.centers() == b.centers() && a.radii() == b.radii() && a.edges() == b.edges() &&
         a.triangles() == b.triangles();
}

} // namespace

TEST(SphereQuadric, SinglePlaneByHand)
{
  // Plane z = 0.5 touching the sphere (0, 0, 0; 0.5) from outside, normal +z.
  const SphereQuadric q = SphereQuadric::fromPlane({0, 0, 1}, {0, 0, 0, 0.5});
  EXPECT_NEAR(q({0, 0, 0.2, 0.3}), 0.0, 1e-15);   // tangent from inside
  EXPECT_NEAR(q({5, -3, 0.2, 0.3}), 0.0, 1e-15);  // anywhere along the plane
  EXPECT_NEAR(q({0, 0, 0.2, 0.4}), 0.01, 1e-15);  // pokes through by 0.1
  EXPECT_NEAR(q({0, 0, -1.0, 0.25}), 1.5625, 1e-14); // 1.25 short of the plane
  const SphereQuadric w = SphereQuadric::fromPlane({0, 0, 1}, {0, 0, 0, 0.5}, 3.0);
  EXPECT_NEAR(w({0, 0, 0.2, 0.4}), 0.03, 1e-15);
  Eigen::Vector4d m(7, 7, 7, 7);
  EXPECT_FALSE(q.minimiser(m)); // one plane: a 3-parameter family of minimisers
  EXPECT_FALSE(q.invertible());
  EXPECT_EQ(m, Eigen::Vector4d(7, 7, 7, 7));
}

TEST(SphereQuadric, CubeFacesGiveTheInscribedSphere)
{
  // The six faces of [-1, 1]³ as outward planes: the optimal sphere is the inscribed one.
  SphereQuadric q;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = sign;
      // A sphere touching that face: centre 0.75 inside, radius 0.25.
      Eigen::Vector4d touching = Eigen::Vector4d::Zero();
      touching[axis] = 0.75 * sign;
      touching[3] = 0.25;
      q += SphereQuadric::fromPlane(n, touching);
    }
  Eigen::Vector4d m;
  ASSERT_TRUE(q.minimiser(m));
  EXPECT_TRUE(m.isApprox(Eigen::Vector4d(0, 0, 0, 1), 1e-12)) << m.transpose();
  EXPECT_NEAR(q(m), 0.0, 1e-12);
  EXPECT_NEAR(q({0, 0, 0, 0.5}), 6 * 0.25, 1e-12); // 0.5 short of all six faces
}

TEST(StabilityRatio, ByHand)
{
  EXPECT_DOUBLE_EQ(stabilityRatio({0, 0, 0, 1}, {2, 0, 0, 1.5}), 0.75); // (2 − 0.5) / 2
  EXPECT_DOUBLE_EQ(stabilityRatio({0, 0, 0, 1}, {0, 3, 4, 1}), 1.0);   // equal radii
  EXPECT_DOUBLE_EQ(stabilityRatio({0, 0, 0, 1}, {0.1, 0, 0, 0.5}), 0.0); // nested: a spike
  EXPECT_DOUBLE_EQ(stabilityRatio({1, 1, 1, 1}, {1, 1, 1, 2}), 0.0);   // same centre
  EXPECT_DOUBLE_EQ(stabilityRatio({0, 0, 0, 2}, {0, 0, 1, 1}), 0.0);   // internally tangent
}

TEST(TangentPlanes, ConeAllAround)
{
  const Eigen::Vector4d s0(1, 2, 3, 1), s1(1, 2, 5, 2); // axis +z, radius slope 0.5
  for (int i = 0; i < 8; ++i) {
    Eigen::Vector3d n;
    ASSERT_TRUE(coneTangentPlane(s0, s1, 0.7 * i, n));
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    EXPECT_NEAR(n.z(), -0.5, 1e-14);
    EXPECT_NEAR(n.dot(s0.head<3>()) + s0[3], n.dot(s1.head<3>()) + s1[3], 1e-13);
  }
  Eigen::Vector3d n;
  EXPECT_FALSE(coneTangentPlane({0, 0, 0, 2}, {0, 0, 1, 0.5}, 0.0, n)); // nested
  EXPECT_FALSE(coneTangentPlane({0, 0, 0, 1}, {0, 0, 0, 1}, 0.0, n));   // same centre
}

TEST(QmatSimplification, RejectsMissingOrEmptyInputAndBadTargets)
{
  QmatSimplification q;
  MedialMesh b, s;
  EXPECT_FALSE(q.compute(b, s));
  q.setInputMat(share(MedialMesh()));
  EXPECT_FALSE(q.compute(b, s));
  // Spheres but no edge: nothing to simplify, nothing a MAT can be built from.
  q.setInputMat(share(MedialMesh({{0, 0, 0}, {1, 0, 0}}, {0.1, 0.1}, {}, {})));
  EXPECT_FALSE(q.compute(b, s));
  q.setInputMat(share(test::planarSheet(4, 1.0, 0.1)));
  q.setBaseTarget(0);
  EXPECT_FALSE(q.compute(b, s));
  EXPECT_TRUE(b.empty() && s.empty());
  q.setBaseTarget(10);
  q.setStructuredTarget(-7);
  EXPECT_FALSE(q.compute(b, s));
  q.setStructuredTarget(5);
  EXPECT_TRUE(q.compute(b, s));
}

TEST(QmatSimplification, TargetsHonouredAndAutomaticStructuredTarget)
{
  const MedialMesh sheet = test::planarSheet(20, 1.0, 0.1); // 441 spheres
  auto [base, structured] = simplify(sheet, 100, 12);
  EXPECT_EQ(base.numVertices(), 100u);
  EXPECT_EQ(structured.numVertices(), 12u);

  QmatSimplification q;
  q.setInputMat(share(sheet));
  q.setBaseTarget(100);
  MedialMesh b, s;
  ASSERT_TRUE(q.compute(b, s));
  EXPECT_EQ(q.getResolvedStructuredTarget(), 15); // max(15, ⌊0.441⌋)
  EXPECT_EQ(s.numVertices(), 15u);
  EXPECT_EQ(q.getInitialSphereCount(), 441u);
  EXPECT_EQ(q.getCollapseCount(), 441u - 15u);

  // A structured target above the base target leaves the structured MAT equal to the base.
  auto [b2, s2] = simplify(sheet, 50, 80);
  EXPECT_EQ(b2.numVertices(), 50u);
  EXPECT_TRUE(sameMat(b2, s2));
  // Targets above the input size keep the input.
  auto [b3, s3] = simplify(sheet, 5000, 4000);
  EXPECT_EQ(b3.numVertices(), 441u);
  EXPECT_EQ(b3.numTriangles(), sheet.numTriangles());
}

TEST(QmatSimplification, AutomaticStructuredTargetCountsBeyondPinnedSpheres)
{
  // A unit sheet (13 × 13 = 169 spheres) and 30 separate small triangles, as the islands of a noisy
  // Voronoi MAT. Topology keeps 31 components, so at best 31 spheres (one per island, one for
  // the sheet): the automatic target max(15, ⌊0.259⌋) = 15 is out of reach. Run down to 31,
  // the sheet would be a single sphere; instead the structured MAT keeps 31 + 15 = 46 and the
  // sheet keeps triangles. An explicit target of 15 still goes to the 31.
  const MedialMesh mat = sheetWithIslands(12, 30);
  ASSERT_EQ(mat.numVertices(), 259u);
  ASSERT_EQ(bettiNumbers(mat).b0, 31);

  QmatSimplification q;
  q.setInputMat(share(mat));
  q.setBaseTarget(1000);
  MedialMesh base, structured;
  ASSERT_TRUE(q.compute(base, structured));
  EXPECT_EQ(base.numVertices(), 259u);
  EXPECT_EQ(q.getResolvedStructuredTarget(), 46);
  ASSERT_EQ(structured.numVertices(), 46u);
  EXPECT_EQ(bettiNumbers(structured).b0, 31);
  int sheet_triangles = 0;
  for (const Eigen::Vector3i& t : structured.triangles())
    sheet_triangles += structured.centers()[t[0]].x() < 1.5 &&
                       structured.centers()[t[1]].x() < 1.5 &&
                       structured.centers()[t[2]].x() < 1.5;
  EXPECT_GE(sheet_triangles, 2);

  auto [literal_base, literal] = simplify(mat, 1000, 15);
  EXPECT_EQ(literal.numVertices(), 31u);
  EXPECT_EQ(literal.numTriangles(), 0u);
}

TEST(QmatSimplification, DropsIsolatedSpheresAndKeepsEveryOtherComponent)
{
  // A noisy cloud's segmentation chooses between two initial MATs by the components that Q-MAT
  // will leave (CloudSegmentation: the retry with mirror-related normals), counting them before
  // Q-MAT runs. That count is right only if Q-MAT drops the isolated spheres and neither joins
  // nor splits the other components: here a sheet, three small triangles and two spheres
  // without an edge (6 components before, 4 after).
  const MedialMesh mat = sheetWithIslands(6, 3, {-1.0, -2.0});
  ASSERT_EQ(mat.numConnectedComponents(), 6u);
  for (const int base_target : {30, 4}) {
    auto [base, structured] = simplify(mat, base_target, 4);
    EXPECT_EQ(base.numConnectedComponents(), 4u) << "base target " << base_target;
    EXPECT_EQ(structured.numConnectedComponents(), 4u) << "base target " << base_target;
    for (const Eigen::Vector3d& c : base.centers())
      EXPECT_GT(c.x(), -0.5) << "an isolated sphere survived";
  }
}

TEST(QmatSimplification, AutomaticStructuredTargetBeyondPinnedLoops)
{
  // Six loops of 30 cones (tunnels): each keeps at least a triangle of edges, so 18 spheres
  // are pinned and the automatic target 15 is out of reach. With only 6 components the state
  // at the base MAT is not kept in advance; the run to it is replayed. 18 + 15 = 33 spheres.
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
  std::vector<Eigen::Vector2i> edges;
  for (int l = 0; l < 6; ++l) {
    const MedialMesh loop = test::pureEdgeLoop(30, 1.0, 0.25);
    const int first = static_cast<int>(centers.size());
    for (std::size_t v = 0; v < loop.numVertices(); ++v) {
      centers.push_back(loop.centers()[v] + Eigen::Vector3d(3.0 * l, 0, 0));
      radii.push_back(loop.radii()[v]);
    }
    for (const Eigen::Vector2i& e : loop.edges())
      edges.emplace_back(e[0] + first, e[1] + first);
  }
  const MedialMesh mat(centers, radii, edges, {});
  QmatSimplification q;
  q.setInputMat(share(mat));
  q.setBaseTarget(1000);
  MedialMesh base, structured;
  ASSERT_TRUE(q.compute(base, structured));
  EXPECT_EQ(q.getResolvedStructuredTarget(), 33);
  EXPECT_EQ(structured.numVertices(), 33u);
  const test::Betti betti = bettiNumbers(structured);
  EXPECT_EQ(betti.b0, 6);
  EXPECT_EQ(betti.b1, 6);
}

TEST(QmatSimplification, FlatSheetKeepsItsBorderWithoutFolding)
{
  // Constant radius on a plane: every collapse is free (Q = 0) but for the border planes, so
  // the square must keep its corners and its area, and no triangle may fold over another.
  const MedialMesh sheet = test::planarSheet(12, 1.0, 0.1);
  for (int target : {60, 20, 4}) {
    auto [base, structured] = simplify(sheet, target, target);
    ASSERT_EQ(base.numVertices(), static_cast<std::size_t>(target));
    for (std::size_t v = 0; v < base.numVertices(); ++v) {
      EXPECT_NEAR(base.centers()[v].z(), 0.0, 1e-12);
      EXPECT_NEAR(base.radii()[v], 0.1, 1e-12);
    }
    // Folded (flipped) triangles would overlap and add area beyond the unit square.
    EXPECT_NEAR(totalTriangleArea(base), 1.0, 1e-9) << "target " << target;
    for (const Eigen::Vector3d corner : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                         Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0)}) {
      double nearest = 1e9;
      for (const Eigen::Vector3d& c : base.centers())
        nearest = std::min(nearest, (c - corner).norm());
      EXPECT_LT(nearest, 1e-12) << "corner " << corner.transpose() << " lost at " << target;
    }
    const test::Betti betti = bettiNumbers(base);
    EXPECT_EQ(betti.b0, 1);
    EXPECT_EQ(betti.b1, 0);
    EXPECT_EQ(betti.b2, 0);
  }
}

TEST(QmatSimplification, AnnulusKeepsItsHole)
{
  // A ring strip must never be closed into a fan: b1 = 1 at every size, and asking for fewer
  // spheres than a hole needs stops with a warning instead of looping or pinching.
  const MedialMesh ring = test::annulusSheet(24, 3, 1.0, 1.6, 0.2);
  ASSERT_EQ(bettiNumbers(ring).b1, 1);
  for (int target : {40, 12, 1}) {
    auto [base, structured] = simplify(ring, target, target);
    const test::Betti betti = bettiNumbers(base);
    EXPECT_EQ(betti.b0, 1) << target;
    EXPECT_EQ(betti.b1, 1) << target;
    EXPECT_GE(base.numVertices(), 3u);
    if (target >= 12)
      EXPECT_EQ(base.numVertices(), static_cast<std::size_t>(target));
  }
}

TEST(QmatSimplification, TunnelLoopOfPureEdgesSurvives)
{
  // The medial axis of a solid torus: a loop of cones. It may shrink to a triangle of edges,
  // never to a point.
  const MedialMesh loop = test::pureEdgeLoop(30, 1.0, 0.25);
  auto [base, structured] = simplify(loop, 10, 1);
  EXPECT_EQ(base.numVertices(), 10u);
  EXPECT_EQ(structured.numVertices(), 3u);
  EXPECT_EQ(structured.numEdges(), 3u);
  EXPECT_EQ(structured.numTriangles(), 0u);
  EXPECT_EQ(bettiNumbers(structured).b1, 1);
  for (double r : structured.radii())
    EXPECT_NEAR(r, 0.25, 1e-9);
}

TEST(QmatSimplification, HollowTetrahedronClosesUnlessCavitiesArePreserved)
{
  // Four triangles enclosing a cavity (b2 = 1). The full link condition forbids every collapse;
  // by default the cavity may close and the complex shrinks to one sphere.
  const MedialMesh tet({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0.1, 0.1, 0.1, 0.1}, {},
                       {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
  ASSERT_EQ(bettiNumbers(tet).b2, 1);
  auto [strict_base, strict_struct] = simplify(tet, 1, 1, true);
  EXPECT_EQ(strict_base.numVertices(), 4u);
  EXPECT_EQ(bettiNumbers(strict_base).b2, 1);
  auto [base, structured] = simplify(tet, 1, 1, false);
  EXPECT_EQ(base.numVertices(), 1u);
  EXPECT_EQ(bettiNumbers(base).b2, 0);
}

TEST(QmatSimplification, SpikesCollapseFirst)
{
  // A flat sheet with spikes: tiny spheres inside a sheet sphere (stability ratio 0), attached
  // by a pure edge or by a thin fin triangle. They cost 0 and must all go before anything else.
  MedialMesh sheet = test::planarSheet(8, 1.0, 0.1);
  std::vector<Eigen::Vector3d> centers = sheet.centers();
  std::vector<double> radii = sheet.radii();
  std::vector<Eigen::Vector2i> edges = sheet.edges();
  std::vector<Eigen::Vector3i> triangles = sheet.triangles();
  const int n0 = static_cast<int>(centers.size());
  const int hosts[] = {10, 22, 40, 57, 70};
  for (int k = 0; k < 5; ++k) {
    const int host = hosts[k];
    centers.push_back(centers[host] + Eigen::Vector3d(0.01, 0.005, 0.05));
    radii.push_back(0.01);
    if (k % 2 == 0)
      edges.emplace_back(host, n0 + k);
    else
      triangles.emplace_back(host, host + 1, n0 + k); // a fin: both sheet spheres contain it
  }
  const MedialMesh spiky(centers, radii, edges, triangles);
  auto [base, structured] = simplify(spiky, n0, n0 - 30);
  ASSERT_EQ(base.numVertices(), static_cast<std::size_t>(n0));
  for (double r : base.radii())
    EXPECT_GT(r, 0.05);
  EXPECT_EQ(base.numTriangles(), sheet.numTriangles());
  EXPECT_EQ(bettiNumbers(base).b1, 0);
}

TEST(QmatSimplification, Deterministic)
{
  MedialMesh ring = test::annulusSheet(40, 5, 1.0, 2.0, 0.3);
  // Make it non-trivial: vary radii and lift the sheet so that m* is used.
  std::vector<Eigen::Vector3d> c = ring.centers();
  std::vector<double> r = ring.radii();
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i].z() = 0.2 * std::sin(3.0 * c[i].x()) * std::cos(2.0 * c[i].y());
    r[i] = 0.2 + 0.05 * std::cos(c[i].x() + c[i].y());
  }
  const MedialMesh wavy(c, r, ring.edges(), ring.triangles());
  auto first = simplify(wavy, 60, 8);
  auto second = simplify(wavy, 60, 8);
  EXPECT_TRUE(sameMat(first.first, second.first));
  EXPECT_TRUE(sameMat(first.second, second.second));
  // The first cost evaluation runs on several threads when asked; the result must not change.
  QmatSimplification threaded;
  threaded.setInputMat(share(wavy));
  threaded.setBaseTarget(60);
  threaded.setStructuredTarget(8);
  threaded.setNumberOfThreads(3);
  MedialMesh b3, s3;
  ASSERT_TRUE(threaded.compute(b3, s3));
  EXPECT_TRUE(sameMat(first.first, b3));
  EXPECT_TRUE(sameMat(first.second, s3));
  EXPECT_EQ(first.first.numVertices(), 60u);
  EXPECT_EQ(bettiNumbers(first.second).b1, 1);
  for (const MedialMesh* m : {&first.first, &first.second})
    for (std::size_t v = 0; v < m->numVertices(); ++v) {
      EXPECT_TRUE(m->centers()[v].allFinite());
      EXPECT_GE(m->radii()[v], 0.0);
    }
}

TEST(QmatSimplification, TeddyBaseMatToFifteenSpheres)
{
  // The authors' teddy base MAT (2000 spheres, 7 spurious cavities) simplified to 15 spheres,
  // compared with their own 15-sphere structured MAT (shipped in data/teddy): same topology
  // class (one component, no loop, no cavity), every one of their spheres has one of ours within
  // 10 % of the diagonal and vice versa, all our centres inside the surface.
  const std::string dir = std::string(SEGMAT_DATA_DIR) + "/teddy/";
  const auto mat = std::make_shared<const MedialMesh>(io::loadMa(dir + "teddy_mat.ma"));
  const MedialMesh reference = io::loadMa(dir + "teddy_smat.ma");
  const TriangleMesh surface = io::loadOff(dir + "teddy.off");
  const double diagonal = surface.boundingBoxDiagonal();
  ASSERT_EQ(mat->numVertices(), 2000u);
  ASSERT_EQ(bettiNumbers(*mat).b2, 7);

  QmatSimplification q;
  q.setInputMat(mat);
  q.setNormalisationScale(diagonal);
  q.setBaseTarget(2000);
  q.setStructuredTarget(15);
  MedialMesh base, structured;
  ASSERT_TRUE(q.compute(base, structured));
  EXPECT_EQ(base.numVertices(), 2000u);
  EXPECT_EQ(base.numTriangles(), mat->numTriangles()); // nothing to do at the base target
  ASSERT_EQ(structured.numVertices(), 15u);
  const test::Betti betti = bettiNumbers(structured);
  EXPECT_EQ(betti.b0, 1);
  EXPECT_EQ(betti.b1, 0);
  EXPECT_EQ(betti.b2, 0);
  std::size_t pure = 0;
  for (std::size_t e = 0; e < structured.numEdges(); ++e)
    pure += structured.isPureEdge(static_cast<int>(e));
  EXPECT_GE(pure, 6u) << "limbs and ears should be medial cones";

  const WindingNumber inside(surface);
  for (std::size_t v = 0; v < structured.numVertices(); ++v) {
    EXPECT_TRUE(structured.centers()[v].allFinite());
    EXPECT_GT(structured.radii()[v], 0.0);
    EXPECT_TRUE(inside.inside(structured.centers()[v])) << "sphere " << v;
  }
  auto farthestNearest = [](const MedialMesh& from, const MedialMesh& to) {
    double worst = 0.0;
    for (const Eigen::Vector3d& c : from.centers()) {
      double nearest = 1e300;
      for (const Eigen::Vector3d& d : to.centers())
        nearest = std::min(nearest, (c - d).norm());
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  EXPECT_LT(farthestNearest(reference, structured), 0.1 * diagonal);
  EXPECT_LT(farthestNearest(structured, reference), 0.1 * diagonal);

  // The full link condition keeps the 7 cavities and cannot get anywhere near 15 spheres.
  q.setPreserveCavitiesFlag(true);
  MedialMesh strict_base, strict_structured;
  ASSERT_TRUE(q.compute(strict_base, strict_structured));
  EXPECT_EQ(bettiNumbers(strict_structured).b2, 7);
  EXPECT_GT(strict_structured.numVertices(), 15u);
}

TEST(MedialMeshEstimation, CapsuleAxisAndTorusLoop)
{
  // Capsule of radius 0.3 around the segment z ∈ [-1, 1]: the structured MAT lies on the axis
  // with radii near 0.3.
  MedialMeshEstimation estimation;
  estimation.setInputMesh(std::make_shared<const TriangleMesh>(test::capsule(0.3, 2.0, 32, 16, 8)));
  estimation.setBaseTarget(300);
  estimation.setStructuredTarget(6);
  MedialMesh base, structured;
  ASSERT_TRUE(estimation.compute(base, structured));
  EXPECT_GT(estimation.getInitialMat().numVertices(), 300u);
  EXPECT_EQ(base.numVertices(), 300u);
  ASSERT_EQ(structured.numVertices(), 6u);
  EXPECT_EQ(estimation.getStatistics().structured_spheres, 6u);
  double z_min = 1e9, z_max = -1e9;
  for (std::size_t v = 0; v < structured.numVertices(); ++v) {
    const Eigen::Vector3d& c = structured.centers()[v];
    EXPECT_LT(c.head<2>().norm(), 0.05) << c.transpose();
    EXPECT_NEAR(structured.radii()[v], 0.3, 0.03);
    z_min = std::min(z_min, c.z());
    z_max = std::max(z_max, c.z());
  }
  EXPECT_LT(z_min, -0.7);
  EXPECT_GT(z_max, 0.7);

  // Torus (tube radius 0.25 around the unit circle): the tunnel survives as a loop, down to the
  // smallest one, a triangle of cones.
  estimation.setInputMesh(std::make_shared<const TriangleMesh>(test::torus(1.0, 0.25, 32, 12)));
  estimation.setBaseTarget(12);
  estimation.setStructuredTarget(1);
  ASSERT_TRUE(estimation.compute(base, structured));
  EXPECT_EQ(bettiNumbers(base).b1, 1);
  // 12 spheres for a 32-gon torus: the optimal spheres sit slightly off the circle (seen: 0.0203
  // with the final sampling), so the bound is 3 % of the radius, still an eighth of the tube.
  for (std::size_t v = 0; v < base.numVertices(); ++v) {
    EXPECT_NEAR(base.centers()[v].head<2>().norm(), 1.0, 0.03);
    EXPECT_NEAR(base.centers()[v].z(), 0.0, 0.01);
    EXPECT_NEAR(base.radii()[v], 0.25, 0.015);
  }
  EXPECT_EQ(structured.numVertices(), 3u);
  EXPECT_EQ(bettiNumbers(structured).b1, 1);
}

TEST(MedialMeshEstimation, BadInputFails)
{
  MedialMeshEstimation estimation;
  MedialMesh base, structured;
  EXPECT_FALSE(estimation.compute(base, structured));
  estimation.setInputMesh(std::make_shared<const TriangleMesh>());
  EXPECT_FALSE(estimation.compute(base, structured));
  // An open single triangle encloses nothing.
  estimation.setInputMesh(std::make_shared<const TriangleMesh>(
      std::vector<Eigen::Vector3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      std::vector<Eigen::Vector3i>{{0, 1, 2}}));
  EXPECT_FALSE(estimation.compute(base, structured));
  EXPECT_TRUE(base.empty() && structured.empty());
}
