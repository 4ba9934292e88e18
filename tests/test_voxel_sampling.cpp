// Voxel representatives: nearest to the cell centre, deterministic, near a target count.
#include <segmat/medial/voxel_sampling.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace segmat;

TEST(VoxelSampling, KeepsThePointNearestTheCellCentre)
{
  // Cells of side 1 from the minimum corner (0,0,0). Cell (0,0,0) holds points 0, 1, 2 with
  // squared distances 0.75, 0.0625, 0.1875 to its centre: 1 wins. Cell (1,0,0) holds 3 only.
  // Cell (0,1,0) holds 4 and 5, both at 0.0625 from (0.5,1.5,0.5): the lower index wins.
  const std::vector<Eigen::Vector3f> points{{0, 0, 0},        {0.5f, 0.5f, 0.25f},
                                            {0.75f, 0.75f, 0.75f}, {1.5f, 0.25f, 0},
                                            {0.25f, 1.5f, 0.5f},   {0.75f, 1.5f, 0.5f},
                                            {2, 2, 2}};
  EXPECT_EQ(voxelRepresentatives(points, 1.0), (std::vector<int>{1, 3, 4, 6}));
  // One cell of side 10, centre (5,5,5): point 6 is nearest.
  EXPECT_EQ(voxelRepresentatives(points, 10.0), (std::vector<int>{6}));
}

TEST(VoxelSampling, NearTargetOnASurfaceAndACurve)
{
  // A 200 × 200 grid on the unit square (40000 points) and 40000 points on a segment.
  std::vector<Eigen::Vector3f> square, segment;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      square.emplace_back(i / 199.0f, j / 199.0f, 0.0f);
      segment.emplace_back((i * 200 + j) / 39999.0f, 0.0f, 0.0f);
    }
  for (const auto* pts : {&square, &segment}) {
    double h = 0.0;
    const std::vector<int> kept = voxelRepresentativesNear(*pts, 1000, &h);
    EXPECT_GT(h, 0.0);
    EXPECT_NEAR(double(kept.size()), 1000.0, 100.0);
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    EXPECT_EQ(kept, voxelRepresentativesNear(*pts, 1000)); // deterministic
  }
  // At most the target: every index; a floor on the cell size thins a tight blob to one point.
  EXPECT_EQ(voxelRepresentativesNear(square, 50000).size(), square.size());
  std::vector<Eigen::Vector3f> blob(100, Eigen::Vector3f(1, 2, 3));
  for (int i = 0; i < 100; ++i)
    blob[i].x() += 1e-4f * i;
  EXPECT_EQ(voxelRepresentativesNear(blob, 50, nullptr, 1.0).size(), 1u);
  EXPECT_TRUE(voxelRepresentativesNear({}, 10).empty());
}
