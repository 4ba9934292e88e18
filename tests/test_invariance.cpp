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
segmentMesh(const TriangleMesh& mesh)
{
  MeshSegmentation seg;
  seg.setNumberOfThreads(1);
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
