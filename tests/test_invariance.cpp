// Invariance by construction: moving, scaling, rotating, re-ordering or re-encoding a shipped
// shape changes its parts by at most the input's own rounding (Rand distance <= 0.01, the same
// part count); a power-of-two scale changes no label at all.
#include <segmat/io/off.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include "../bench/shape_variants.h"
#include "util/temp_files.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace segmat;

namespace {

using bench::randDistance;

int
partCount(const std::vector<int>& labels)
{
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

std::vector<int>
segmentMesh(const TriangleMesh& mesh, bool principal_axes = false)
{
  MeshSegmentation seg;
  seg.setNumberOfThreads(1);
  seg.setPrincipalAxesFrame(principal_axes);
  seg.setInputMesh(std::make_shared<const TriangleMesh>(mesh));
  std::vector<int> labels;
  EXPECT_TRUE(seg.segment(labels));
  return labels;
}

} // namespace

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

// PSB 246 (8 434 faces): in the input's own orientation a rotation moves part boundaries (Rand
// distance about 0.017: the Delaunay grid, the jitter and the sampling follow the axes); in the
// principal-axes frame two rotations give exactly the original labels.
TEST(Invariance, PrincipalAxesFrameMakesRotationsChangeNothing)
{
  const TriangleMesh mesh = io::loadOff(std::string(SEGMAT_DATA_DIR) + "/psb246/246.off");
  const std::vector<int> reference = segmentMesh(mesh, true);
  ASSERT_GE(partCount(reference), 2);
  const Eigen::Matrix3d rotations[] = {
      bench::someRotation(),
      Eigen::AngleAxisd(2.5, Eigen::Vector3d(-3, 1, 1).normalized()).toRotationMatrix()};
  for (const Eigen::Matrix3d& rotation : rotations) {
    TriangleMesh turned = mesh;
    for (Eigen::Vector3d& p : turned.vertices)
      p = rotation * p;
    EXPECT_EQ(segmentMesh(turned, true), reference);
  }
  // Turning the frame is a choice the default leaves alone: the default labels differ.
  EXPECT_NE(segmentMesh(mesh), reference);
}
