// MAT graph of medial points: k-NN edges gated by ball overlap, component bridging.
#include <segmat/medial/medial_point_graph.h>

#include <gtest/gtest.h>

#include <limits>

using namespace segmat;

namespace {

MedialPoint
ball(float x, float y, float z, float r, Eigen::Vector3f normal = Eigen::Vector3f::UnitZ())
{
  MedialPoint m;
  m.getVector3fMap() = Eigen::Vector3f(x, y, z);
  m.getNormalVector3fMap() = normal;
  m.radius = r;
  m.surface_index = m.contact_index = -1;
  return m;
}

std::vector<int>
neighbours(const MatGraph& g, int i)
{
  return std::vector<int>(g.neighboursBegin(i), g.neighboursEnd(i));
}

} // namespace

TEST(MedialPointGraph, OverlapGateAndNodeFields)
{
  // A chain 0–1–2 with spacing 1 and radius 0.6 (overlapping: 1 < 1.2), and 3 at distance 1.5
  // from 2 with radius 0.2 (0.6 + 0.2 = 0.8 < 1.5: no overlap, although it is a k-NN).
  auto cloud = std::make_shared<pcl::PointCloud<MedialPoint>>();
  cloud->push_back(ball(0, 0, 0, 0.6f));
  cloud->push_back(ball(1, 0, 0, 0.6f, Eigen::Vector3f(0, 3, 4)));
  cloud->push_back(ball(2, 0, 0, 0.6f));
  cloud->push_back(ball(3.5f, 0, 0, 0.2f, Eigen::Vector3f::Zero()));
  MedialPointGraph builder;
  builder.setInputCloud(cloud);
  builder.setKSearch(3);
  MatGraph graph;
  ASSERT_TRUE(builder.compute(graph));
  ASSERT_EQ(graph.numNodes(), 4u);
  EXPECT_FALSE(graph.hasPrimitives());
  // With k = 3 every pair is a k-NN pair; overlap keeps 0–1, 1–2 and drops 0–2 (2 > 1.2).
  EXPECT_EQ(neighbours(graph, 0), (std::vector<int>{1}));
  EXPECT_EQ(neighbours(graph, 1), (std::vector<int>{0, 2}));
  EXPECT_EQ(neighbours(graph, 2), (std::vector<int>{1}));
  EXPECT_TRUE(neighbours(graph, 3).empty());
  EXPECT_EQ(graph.numEdges(), 2u);
  EXPECT_EQ(builder.getNumberOfComponents(), 2u);
  const MatNode& n1 = graph.node(1);
  EXPECT_EQ(n1.kind, MatNodeKind::Point);
  EXPECT_EQ(n1.v, Eigen::Vector3i(1, -1, -1));
  EXPECT_DOUBLE_EQ(n1.mean_radius, 0.6f);
  EXPECT_TRUE(n1.centroid.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(n1.normal.isApprox(Eigen::Vector3d(0, 0.6, 0.8)));
  EXPECT_EQ(graph.node(3).normal, Eigen::Vector3d::Zero());
  // ρ = 2: 3 now overlaps 2 (1.5 < 2·0.8) and 0–2 joins (2 < 2.4).
  builder.setOverlapFactor(2.0);
  ASSERT_TRUE(builder.compute(graph));
  EXPECT_EQ(neighbours(graph, 2), (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(builder.getNumberOfComponents(), 1u);
}

TEST(MedialPointGraph, BridgesComponentsThatKnnSplits)
{
  // A dense blob of 12 balls within 0.011 of the origin and a chain at x = 1.2, 1.7, 2.2, 2.7,
  // all of radius 1. With k = 2 the blob's points see only each other and the chain's only the
  // chain (1.2 − 0.011 > 1.0), so k-NN gives two components although the balls overlap.
  auto cloud = std::make_shared<pcl::PointCloud<MedialPoint>>();
  for (int i = 0; i < 12; ++i)
    cloud->push_back(ball(0.001f * i, 0, 0, 1.0f));
  for (int i = 0; i < 4; ++i)
    cloud->push_back(ball(1.2f + 0.5f * i, 0, 0, 1.0f));
  MedialPointGraph builder;
  builder.setInputCloud(cloud);
  builder.setKSearch(2);
  builder.setConnectComponentsFlag(false);
  MatGraph graph;
  ASSERT_TRUE(builder.compute(graph));
  EXPECT_EQ(builder.getNumberOfComponents(), 2u);
  builder.setConnectComponentsFlag(true);
  ASSERT_TRUE(builder.compute(graph));
  EXPECT_EQ(builder.getNumberOfComponents(), 1u);
  EXPECT_EQ(builder.getNumberOfBridges(), 1u);
  // The bridge is the shortest overlapping link: blob point 11 (x = 0.011) to chain point 12.
  EXPECT_EQ(neighbours(graph, 12), (std::vector<int>{11, 13, 14})); // 13, 14: its 2-NN
}

TEST(MedialPointGraph, BadInputIsRefused)
{
  MedialPointGraph builder;
  MatGraph graph;
  EXPECT_FALSE(builder.compute(graph));
  auto cloud = std::make_shared<pcl::PointCloud<MedialPoint>>();
  builder.setInputCloud(cloud);
  EXPECT_FALSE(builder.compute(graph));
  cloud->push_back(ball(0, 0, 0, std::numeric_limits<float>::quiet_NaN()));
  EXPECT_FALSE(builder.compute(graph));
  EXPECT_TRUE(graph.empty());
  (*cloud)[0].radius = 1.0f;
  ASSERT_TRUE(builder.compute(graph)); // a single node, no edge
  EXPECT_EQ(graph.numNodes(), 1u);
  EXPECT_EQ(graph.numEdges(), 0u);
  builder.setKSearch(0);
  EXPECT_EQ(builder.getKSearch(), 10);
}
