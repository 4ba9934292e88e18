// Invariance by construction: moving, scaling, rotating, re-ordering or re-encoding a shipped
// shape changes its parts by at most the input's own rounding (Rand distance <= 0.01, the same
// part count); a power-of-two scale changes no label at all.
#include <segmat/io/off.h>
#include <segmat/segmentation/cloud_segmentation.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include "../bench/shape_variants.h"
#include "util/cloud_sampler.h"
#include "util/temp_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace segmat;

namespace {

using bench::randDistance;

int
partCount(const std::vector<int>& labels)
{
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

std::vector<int>
segmentMesh(const TriangleMesh& mesh, bool principal_axes = true)
{
  MeshSegmentation seg;
  seg.setNumberOfThreads(1);
  seg.setPrincipalAxesFrame(principal_axes);
  seg.setInputMesh(std::make_shared<const TriangleMesh>(mesh));
  std::vector<int> labels;
  EXPECT_TRUE(seg.segment(labels));
  return labels;
}

std::vector<int>
segmentCloud(const std::vector<Eigen::Vector3d>& points)
{
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3d& p : points)
    cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  CloudSegmentation<pcl::PointXYZ> seg;
  seg.setNumberOfThreads(1);
  seg.setInputCloud(cloud);
  std::vector<pcl::PointIndices> parts;
  EXPECT_TRUE(seg.segment(parts));
  return seg.getLabels();
}

/** 20 000 points sampled from PSB 346 (seed 1). */
std::vector<Eigen::Vector3d>
cloudOf346(TriangleMesh& mesh)
{
  mesh = io::loadOff(std::string(SEGMAT_DATA_DIR) + "/psb346/346.off");
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3f& p : test::sampleMesh(mesh, 20000, 1).points)
    points.push_back(p.cast<double>());
  return points;
}

} // namespace

// 20 000 points sampled from PSB 346, normals estimated: moved far away, scaled by 10^±3 or
// rotated, the cloud keeps its parts; scaled by a power of two, every label.
TEST(Invariance, CloudPartsSurviveMovingScalingAndRotating)
{
  TriangleMesh mesh;
  const std::vector<Eigen::Vector3d> points = cloudOf346(mesh);
  const std::vector<int> reference = segmentCloud(points);
  ASSERT_GE(partCount(reference), 2);
  const Eigen::Vector3d far = 1000.0 * mesh.boundingBoxDiagonal() * Eigen::Vector3d(1, -2, 3);
  const Eigen::Matrix3d rotation = bench::someRotation();
  struct Variant
  {
    std::string name;
    std::function<Eigen::Vector3d(const Eigen::Vector3d&)> map;
    bool identical;
  };
  const std::vector<Variant> variants{
      {"translated", [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(p + far); }, false},
      {"scale 1e3", [](const Eigen::Vector3d& p) { return Eigen::Vector3d(1e3 * p); }, false},
      {"scale 1e-3", [](const Eigen::Vector3d& p) { return Eigen::Vector3d(1e-3 * p); }, false},
      {"rotated", [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(rotation * p); }, false},
      {"scale 2^-7", [](const Eigen::Vector3d& p) { return Eigen::Vector3d(std::ldexp(1.0, -7) * p); },
       true},
      {"scale 2^30", [](const Eigen::Vector3d& p) { return Eigen::Vector3d(std::ldexp(1.0, 30) * p); },
       true}};
  for (const Variant& v : variants) {
    std::vector<Eigen::Vector3d> moved;
    for (const Eigen::Vector3d& p : points)
      moved.push_back(v.map(p));
    const std::vector<int> labels = segmentCloud(moved);
    const double distance = randDistance(labels, reference);
    EXPECT_EQ(partCount(labels), partCount(reference)) << v.name;
    EXPECT_LE(distance, 0.01) << v.name;
    if (v.identical)
      EXPECT_EQ(labels, reference) << v.name;
  }
}

// The same 20 000 points in a shuffled order: the copy is put into position order first, so
// every point keeps its label exactly.
TEST(Invariance, ShuffledCloudGivesIdenticalLabels)
{
  TriangleMesh mesh;
  const std::vector<Eigen::Vector3d> points = cloudOf346(mesh);
  const std::vector<int> reference = segmentCloud(points);
  ASSERT_GE(partCount(reference), 2);
  std::vector<int> point_of(points.size());
  std::iota(point_of.begin(), point_of.end(), 0);
  std::shuffle(point_of.begin(), point_of.end(), std::mt19937(11));
  std::vector<Eigen::Vector3d> shuffled;
  for (int i : point_of)
    shuffled.push_back(points[i]);
  const std::vector<int> labels = segmentCloud(shuffled);
  ASSERT_EQ(labels.size(), points.size());
  std::vector<int> in_original_order(labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k)
    in_original_order[point_of[k]] = labels[k];
  EXPECT_EQ(in_original_order, reference);
}

// PSB 346 (7 170 faces): every transformation keeps the parts.
TEST(Invariance, MeshPartsSurviveMovingScalingRotatingReorderingAndFormats)
{
  const std::string path = std::string(SEGMAT_DATA_DIR) + "/psb346/346.off";
  const TriangleMesh mesh = io::loadOff(path);
  const std::vector<int> reference = segmentMesh(mesh);
  ASSERT_GE(partCount(reference), 2);
  for (const bench::MeshVariant& v :
       bench::meshVariants(mesh, test::scratchDir() + "invariance_346")) {
    ASSERT_EQ(v.mesh.numFaces(), mesh.numFaces()) << v.name;
    const std::vector<int> labels = v.inOriginalOrder(segmentMesh(v.mesh));
    const double distance = randDistance(labels, reference);
    EXPECT_EQ(partCount(labels), partCount(reference)) << v.name;
    EXPECT_LE(distance, 0.01) << v.name;
    if (v.identical)
      EXPECT_EQ(distance, 0.0) << v.name;
  }
}

// PSB 321 and 246: in the default principal-axes frame two rotations give exactly the original
// labels. In the input's own orientation (setPrincipalAxesFrame(false)) the same rotation moves
// PSB 321's cut (the Voronoi MAT's grid, jitter and sampling follow the axes).
TEST(Invariance, RotationsChangeNothingInThePrincipalAxesFrame)
{
  const Eigen::Matrix3d rotations[] = {
      bench::someRotation(),
      Eigen::AngleAxisd(2.5, Eigen::Vector3d(-3, 1, 1).normalized()).toRotationMatrix()};
  const auto turned = [](const TriangleMesh& mesh, const Eigen::Matrix3d& rotation) {
    TriangleMesh out = mesh;
    for (Eigen::Vector3d& p : out.vertices)
      p = rotation * p;
    return out;
  };
  for (const char* shape : {"psb321/321.off", "psb246/246.off"}) {
    const TriangleMesh mesh = io::loadOff(std::string(SEGMAT_DATA_DIR) + "/" + shape);
    const std::vector<int> reference = segmentMesh(mesh);
    ASSERT_GE(partCount(reference), 2) << shape;
    for (const Eigen::Matrix3d& rotation : rotations)
      EXPECT_EQ(segmentMesh(turned(mesh, rotation)), reference) << shape;
  }
  const TriangleMesh mesh = io::loadOff(std::string(SEGMAT_DATA_DIR) + "/psb321/321.off");
  EXPECT_GT(randDistance(segmentMesh(turned(mesh, rotations[0]), false), segmentMesh(mesh, false)),
            0.0);
}

// Vertices and faces in a shuffled order, each face's corners rotated: the frame copy is put
// into position order first, so every order gives the very same labels (not merely similar
// ones), on shapes whose parts the input order used to move.
TEST(Invariance, ShuffledMeshGivesIdenticalLabels)
{
  for (const char* shape : {"psb101/101.off", "psb321/321.off", "teddy/teddy.off"}) {
    const TriangleMesh mesh = io::loadOff(std::string(SEGMAT_DATA_DIR) + "/" + shape);
    const std::vector<int> reference = segmentMesh(mesh);
    ASSERT_GE(partCount(reference), 2) << shape;
    std::mt19937 engine(7);
    std::vector<int> vertex_of(mesh.numVertices()), face_of(mesh.numFaces());
    std::iota(vertex_of.begin(), vertex_of.end(), 0);
    std::iota(face_of.begin(), face_of.end(), 0);
    std::shuffle(vertex_of.begin(), vertex_of.end(), engine);
    std::shuffle(face_of.begin(), face_of.end(), engine);
    std::vector<int> new_index(vertex_of.size());
    TriangleMesh shuffled;
    for (std::size_t k = 0; k < vertex_of.size(); ++k) {
      new_index[vertex_of[k]] = static_cast<int>(k);
      shuffled.vertices.push_back(mesh.vertices[vertex_of[k]]);
    }
    for (std::size_t k = 0; k < face_of.size(); ++k) {
      const Eigen::Vector3i& f = mesh.faces[face_of[k]];
      const int r = static_cast<int>(k % 3); // rotate the corners, keep the orientation
      shuffled.faces.emplace_back(new_index[f[r]], new_index[f[(r + 1) % 3]],
                                  new_index[f[(r + 2) % 3]]);
    }
    const std::vector<int> labels = segmentMesh(shuffled);
    std::vector<int> in_original_order(labels.size());
    for (std::size_t k = 0; k < labels.size(); ++k)
      in_original_order[face_of[k]] = labels[k];
    EXPECT_EQ(in_original_order, reference) << shape;
  }
}
