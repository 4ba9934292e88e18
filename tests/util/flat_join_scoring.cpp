#include "flat_join_scoring.h"

#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <gtest/gtest.h>

#include <set>

namespace segmat {
namespace test {

std::vector<std::vector<int>>
loadHumans(const std::string& prefix, int count, std::size_t num_faces)
{
  std::vector<std::vector<int>> humans;
  for (int k = 0; k < count; ++k)
    humans.push_back(
        io::loadSeg(prefix + std::to_string(k) + ".seg", static_cast<long>(num_faces)));
  return humans;
}

std::size_t
segmentWithFlatJoin(const TriangleMesh::Ptr& mesh, const PsbEvaluator& evaluator,
                    const std::vector<std::vector<int>>& humans, bool join, unsigned int jitter,
                    double& rand_distance)
{
  MeshSegmentation seg;
  seg.setInputMesh(mesh);
  seg.setJitterSeed(jitter);
  seg.setJoinFlatBoundaries(join);
  std::vector<int> labels;
  EXPECT_TRUE(seg.segment(labels));
  PsbScores mean;
  EXPECT_TRUE(evaluator.scoreAgainstAll(labels, humans, mean));
  rand_distance = mean.RI;
  const std::size_t parts = std::set<int>(labels.begin(), labels.end()).size();
  EXPECT_EQ(seg.getMatParts().size(), parts);
  return parts;
}

} // namespace test
} // namespace segmat
