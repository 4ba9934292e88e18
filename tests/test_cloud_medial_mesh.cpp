// The cloud's medial mesh: splat surface (hand-computed triangle), cloud winding number, and the
// Voronoi + Q-MAT medial mesh of analytic shapes whose medial axis is known.
#include "util/cloud_sampler.h"

#include <segmat/geometry/splat_surface.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/voronoi_mat.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace segmat;
using namespace segmat::test;

TEST(SplatSurface, OneTriangleOfTheGivenAreaAroundThePointFacingTheNormal)
{
  const std::vector<Eigen::Vector3d> points = {{1, 2, 3}, {0, 0, 0}, {5, 5, 5}};
  const std::vector<Eigen::Vector3d> normals = {{0, 0, 2}, {0, 0, 0}, {1, 0, 0}};
  const std::vector<double> areas = {0.75, 1.0, -1.0}; // 2nd: zero normal, 3rd: no area
  const TriangleMesh soup = makeSplatSurface(points, normals, areas);
  ASSERT_EQ(soup.numFaces(), 1u);
  ASSERT_EQ(soup.numVertices(), 3u);
  EXPECT_NEAR(soup.faceArea(0), 0.75, 1e-12);
  EXPECT_TRUE(soup.faceCentroid(0).isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  EXPECT_TRUE(soup.faceNormal(0).isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  // Equilateral: every corner at the circumradius sqrt(4a / (3√3)) = 0.7598... from the point.
  for (const Eigen::Vector3d& v : soup.vertices)
    EXPECT_NEAR((v - points[0]).norm(), std::sqrt(4 * 0.75 / (3 * std::sqrt(3.0))), 1e-12);
}

TEST(SplatSurface, WindingNumberOfASphereCloudIsOneInsideZeroOutside)
{
  const SampledCloud sphere = sphereCloud(4000, 7);
  std::vector<Eigen::Vector3d> points, normals;
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    points.push_back(sphere.points[i].cast<double>());
    normals.push_back(sphere.normals[i].cast<double>());
  }
  // Each of 4000 points stands for 4π/4000 of the unit sphere.
  const std::vector<double> areas(points.size(), 4.0 * M_PI / 4000.0);
  const WindingNumber w(makeSplatSurface(points, normals, areas), false);
  EXPECT_NEAR(w(Eigen::Vector3d::Zero()), 1.0, 0.02);
  EXPECT_NEAR(w(Eigen::Vector3d(0.5, 0.3, -0.2)), 1.0, 0.05);
  EXPECT_NEAR(w(Eigen::Vector3d(2, 0, 0)), 0.0, 0.02);
  EXPECT_NEAR(w(Eigen::Vector3d(0, -1.3, 0.4)), 0.0, 0.05);
  // Flipped normals: the inside counts −1.
  for (Eigen::Vector3d& n : normals)
    n = -n;
  const WindingNumber flipped(makeSplatSurface(points, normals, areas), false);
  EXPECT_NEAR(flipped(Eigen::Vector3d::Zero()), -1.0, 0.02);
}

namespace {

/// Base and structured MATs of a cloud with its true normals.
bool
cloudMat(const SampledCloud& cloud, MedialMesh& base, MedialMesh& structured)
{
  CloudMedialMeshEstimation estimation;
  estimation.setInputCloud(cloud.toPointNormal());
  return estimation.compute(base, structured);
}

double
medianRadius(const MedialMesh& mat)
{
  std::vector<double> r;
  for (std::size_t v = 0; v < mat.numVertices(); ++v)
    r.push_back(mat.radii()[v]);
  std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
  return r[r.size() / 2];
}

} // namespace

TEST(CloudMedialMeshEstimation, TorusMedialAxisIsItsCoreCircle)
{
  // Torus R = 2, r = 0.5: the medial axis is the circle of radius 2 in z = 0, every ball r = 0.5.
  MedialMesh base, structured;
  ASSERT_TRUE(cloudMat(torusCloud(12000, 4), base, structured));
  EXPECT_EQ(base.numVertices(), 2000u);
  EXPECT_GT(structured.numVertices(), 0u);
  EXPECT_NEAR(medianRadius(base), 0.5, 0.03);
  int near_core = 0;
  for (std::size_t v = 0; v < base.numVertices(); ++v) {
    const Eigen::Vector3d c = base.centers()[v];
    if (std::abs(std::hypot(c.x(), c.y()) - 2.0) < 0.1 && std::abs(c.z()) < 0.1)
      ++near_core;
  }
  EXPECT_GE(near_core, int(0.9 * base.numVertices()));
}

TEST(CloudMedialMeshEstimation, SphereMedialAxisIsItsCentre)
{
  MedialMesh base, structured;
  ASSERT_TRUE(cloudMat(sphereCloud(10000, 3), base, structured));
  EXPECT_NEAR(medianRadius(base), 1.0, 0.03);
  for (std::size_t v = 0; v < base.numVertices(); ++v)
    EXPECT_LT(base.centers()[v].norm() + base.radii()[v], 1.05); // every ball inside the sphere
}

TEST(VoronoiMat, SampleNormalsSettleMostInsideTestsAndChangeNoDecision)
{
  // Torus cloud with its true normals, splat surface for the winding number: the normals must
  // decide most circumcentres (a pole sees all four samples within 60° of their normals) and
  // give exactly the medial mesh that the winding number alone gives.
  const SampledCloud torus = torusCloud(6000, 9);
  auto points = std::make_shared<std::vector<Eigen::Vector3d>>();
  auto normals = std::make_shared<std::vector<Eigen::Vector3d>>();
  for (std::size_t i = 0; i < torus.size(); ++i) {
    points->push_back(torus.points[i].cast<double>());
    normals->push_back(torus.normals[i].cast<double>());
  }
  // Surface area of the torus R = 2, r = 0.5: 4π²Rr = 4π², shared by the points.
  const std::vector<double> areas(points->size(), 4.0 * M_PI * M_PI / double(points->size()));
  auto splats = std::make_shared<TriangleMesh>(makeSplatSurface(*points, *normals, areas));
  auto winding = std::make_shared<WindingNumber>(*splats, false);
  MedialMesh with, without;
  VoronoiMatStatistics with_stats, without_stats;
  for (const bool use_normals : {true, false}) {
    VoronoiMat voronoi;
    voronoi.setInputMesh(splats);
    voronoi.setWindingNumber(winding);
    voronoi.setSurfaceSamples(points, use_normals ? normals : nullptr);
    ASSERT_TRUE(voronoi.compute(use_normals ? with : without));
    (use_normals ? with_stats : without_stats) = voronoi.getStatistics();
  }
  EXPECT_GT(without_stats.num_winding_evaluations, without_stats.num_inside); // every candidate
  EXPECT_LT(with_stats.num_winding_evaluations, without_stats.num_winding_evaluations / 5);
  EXPECT_EQ(with_stats.num_inside, without_stats.num_inside);
  ASSERT_EQ(with.numVertices(), without.numVertices());
  ASSERT_GT(with.numVertices(), 1000u);
  for (std::size_t v = 0; v < with.numVertices(); ++v)
    ASSERT_EQ(with.centers()[v], without.centers()[v]);
  EXPECT_EQ(with.numTriangles(), without.numTriangles());
}

TEST(CloudMedialMeshEstimation, BadInputFailsCleanly)
{
  CloudMedialMeshEstimation estimation;
  MedialMesh base, structured;
  EXPECT_FALSE(estimation.compute(base, structured)); // no input
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  estimation.setInputCloud(cloud);
  EXPECT_FALSE(estimation.compute(base, structured)); // empty
  pcl::PointNormal p;
  p.x = p.y = p.z = 0.0f;
  p.normal_x = std::nanf("");
  p.normal_y = p.normal_z = 0.0f;
  cloud->resize(10, p);
  EXPECT_FALSE(estimation.compute(base, structured)); // no finite normal
  // A flat disc encloses nothing: no medial sphere.
  estimation.setInputCloud(discCloud(2000, 5).toPointNormal());
  EXPECT_FALSE(estimation.compute(base, structured));
  EXPECT_TRUE(base.empty());
  estimation.setAreaKSearch(0); // refused, kept
  EXPECT_EQ(estimation.getAreaKSearch(), 8);
}

TEST(CloudMedialMeshEstimation, ComputeIsItsTwoHalvesAndQmatKeepsTheComponents)
{
  // Three solids apart: two spheres and a torus. The segmentation decides between two
  // orientations of a noisy cloud by the components of their initial MATs and simplifies only
  // the one it keeps, which is right because Q-MAT drops isolated spheres and never joins or
  // splits the other components.
  SampledCloud cloud = sphereCloud(5000, 3);
  const SampledCloud second = sphereCloud(5000, 4), torus = torusCloud(8000, 5);
  for (std::size_t i = 0; i < second.size(); ++i) {
    cloud.points.push_back(second.points[i] + Eigen::Vector3f(5.0f, 0.0f, 0.0f));
    cloud.normals.push_back(second.normals[i]);
  }
  for (std::size_t i = 0; i < torus.size(); ++i) {
    cloud.points.push_back(torus.points[i] + Eigen::Vector3f(0.0f, 6.0f, 0.0f));
    cloud.normals.push_back(torus.normals[i]);
  }
  CloudMedialMeshEstimation estimation;
  estimation.setInputCloud(cloud.toPointNormal());
  MedialMesh base, structured, halves_base, halves_structured;
  EXPECT_FALSE(estimation.simplify(halves_base, halves_structured)); // no initial MAT yet
  ASSERT_TRUE(estimation.compute(base, structured));
  ASSERT_TRUE(estimation.computeInitialMat());
  const MedialMesh& initial = estimation.getMedialMeshEstimation().getInitialMat();
  std::size_t isolated = 0;
  for (std::size_t v = 0; v < initial.numVertices(); ++v)
    isolated += initial.vertexEdges(int(v)).empty();
  const std::size_t components = initial.numConnectedComponents() - isolated;
  EXPECT_GE(components, 3u);
  ASSERT_TRUE(estimation.simplify(halves_base, halves_structured));
  EXPECT_EQ(halves_base.numConnectedComponents(), components);
  EXPECT_EQ(halves_structured.numConnectedComponents(), components);
  ASSERT_EQ(halves_base.numVertices(), base.numVertices());
  for (std::size_t v = 0; v < base.numVertices(); ++v) {
    ASSERT_EQ(halves_base.centers()[v], base.centers()[v]);
    ASSERT_EQ(halves_base.radii()[v], base.radii()[v]);
  }
  EXPECT_EQ(halves_base.numTriangles(), base.numTriangles());
  EXPECT_EQ(halves_structured.numVertices(), structured.numVertices());
  MedialMesh again, again_structured;
  EXPECT_FALSE(estimation.simplify(again, again_structured)); // once per initial MAT
  EXPECT_TRUE(again.empty());
}
