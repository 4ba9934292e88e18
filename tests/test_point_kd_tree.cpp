/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// The kd-tree every cloud stage searches must answer exactly as pcl::KdTreeFLANN (whose place
// it took for speed): same neighbours, same order (ties included), same squared distances.
#include "../src/common/point_kd_tree.h"

#include <pcl/kdtree/kdtree_flann.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

/// Random points on a coarse lattice, so that many distances tie, plus exact duplicates and a
/// few non-finite points (both trees must leave those out and map indices back).
pcl::PointCloud<pcl::PointXYZ>::Ptr
latticeCloud(int n)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(0, 12);
  for (int i = 0; i < n; ++i)
    cloud->push_back(pcl::PointXYZ(0.25f * cell(rng), 0.25f * cell(rng), 0.25f * cell(rng)));
  for (int i = 0; i < n / 10; ++i)
    cloud->push_back((*cloud)[i * 3]);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  (*cloud)[5].x = nan;
  (*cloud)[17].z = std::numeric_limits<float>::infinity();
  return cloud;
}

void
expectSameAsFlann(const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                  const pcl::IndicesPtr& indices, bool sorted_radius = true)
{
  pcl::KdTreeFLANN<pcl::PointXYZ> reference;
  reference.setSortedResults(sorted_radius);
  reference.setInputCloud(cloud, indices);
  segmat::detail::PointKdTree tree;
  tree.setSortedResults(sorted_radius);
  tree.setInputCloud(cloud, indices);
  EXPECT_EQ(tree.getInputCloud(), cloud);
  pcl::Indices a, b;
  std::vector<float> da, db;
  int compared = 0;
  for (std::size_t q = 0; q < cloud->size(); q += 7) {
    const pcl::PointXYZ& p = (*cloud)[q];
    if (!std::isfinite(p.x) || !std::isfinite(p.z))
      continue;
    for (int k : {1, 8, 33, 300}) {
      const int na = reference.nearestKSearch(p, k, a, da);
      const int nb = tree.nearestKSearch(p, k, b, db);
      ASSERT_EQ(na, nb) << "query " << q << " k " << k;
      ASSERT_EQ(a, b) << "query " << q << " k " << k;
      ASSERT_EQ(da, db) << "query " << q << " k " << k;
      ++compared;
    }
    for (unsigned max_nn : {0u, 5u}) {
      const int na = reference.radiusSearch(p, 0.6, a, da, max_nn);
      const int nb = tree.radiusSearch(p, 0.6, b, db, max_nn);
      ASSERT_EQ(na, nb) << "query " << q << " max_nn " << max_nn;
      ASSERT_EQ(a, b) << "query " << q << " max_nn " << max_nn;
      ASSERT_EQ(da, db) << "query " << q << " max_nn " << max_nn;
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(PointKdTree, AnswersExactlyAsKdTreeFlannWithTiesAndNonFinitePoints)
{
  expectSameAsFlann(latticeCloud(3000), nullptr);
}

TEST(PointKdTree, UnsortedRadiusAnswersComeInKdTreeFlannsOrder)
{
  expectSameAsFlann(latticeCloud(3000), nullptr, false);
}

TEST(PointKdTree, AnswersExactlyAsKdTreeFlannOnAnIndexSubset)
{
  const auto cloud = latticeCloud(3000);
  pcl::IndicesPtr subset(new pcl::Indices);
  for (int i = 0; i < static_cast<int>(cloud->size()); i += 3)
    subset->push_back(i);
  expectSameAsFlann(cloud, subset);
}

TEST(PointKdTree, EmptyAndAllNonFiniteCloudsFindNothing)
{
  segmat::detail::PointKdTree tree;
  pcl::Indices found = {1, 2};
  std::vector<float> d2 = {1.0f};
  EXPECT_EQ(tree.nearestKSearch(pcl::PointXYZ(0, 0, 0), 3, found, d2), 0);
  EXPECT_TRUE(found.empty() && d2.empty());

  pcl::PointCloud<pcl::PointXYZ>::Ptr nan_cloud(new pcl::PointCloud<pcl::PointXYZ>);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nan_cloud->push_back(pcl::PointXYZ(nan, 0, 0));
  tree.setInputCloud(nan_cloud);
  EXPECT_EQ(tree.nearestKSearch(pcl::PointXYZ(0, 0, 0), 3, found, d2), 0);
  EXPECT_EQ(tree.radiusSearch(pcl::PointXYZ(0, 0, 0), 1.0, found, d2), 0);

  // Three points, k = 5: all three, nearest first.
  pcl::PointCloud<pcl::PointXYZ>::Ptr small(new pcl::PointCloud<pcl::PointXYZ>);
  small->push_back(pcl::PointXYZ(3, 0, 0));
  small->push_back(pcl::PointXYZ(1, 0, 0));
  small->push_back(pcl::PointXYZ(2, 0, 0));
  tree.setInputCloud(small);
  ASSERT_EQ(tree.nearestKSearch(pcl::PointXYZ(0, 0, 0), 5, found, d2), 3);
  EXPECT_EQ(found, (pcl::Indices{1, 2, 0}));
  EXPECT_EQ(d2, (std::vector<float>{1.0f, 4.0f, 9.0f}));
}

} // namespace
