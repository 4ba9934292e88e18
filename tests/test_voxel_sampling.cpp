// Voxel representatives: nearest to the cell centre or to a jittered target, deterministic, near
// a target count.
#include <segmat/medial/voxel_sampling.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

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

namespace {

/// A plane z = 0.5 sampled on a 160 × 160 lattice of step 1/16 (dyadic: every coordinate and
/// every difference is exact in float): cells of side 1 hold 16 × 16 points each.
std::vector<Eigen::Vector3f>
latticePlane()
{
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 160; ++i)
    for (int j = 0; j < 160; ++j)
      points.emplace_back((i + 0.5f) / 16.0f, (j + 0.5f) / 16.0f, 0.5f);
  return points;
}

/// Mean distance, in the plane, of the kept points from their cells' centres (cells of side 1
/// from the points' minimum corner, (1/32, 1/32)).
double
meanOffsetFromCentres(const std::vector<Eigen::Vector3f>& points, const std::vector<int>& kept)
{
  const Eigen::Vector2d corner(1.0 / 32.0, 1.0 / 32.0);
  double sum = 0.0;
  for (int k : kept) {
    const Eigen::Vector2d p = points[k].head<2>().cast<double>() - corner;
    const Eigen::Vector2d centre(std::floor(p.x()) + 0.5, std::floor(p.y()) + 0.5);
    sum += (p - centre).norm();
  }
  return sum / double(kept.size());
}

} // namespace

// The cells start at the lattice's first point, so every cell centre is a lattice point in the
// plane: centre picks land on the centres, and the kept points form a lattice again. Jittered
// targets are uniform in the cell: the mean distance of a uniform point of the unit square from
// its centre is (sqrt(2) + ln(1 + sqrt(2))) / 6 ≈ 0.383, and the nearest lattice point to a
// target is within sqrt(2) / 32 ≈ 0.044 of it.
TEST(VoxelSampling, JitteredPicksLeaveNoLattice)
{
  const std::vector<Eigen::Vector3f> points = latticePlane();
  const std::vector<int> centre = voxelRepresentatives(points, 1.0);
  const std::vector<int> jittered =
      voxelRepresentatives(points, 1.0, nullptr, VoxelPick::Jittered);
  ASSERT_EQ(centre.size(), 100u);
  ASSERT_EQ(jittered.size(), 100u); // one per occupied cell either way
  EXPECT_NEAR(meanOffsetFromCentres(points, centre), 0.0, 1e-9);
  EXPECT_NEAR(meanOffsetFromCentres(points, jittered), 0.383, 0.06);
}

// The jittered target depends on the cell's grid coordinates only: the same points in another
// order, or moved by an exactly representable offset, keep the same representatives.
TEST(VoxelSampling, JitteredPicksDependOnTheCellsOnly)
{
  const std::vector<Eigen::Vector3f> points = latticePlane();
  std::vector<int> representative;
  const std::vector<int> kept =
      voxelRepresentatives(points, 1.0, &representative, VoxelPick::Jittered);
  EXPECT_EQ(kept, voxelRepresentatives(points, 1.0, nullptr, VoxelPick::Jittered));
  for (std::size_t i = 0; i < points.size(); ++i) // every point maps to a kept point of its cell
    EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), representative[i]));

  // Reversed order: point i is now at n - 1 - i.
  const int n = static_cast<int>(points.size());
  std::vector<Eigen::Vector3f> reversed(points.rbegin(), points.rend());
  std::vector<int> back = voxelRepresentatives(reversed, 1.0, nullptr, VoxelPick::Jittered);
  for (int& k : back)
    k = n - 1 - k;
  std::sort(back.begin(), back.end());
  EXPECT_EQ(back, kept);

  std::vector<Eigen::Vector3f> moved = points;
  for (Eigen::Vector3f& p : moved)
    p += Eigen::Vector3f(-64.0f, 32.0f, 8.0f);
  EXPECT_EQ(voxelRepresentatives(moved, 1.0, nullptr, VoxelPick::Jittered), kept);
}
