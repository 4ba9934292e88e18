// Initial Voronoi medial mesh (Q-MAT step 1) on shapes whose medial axis is known.
#include <segmat/geometry/delaunay_3d.h>
#include <segmat/geometry/surface_sampling.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/io/off.h>
#include <segmat/medial/voronoi_mat.h>

#include "util/synthetic_mesh.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <limits>

using namespace segmat;

namespace {
MedialMesh
computeMat(const TriangleMesh& mesh, double spacing = 0.015, double jitter = 1e-6,
           bool expect_ok = true, VoronoiMatStatistics* stats = nullptr)
{
  VoronoiMat vmat;
  vmat.setInputMesh(std::make_shared<TriangleMesh>(mesh));
  vmat.setMaxSpacing(spacing);
  vmat.setJitter(jitter);
  MedialMesh mat;
  EXPECT_EQ(vmat.compute(mat), expect_ok);
  if (stats)
    *stats = vmat.getStatistics();
  return mat;
}

// Distance from p to the segment z ∈ [-h, h] of the z axis.
double
distanceToAxisSegment(const Eigen::Vector3d& p, double h)
{
  const double z = std::max(-h, std::min(h, p.z()));
  return (p - Eigen::Vector3d(0, 0, z)).norm();
}

double
fraction(std::size_t count, std::size_t total)
{
  return total == 0 ? 0.0 : static_cast<double>(count) / static_cast<double>(total);
}
} // namespace

TEST(VoronoiMat, RegularTetrahedronHasOneSphereAtItsCentre)
{
  // Circumcentre of this regular tetrahedron is the origin, circumradius √3.
  const TriangleMesh tet({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                         {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
  ASSERT_GT(test::signedVolume(tet), 0.0);
  const MedialMesh mat = computeMat(tet, 0.0, 0.0);
  ASSERT_EQ(mat.numVertices(), 1u);
  EXPECT_LT(mat.centers()[0].norm(), 1e-12);
  EXPECT_NEAR(mat.radii()[0], std::sqrt(3.0), 1e-12);
  EXPECT_EQ(mat.numEdges(), 0u);
  EXPECT_EQ(mat.numTriangles(), 0u);

  // The corner tetrahedron's circumcentre (0.5, 0.5, 0.5) is outside it: an empty medial mesh.
  EXPECT_EQ(computeMat(test::tetrahedron(), 0.0, 0.0).numVertices(), 0u);
}

TEST(VoronoiMat, CosphericalIcosphereCollapsesToItsCentre)
{
  // Vertices of an icosphere are co-spherical: every Delaunay circumsphere is the unit sphere,
  // up to the 1e-6 jitter, so every medial vertex sits at the centre with radius 1.
  VoronoiMatStatistics stats;
  const MedialMesh mat = computeMat(test::icosphere(3), 0.0, 1e-6, true, &stats);
  EXPECT_EQ(stats.num_samples, 642u);
  ASSERT_GT(mat.numVertices(), 100u);
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    EXPECT_LT(mat.centers()[v].norm(), 1e-3);
    EXPECT_NEAR(mat.radii()[v], 1.0, 1e-3);
  }
}

TEST(VoronoiMat, DenseSphereSpheresAreInsideAndMaximal)
{
  // With fill samples on the flat faces the input is no longer co-spherical; centres stay inside
  // and every ball is (close to) maximal: its radius is at least the distance from its centre to
  // the surface (it passes through surface samples) and at most that plus the sample spacing
  // (an empty ball can only bulge out between samples).
  const TriangleMesh sphere = test::icosphere(4);
  VoronoiMatStatistics stats;
  const double spacing = 0.015 * 2.0 * std::sqrt(3.0); // relative to the bounding-box diagonal
  const MedialMesh mat = computeMat(sphere, 0.015, 1e-6, true, &stats);
  EXPECT_GT(stats.num_samples, sphere.vertices.size());
  ASSERT_GT(mat.numVertices(), 1000u);
  const WindingNumber w(sphere);
  std::size_t near_centre = 0;
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    const Eigen::Vector3d& c = mat.centers()[v];
    const double r = mat.radii()[v];
    ASSERT_TRUE(std::isfinite(r));
    EXPECT_GT(w(c), 0.5);
    EXPECT_LT(c.norm(), 1.0);
    EXPECT_LE(r, 1.0 + 1e-6);
    // The polyhedron lies between radii 0.9988 and 1 (icosphere(4)): distance to it ≈ 1 − |c|.
    EXPECT_GE(r, 1.0 - c.norm() - 0.002);
    EXPECT_LE(r, 1.0 - c.norm() + spacing);
    near_centre += c.norm() < 0.05;
  }
  // The sphere's medial axis is its centre: a large share of the spheres sit there with radius
  // ≈ 1; the rest are short spikes towards the flat facets, which carry fill samples (Q-MAT's
  // simplification removes spikes first).
  EXPECT_NEAR(mat.maxRadius(), 1.0, 0.01);
  EXPECT_GT(fraction(near_centre, mat.numVertices()), 0.25)
      << near_centre << " of " << mat.numVertices();
}

TEST(VoronoiMat, CapsuleCentresLieOnTheAxis)
{
  // Capsule: radius 0.5, cylinder length 2 along z. Medial axis: the segment |z| ≤ 1, radius 0.5.
  const double radius = 0.5, half = 1.0;
  const TriangleMesh capsule = test::capsule(radius, 2 * half, 64, 32, 16);
  const MedialMesh mat = computeMat(capsule);
  const double spacing = 0.015 * std::sqrt(1.0 + 1.0 + 9.0); // of the diagonal (1, 1, 3)
  ASSERT_GT(mat.numVertices(), 1000u);
  std::size_t on_axis = 0;
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    const Eigen::Vector3d& c = mat.centers()[v];
    const double r = mat.radii()[v];
    const double d = distanceToAxisSegment(c, half);
    // Inside, and the ball reaches the surface (at distance radius − d from c), bulging out by
    // less than the sample spacing (the polygonal capsule is within ~1.5e-3 of the true one).
    EXPECT_LT(d, radius);
    EXPECT_GE(r, radius - d - 3e-3);
    EXPECT_LE(r, radius - d + spacing);
    on_axis += d < 0.02 && std::abs(r - radius) < 0.02;
  }
  EXPECT_GT(fraction(on_axis, mat.numVertices()), 0.5) << on_axis << " of " << mat.numVertices();
  // The medial mesh has sheets (triangles) and cones (edges).
  EXPECT_GT(mat.numTriangles(), 0u);
}

TEST(VoronoiMat, GridBoxNeedsJitterAndStaysInside)
{
  // A box whose sides are 12×12 grids: co-spherical, grid-like input (qhull's worst case).
  const Eigen::Vector3d lo(0, 0, 0), hi(2, 1, 1);
  const MedialMesh mat = computeMat(test::box(lo, hi, 12));
  ASSERT_GT(mat.numVertices(), 100u);
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    const Eigen::Vector3d& c = mat.centers()[v];
    const double to_boundary = std::min((c - lo).minCoeff(), (hi - c).minCoeff());
    EXPECT_GT(to_boundary, 0.0);
    // An empty ball through surface samples cannot poke out by more than the sample spacing.
    EXPECT_LE(mat.radii()[v], to_boundary + 1.0 / 12.0);
  }
}

TEST(VoronoiMat, TorusKeepsItsHole)
{
  // Torus: major radius 2, tube 0.5. Medial axis: the circle of radius 2 in z = 0.
  const MedialMesh mat = computeMat(test::torus(2.0, 0.5, 96, 32));
  ASSERT_GT(mat.numVertices(), 1000u);
  std::size_t on_circle = 0;
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    const Eigen::Vector3d& c = mat.centers()[v];
    const double d = std::hypot(std::hypot(c.x(), c.y()) - 2.0, c.z());
    EXPECT_LT(d, 0.5);
    EXPECT_GT(std::hypot(c.x(), c.y()), 1.5); // nothing in the hole
    on_circle += d < 0.02;
  }
  EXPECT_GT(fraction(on_circle, mat.numVertices()), 0.5)
      << on_circle << " of " << mat.numVertices();
}

TEST(VoronoiMat, DeterministicAcrossRunsAndThreads)
{
  // Closed (winding number carried along Voronoi edges) and open (evaluated everywhere, in
  // parallel when asked) inputs give identical output on 1 and 2 threads.
  TriangleMesh open = test::capsule(0.4, 1.0, 24, 8, 6);
  open.faces.pop_back();
  for (const TriangleMesh& mesh : {test::capsule(0.4, 1.0, 24, 8, 6), open}) {
    VoronoiMat a, b;
    a.setInputMesh(std::make_shared<TriangleMesh>(mesh));
    b.setInputMesh(std::make_shared<TriangleMesh>(mesh));
    b.setNumberOfThreads(2);
    MedialMesh ma, mb;
    ASSERT_TRUE(a.compute(ma));
    ASSERT_TRUE(b.compute(mb));
    ASSERT_GT(ma.numVertices(), 0u);
    ASSERT_EQ(ma.numVertices(), mb.numVertices());
    EXPECT_EQ(ma.centers(), mb.centers());
    EXPECT_EQ(ma.radii(), mb.radii());
    EXPECT_EQ(ma.edges(), mb.edges());
    EXPECT_EQ(ma.triangles(), mb.triangles());
  }
}

TEST(VoronoiMat, BadInputFailsCleanly)
{
  VoronoiMat vmat;
  MedialMesh mat;
  EXPECT_FALSE(vmat.compute(mat)); // no input
  vmat.setInputMesh(std::make_shared<TriangleMesh>());
  EXPECT_FALSE(vmat.compute(mat)); // empty
  EXPECT_TRUE(mat.empty());

  TriangleMesh nan_mesh = test::icosphere(1);
  nan_mesh.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
  computeMat(nan_mesh, 0.015, 1e-6, false);

  TriangleMesh bad_index = test::icosphere(1);
  bad_index.faces.emplace_back(0, 1, 1000);
  computeMat(bad_index, 0.015, 1e-6, false);

  // One triangle: 3 samples with max spacing 0.
  computeMat(TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}), 0.0, 0.0, false);
  // A flat, two-sided square: coplanar samples, qhull reports a flat simplex.
  TriangleMesh flat({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                    {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}});
  computeMat(flat, 0.1, 0.0, false);
  // All faces degenerate (one point): no extent.
  computeMat(TriangleMesh({{1, 1, 1}}, {{0, 0, 0}}), 0.015, 1e-6, false);

  // An unreferenced NaN vertex is not part of the surface and is ignored.
  TriangleMesh stray = test::icosphere(2);
  stray.vertices.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_GT(computeMat(stray).numVertices(), 0u);
}

TEST(VoronoiMat, OpenMeshIsABestEffort)
{
  // A capsule with a band of faces removed: the winding number still separates inside from
  // outside away from the gap, and nothing crashes.
  TriangleMesh open = test::capsule(0.5, 2.0, 48, 24, 12);
  open.faces.erase(open.faces.begin() + 600, open.faces.begin() + 640);
  const MedialMesh mat = computeMat(open);
  ASSERT_GT(mat.numVertices(), 100u);
  for (std::size_t v = 0; v < mat.numVertices(); ++v) {
    ASSERT_TRUE(std::isfinite(mat.radii()[v]));
    EXPECT_LT(distanceToAxisSegment(mat.centers()[v], 1.0), 0.5 + 1e-9);
  }
  // A hemisphere-like open sheet encloses nothing much but must not crash either.
  TriangleMesh cap = test::icosphere(3);
  std::vector<Eigen::Vector3i> kept;
  for (const auto& f : cap.faces)
    if (cap.faceCentroid(static_cast<int>(&f - cap.faces.data())).z() > 0.0)
      kept.push_back(f);
  cap.faces = kept;
  VoronoiMat vmat;
  vmat.setInputMesh(std::make_shared<TriangleMesh>(cap));
  MedialMesh sheet;
  EXPECT_TRUE(vmat.compute(sheet));
}

TEST(SurfaceSampling, FillsLongEdgesAndBigFaces)
{
  // One right triangle with legs 4: edges of length 4, 4, 4√2 with spacing 1 get 3, 3, 5 points;
  // the lattice adds interior points at least 0.5 from every side.
  const TriangleMesh tri({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, {{0, 1, 2}});
  const auto samples = sampleSurface(tri, 1.0);
  ASSERT_GE(samples.size(), 3u + 11u);
  std::size_t interior = 0;
  for (const auto& p : samples) {
    EXPECT_NEAR(p.z(), 0.0, 1e-12);
    EXPECT_GE(p.x(), -1e-12);
    EXPECT_GE(p.y(), -1e-12);
    EXPECT_LE(p.x() + p.y(), 4.0 + 1e-12);
    const double d = std::min({p.x(), p.y(), (4.0 - p.x() - p.y()) / std::sqrt(2.0)});
    if (d > 1e-9) {
      EXPECT_GE(d, 0.5 - 1e-12);
      ++interior;
    }
  }
  EXPECT_EQ(samples.size(), 3u + 11u + interior);
  EXPECT_GT(interior, 0u);
  // Every point of the triangle is within one spacing of a sample.
  for (double x = 0.05; x < 4; x += 0.1)
    for (double y = 0.05; x + y < 4; y += 0.1) {
      double best = 1e9;
      for (const auto& p : samples)
        best = std::min(best, (p - Eigen::Vector3d(x, y, 0)).norm());
      EXPECT_LT(best, 1.0);
    }
  // Max spacing 0: the used vertices only.
  TriangleMesh with_stray = tri;
  with_stray.vertices.emplace_back(9, 9, 9);
  EXPECT_EQ(sampleSurface(with_stray, 0.0).size(), 3u);
}

TEST(Delaunay3D, CubeCornersAndFailures)
{
  // 8 cube corners + the centre: the centre joins every hull face, 12 tetrahedra.
  std::vector<Eigen::Vector3d> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1},
                                 {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.5, 0.5}};
  DelaunayTetrahedra dt;
  std::string message;
  ASSERT_TRUE(delaunayTetrahedralize(p, dt, message)) << message;
  EXPECT_EQ(dt.tetrahedra.size(), 12u);
  for (std::size_t t = 0; t < dt.tetrahedra.size(); ++t) {
    EXPECT_TRUE((dt.tetrahedra[t].array() == 8).any());
    int hull = 0;
    for (int i = 0; i < 4; ++i) {
      const int u = dt.neighbors[t][i];
      if (u < 0) {
        ++hull;
        continue;
      }
      // Neighbour relation is symmetric and u does not contain the opposite corner.
      EXPECT_FALSE((dt.tetrahedra[u].array() == dt.tetrahedra[t][i]).any());
      EXPECT_TRUE((dt.neighbors[u].array() == static_cast<int>(t)).any());
    }
    EXPECT_EQ(hull, 1);
  }
  // Coplanar and too few points fail with a message.
  EXPECT_FALSE(delaunayTetrahedralize({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, dt, message));
  EXPECT_FALSE(message.empty());
  EXPECT_TRUE(dt.tetrahedra.empty());
  EXPECT_FALSE(delaunayTetrahedralize({{0, 0, 0}}, dt, message));
}

TEST(SurfaceSampling, ThinningKeepsSpacingAndCount)
{
  // Eleven points 0.1 apart on a line; radius 0.25 keeps 0, 0.3, 0.6, 0.9 (greedy, in order).
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i <= 10; ++i)
    line.emplace_back(0.1 * i, 0, 0);
  EXPECT_EQ(thinPoints(line, 0.25), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(thinPoints(line, 0.0).size(), 11u);
  const std::vector<int> four = thinPointsToCount(line, 4);
  EXPECT_LE(four.size(), 4u);
  EXPECT_GE(four.size(), 3u);
  EXPECT_EQ(thinPointsToCount(line, 20).size(), 11u);

  // A dense sphere thinned to 3000 points keeps a near-uniform spacing.
  const TriangleMesh sphere = test::icosphere(5); // 10242 vertices
  const std::vector<int> kept = thinPointsToCount(sphere.vertices, 3000);
  EXPECT_LE(kept.size(), 3000u);
  EXPECT_GE(kept.size(), 2550u); // the search stops within 15 % below the cap
}

TEST(VoronoiMat, SampleLimitThinsDenseMeshes)
{
  VoronoiMat vmat;
  vmat.setInputMesh(std::make_shared<TriangleMesh>(test::icosphere(5)));
  vmat.setMaxSampleCount(3000);
  MedialMesh mat;
  ASSERT_TRUE(vmat.compute(mat));
  EXPECT_LE(vmat.getStatistics().num_samples, 3000u);
  EXPECT_GE(vmat.getStatistics().num_samples, 2550u);
  for (std::size_t v = 0; v < mat.numVertices(); ++v)
    EXPECT_LT(mat.centers()[v].norm(), 1.0);
}

TEST(VoronoiMat, TeddyVerticesMatchQMatReference)
{
  // Q-MAT's initial MAT of the 9548 teddy vertices (CGAL, the authors' program): 32,486 vertices,
  // 94,784 edges, 62,299 faces. qhull with a 1e-6 jitter and the winding-number inside test land
  // within 1 % of it.
  const std::string path = std::string(SEGMAT_DATA_DIR) + "/teddy/teddy.off";
  auto mesh = std::make_shared<TriangleMesh>(io::loadOff(path));
  VoronoiMat vmat;
  vmat.setInputMesh(mesh);
  vmat.setMaxSpacing(0.0);
  vmat.setMaxSampleCount(0);
  MedialMesh mat;
  ASSERT_TRUE(vmat.compute(mat));
  EXPECT_EQ(vmat.getStatistics().num_samples, 9548u);
  EXPECT_NEAR(static_cast<double>(mat.numVertices()), 32486.0, 325.0);
  EXPECT_NEAR(static_cast<double>(mat.numEdges()), 94784.0, 948.0);
  EXPECT_NEAR(static_cast<double>(mat.numTriangles()), 62299.0, 623.0);
  // Every sphere is inside the teddy and none is degenerate.
  const WindingNumber w(*mesh);
  for (std::size_t v = 0; v < mat.numVertices(); v += 97) {
    EXPECT_GT(w.exact(mat.centers()[v]), 0.5);
    EXPECT_TRUE(std::isfinite(mat.radii()[v]));
  }
}

TEST(VoronoiMat, FarFromTheOrigin)
{
  // Same sphere moved by 1e4: the same medial mesh up to the offset. Moved by 1e9 (about 1e-7
  // relative precision left): it may fail, but it must return promptly and never crash.
  const TriangleMesh sphere = test::icosphere(2);
  TriangleMesh moved = sphere, far = sphere;
  for (auto& v : moved.vertices)
    v += Eigen::Vector3d(1e4, -2e4, 3e4);
  for (auto& v : far.vertices)
    v += Eigen::Vector3d(1e9, 1e9, 1e9);
  const MedialMesh a = computeMat(sphere), b = computeMat(moved);
  ASSERT_GT(a.numVertices(), 0u);
  EXPECT_NEAR(static_cast<double>(b.numVertices()), static_cast<double>(a.numVertices()),
              0.05 * a.numVertices());
  for (std::size_t v = 0; v < b.numVertices(); ++v)
    EXPECT_LT((b.centers()[v] - Eigen::Vector3d(1e4, -2e4, 3e4)).norm(), 1.0);
  VoronoiMat vmat;
  vmat.setInputMesh(std::make_shared<TriangleMesh>(far));
  MedialMesh c;
  if (vmat.compute(c))
    for (std::size_t v = 0; v < c.numVertices(); ++v)
      EXPECT_TRUE(std::isfinite(c.radii()[v]));
}

namespace {
std::set<std::array<int, 4>>
tetrahedronSet(const DelaunayTetrahedra& dt)
{
  std::set<std::array<int, 4>> set;
  for (const auto& t : dt.tetrahedra) {
    std::array<int, 4> key{t[0], t[1], t[2], t[3]};
    std::sort(key.begin(), key.end());
    set.insert(key);
  }
  return set;
}

double
signedVolume(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector4i& t)
{
  return (p[t[1]] - p[t[0]]).dot((p[t[2]] - p[t[0]]).cross(p[t[3]] - p[t[0]])) / 6.0;
}

// A valid Delaunay tetrahedralisation: positive volumes summing to the hull volume, symmetric
// neighbours across shared facets, and no point strictly inside any circumsphere.
void
expectValidDelaunay(const DelaunayTetrahedra& dt, double hull_volume)
{
  const auto& p = dt.points;
  double volume = 0.0;
  for (std::size_t t = 0; t < dt.tetrahedra.size(); ++t) {
    const Eigen::Vector4i& v = dt.tetrahedra[t];
    const double vol = signedVolume(p, v);
    EXPECT_GT(vol, 0.0);
    volume += vol;
    for (int i = 0; i < 4; ++i) {
      const int u = dt.neighbors[t][i];
      if (u < 0)
        continue;
      EXPECT_TRUE((dt.neighbors[u].array() == static_cast<int>(t)).any());
      EXPECT_FALSE((dt.tetrahedra[u].array() == v[i]).any());
    }
    // Empty circumsphere (checked in double with a small relative tolerance).
    const Eigen::Vector3d b = p[v[1]] - p[v[0]], c = p[v[2]] - p[v[0]], d = p[v[3]] - p[v[0]];
    const Eigen::Vector3d x = (b.squaredNorm() * c.cross(d) + c.squaredNorm() * d.cross(b) +
                               d.squaredNorm() * b.cross(c)) /
                              (2.0 * b.dot(c.cross(d)));
    const Eigen::Vector3d centre = p[v[0]] + x;
    const double r2 = x.squaredNorm();
    for (const Eigen::Vector3d& q : p)
      EXPECT_GE((q - centre).squaredNorm(), r2 * (1.0 - 1e-9));
  }
  EXPECT_NEAR(volume, hull_volume, 1e-6 * hull_volume); // snapping moves the hull by ~1e-7
}
} // namespace

TEST(Delaunay3D, ExactMatchesQhullOnGenericPoints)
{
  // Points in general position have one Delaunay tetrahedralisation: both codes must find it.
  std::vector<Eigen::Vector3d> points;
  std::uint64_t x = 42;
  auto next = [&x]() {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(x >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < 3000; ++i)
    points.emplace_back(next(), next(), 0.5 * next());
  DelaunayTetrahedra exact, qhull;
  std::string message;
  ASSERT_TRUE(delaunayTetrahedralizeExact(points, exact, message)) << message;
  ASSERT_TRUE(delaunayTetrahedralize(exact.points, qhull, message)) << message;
  EXPECT_EQ(tetrahedronSet(exact), tetrahedronSet(qhull));
  // Snapping moves a point by at most half a grid cell of the longest side (1 / 2^22).
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_LE((exact.points[i] - points[i]).cwiseAbs().maxCoeff(), 0.5 / 4194303.0 + 1e-15);
}

TEST(Delaunay3D, ExactHandlesDegenerateInput)
{
  // A 6×6×6 grid of the unit cube: every cell's 8 corners are co-spherical. Any valid Delaunay
  // tetrahedralisation fills the cube (volume 1) with positive tetrahedra.
  std::vector<Eigen::Vector3d> grid;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        grid.emplace_back(i / 5.0, j / 5.0, k / 5.0);
  DelaunayTetrahedra dt;
  std::string message;
  ASSERT_TRUE(delaunayTetrahedralizeExact(grid, dt, message)) << message;
  expectValidDelaunay(dt, 1.0);

  // Co-spherical icosphere vertices, plus duplicates (used once) and the centre.
  TriangleMesh sphere = test::icosphere(2);
  std::vector<Eigen::Vector3d> points = sphere.vertices;
  points.push_back(points[5]);
  points.push_back(points[7]);
  points.emplace_back(0, 0, 0);
  ASSERT_TRUE(delaunayTetrahedralizeExact(points, dt, message)) << message;
  expectValidDelaunay(dt, test::signedVolume(sphere));
  for (const auto& t : dt.tetrahedra)
    for (int k = 0; k < 4; ++k)
      EXPECT_LT(t[k], static_cast<int>(sphere.vertices.size()) + 2 + 1)
          << "a duplicate point was inserted";
  for (const auto& t : dt.tetrahedra)
    EXPECT_FALSE((t.array() == static_cast<int>(sphere.vertices.size())).any() ||
                 (t.array() == static_cast<int>(sphere.vertices.size()) + 1).any());

  // Failures: coplanar, too few, non-finite.
  EXPECT_FALSE(delaunayTetrahedralizeExact({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}},
                                           dt, message));
  EXPECT_FALSE(message.empty());
  EXPECT_FALSE(delaunayTetrahedralizeExact({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, dt, message));
  EXPECT_FALSE(delaunayTetrahedralizeExact(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::numeric_limits<double>::quiet_NaN()}}, dt,
      message));
}

TEST(VoronoiMat, QhullAndExactDelaunayAgree)
{
  // Same samples, same jitter: nearly the same tetrahedra and medial mesh. Not identical: the
  // capsule's rings are close to co-spherical, where qhull's merged-and-retriangulated facets
  // (option Qt) and the exact code's snapped grid resolve ties differently.
  const TriangleMesh capsule = test::capsule(0.5, 1.5, 32, 12, 8);
  VoronoiMat a, b;
  a.setInputMesh(std::make_shared<TriangleMesh>(capsule));
  b.setInputMesh(std::make_shared<TriangleMesh>(capsule));
  b.setDelaunayMethod(DelaunayMethod::Qhull);
  MedialMesh ma, mb;
  ASSERT_TRUE(a.compute(ma));
  ASSERT_TRUE(b.compute(mb));
  EXPECT_NEAR(static_cast<double>(a.getStatistics().num_tetrahedra),
              static_cast<double>(b.getStatistics().num_tetrahedra),
              0.005 * b.getStatistics().num_tetrahedra);
  EXPECT_NEAR(static_cast<double>(ma.numVertices()), static_cast<double>(mb.numVertices()),
              0.01 * mb.numVertices());
  EXPECT_NEAR(static_cast<double>(ma.numTriangles()), static_cast<double>(mb.numTriangles()),
              0.01 * mb.numTriangles());
}

TEST(VoronoiMat, UsersMeshesUnweldedMixedAndOverlapping)
{
  // An unwelded "triangle soup" with every other face flipped gives the same medial mesh as the
  // clean shape: duplicates merge in sampling, the winding number welds and re-orients. (A bumpy
  // sphere, so that the samples are in general position and, without jitter, their Delaunay
  // tetrahedralisation does not depend on the order of the samples.)
  TriangleMesh sphere = test::icosphere(3);
  for (std::size_t v = 0; v < sphere.vertices.size(); ++v)
    sphere.vertices[v] *= 1.0 + 0.05 * std::sin(12.9898 * static_cast<double>(v));
  const TriangleMesh soup = test::triangleSoup(sphere, 2);
  const MedialMesh clean = computeMat(sphere, 0.015, 0.0), messy = computeMat(soup, 0.015, 0.0);
  ASSERT_GT(clean.numVertices(), 0u);
  EXPECT_EQ(messy.numVertices(), clean.numVertices());
  EXPECT_EQ(messy.numTriangles(), clean.numTriangles());

  // Two overlapping closed spheres (a self-intersecting union, winding number 2 in the overlap):
  // every centre lies in the union and some lie in the overlap.
  const TriangleMesh both =
      test::merge({test::icosphere(3, 1.0, {0, 0, 0}), test::icosphere(3, 1.0, {1.2, 0, 0})});
  const MedialMesh mat = computeMat(both);
  ASSERT_GT(mat.numVertices(), 0u);
  std::size_t in_overlap = 0;
  for (const Eigen::Vector3d& c : mat.centers()) {
    const bool in_a = c.norm() < 1.0, in_b = (c - Eigen::Vector3d(1.2, 0, 0)).norm() < 1.0;
    EXPECT_TRUE(in_a || in_b) << c.transpose();
    in_overlap += in_a && in_b;
  }
  EXPECT_GT(in_overlap, 0u);
}
