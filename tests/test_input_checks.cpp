// Checks of inputs before the pipeline: medial meshes against their mesh, open or non-manifold
// surfaces, the sample-count estimate behind the memory ceiling, and the normalised frame.
#include <segmat/geometry/medial_mesh_fit.h>
#include <segmat/geometry/mesh_edge_counts.h>
#include <segmat/geometry/surface_sampling.h>
#include <segmat/io/ma.h>
#include <segmat/io/off.h>

#include "../src/geometry/normalized_frame.h"
#include "util/synthetic_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;

namespace {
const std::string kTeddyDir = std::string(SEGMAT_DATA_DIR) + "/teddy/";
} // namespace

TEST(MedialMeshFit, TheTeddysOwnMatsFitAndDamagedOnesDoNot)
{
  const TriangleMesh mesh = io::loadOff(kTeddyDir + "teddy.off");
  const MedialMesh base = io::loadMa(kTeddyDir + "teddy_mat.ma");
  const MedialMesh structured = io::loadMa(kTeddyDir + "teddy_smat.ma");
  std::string reason;
  EXPECT_TRUE(MedialMeshFit().check(base, mesh, reason)) << reason;
  EXPECT_TRUE(MedialMeshFit().check(structured, mesh, reason)) << reason;

  const auto with = [&](int sphere, const Eigen::Vector3d& centre, double radius) {
    std::vector<Eigen::Vector3d> centres = base.centers();
    std::vector<double> radii = base.radii();
    centres[sphere] = centre;
    radii[sphere] = radius;
    return MedialMesh(centres, radii, base.edges(), base.triangles());
  };
  const double diagonal = mesh.boundingBoxDiagonal();
  const Eigen::Vector3d c = base.centers()[3];
  // (MedialMesh itself refuses non-finite and negative radii.)
  EXPECT_FALSE(MedialMeshFit().check(with(3, c, 1.01 * diagonal), mesh, reason));
  EXPECT_NE(reason.find("sphere 3 "), std::string::npos) << reason;
  EXPECT_NE(reason.find("exceeds the mesh's size"), std::string::npos) << reason;
  EXPECT_FALSE(
      MedialMeshFit().check(with(3, c + Eigen::Vector3d(0.2 * diagonal, 0, 0) * 5, 0.01), mesh,
                            reason));
  EXPECT_NE(reason.find("outside the mesh's bounding box"), std::string::npos) << reason;

  // Another shape's MAT inside the box: the teddy's, shrunk towards one corner of the box.
  std::vector<Eigen::Vector3d> centres = base.centers();
  std::vector<double> radii = base.radii();
  Eigen::Vector3d lo = mesh.vertices[0];
  for (const Eigen::Vector3d& p : mesh.vertices)
    lo = lo.cwiseMin(p);
  for (std::size_t v = 0; v < centres.size(); ++v) {
    centres[v] = lo + 0.25 * (centres[v] - lo);
    radii[v] *= 0.25;
  }
  EXPECT_FALSE(MedialMeshFit().check(MedialMesh(centres, radii, base.edges(), base.triangles()),
                                     mesh, reason));
  EXPECT_NE(reason.find("outside the surface"), std::string::npos) << reason;
}

TEST(MeshEdgeCounts, ClosedOpenAndNonManifold)
{
  TriangleMesh mesh = test::capsule(0.3, 2.0, 24, 12, 6);
  MeshEdgeCounts counts = countMeshEdges(mesh);
  EXPECT_TRUE(counts.closedManifold());
  EXPECT_EQ(counts.edges, 3 * mesh.numFaces() / 2);
  // Unwelded copy: vertices at equal positions count as one.
  TriangleMesh soup;
  for (const Eigen::Vector3i& f : mesh.faces) {
    const int n = static_cast<int>(soup.vertices.size());
    for (int k = 0; k < 3; ++k)
      soup.vertices.push_back(mesh.vertices[f[k]]);
    soup.faces.emplace_back(n, n + 1, n + 2);
  }
  EXPECT_TRUE(countMeshEdges(soup).closedManifold());
  // One face less: its three edges border one face each.
  const Eigen::Vector3i last = mesh.faces.back();
  mesh.faces.pop_back();
  counts = countMeshEdges(mesh);
  EXPECT_EQ(counts.boundary, 3u);
  EXPECT_EQ(counts.non_manifold, 0u);
  // The face back twice: three edges of three faces.
  mesh.faces.push_back(last);
  mesh.faces.push_back(last);
  counts = countMeshEdges(mesh);
  EXPECT_EQ(counts.boundary, 0u);
  EXPECT_EQ(counts.non_manifold, 3u);
}

TEST(SurfaceSampling, TheCountEstimateBoundsTheSamplesAndIsTightWhenDense)
{
  const TriangleMesh mesh = io::loadOff(kTeddyDir + "teddy.off");
  const double diagonal = mesh.boundingBoxDiagonal();
  for (double spacing : {0.0, 0.03, 0.01, 0.004, 0.002}) {
    const double estimate = estimateSurfaceSampleCount(mesh, spacing * diagonal);
    const double actual = static_cast<double>(sampleSurface(mesh, spacing * diagonal).size());
    EXPECT_GE(estimate, actual) << spacing;
    // Coarse spacings add few points to the vertices (small triangles get no lattice point but
    // count by area); where the ceiling matters, with many fill points, the estimate is tight.
    if (spacing > 0.0 && spacing <= 0.004)
      EXPECT_LE(estimate, 2.0 * actual) << spacing;
  }
  // An absurd spacing is estimated, not sampled: no overflow, no allocation.
  EXPECT_GT(estimateSurfaceSampleCount(mesh, 1e-9 * diagonal), 1e16);
}

TEST(NormalizedFrame, PowerOfTwoScalesGiveBitIdenticalFrameCoordinates)
{
  const TriangleMesh mesh = io::loadOff(kTeddyDir + "teddy.off");
  const TriangleMesh reference = detail::NormalizedFrame::of(mesh.vertices).toFrame(mesh);
  const double d = reference.boundingBoxDiagonal();
  EXPECT_GE(d, std::sqrt(0.5));
  EXPECT_LT(d, std::sqrt(2.0));
  for (int k : {-40, -3, 1, 17, 300}) {
    TriangleMesh scaled = mesh;
    for (Eigen::Vector3d& p : scaled.vertices)
      p = std::ldexp(1.0, k) * p;
    const TriangleMesh moved = detail::NormalizedFrame::of(scaled.vertices).toFrame(scaled);
    EXPECT_EQ(moved.vertices, reference.vertices) << k;
    EXPECT_EQ(moved.faces, reference.faces) << k;
  }
  // Coordinates near the double limit still get a finite frame.
  TriangleMesh huge = mesh;
  for (Eigen::Vector3d& p : huge.vertices)
    p = 1e307 * p;
  const detail::NormalizedFrame frame = detail::NormalizedFrame::of(huge.vertices);
  EXPECT_GT(frame.scale, 0.0);
  EXPECT_TRUE(frame.toFrame(huge.vertices[0]).allFinite());
}

TEST(NormalizedFrame, FrameCopyKeepsTheInputOrder)
{
  // The copy is the input moved into its frame, vertex for vertex and face for face (a sorted
  // order would move the samples' index-hashed jitter: see docs/robustness.md).
  const TriangleMesh mesh = test::capsule(0.3, 2.0, 24, 12, 6);
  const detail::NormalizedFrame frame = detail::NormalizedFrame::of(mesh.vertices);
  const TriangleMesh copy = frame.toFrame(mesh);
  ASSERT_EQ(copy.vertices.size(), mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    EXPECT_EQ(copy.vertices[v], frame.toFrame(mesh.vertices[v]));
  EXPECT_EQ(copy.faces, mesh.faces);
}
