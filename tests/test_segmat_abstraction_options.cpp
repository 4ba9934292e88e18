// --boxes, --level and --hierarchy of the command-line programs: the files they write, read back.
#include "util/cloud_sampler.h"

#include <segmat/geometry/oriented_box.h>
#include <segmat/io/cloud.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>

#include <util/run_program.h>
#include <util/temp_files.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <map>
#include <set>
#include <string>

using namespace segmat;

namespace {

const std::string kTeddy = std::string(SEGMAT_DATA_DIR) + "/teddy/";

Eigen::Vector3d
vectorOf(const boost::property_tree::ptree& array)
{
  Eigen::Vector3d v;
  int k = 0;
  for (const auto& x : array)
    v[k++] = x.second.get_value<double>();
  EXPECT_EQ(k, 3);
  return v;
}

/// PREFIX_boxes.json as part → box.
std::map<int, OrientedBox>
readBoxes(const std::string& path)
{
  boost::property_tree::ptree json;
  boost::property_tree::read_json(path, json);
  std::map<int, OrientedBox> boxes;
  for (const auto& entry : json.get_child("boxes")) {
    OrientedBox box;
    box.center = vectorOf(entry.second.get_child("center"));
    int row = 0;
    for (const auto& axis : entry.second.get_child("axes"))
      box.axes.row(row++) = vectorOf(axis.second).transpose();
    box.extents = vectorOf(entry.second.get_child("extents"));
    EXPECT_NEAR(entry.second.get<double>("volume"), box.volume(), 1e-12 * box.volume());
    boxes[entry.second.get<int>("part")] = box;
  }
  return boxes;
}

/// Each labelled point lies in its part's box (0.1 % of the diagonal), one box per label.
void
expectBoxesHoldTheirParts(const std::map<int, OrientedBox>& boxes,
                          const std::vector<Eigen::Vector3d>& points,
                          const std::vector<int>& labels)
{
  Eigen::AlignedBox3d bounds;
  std::set<int> parts;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (labels[i] >= 0) {
      bounds.extend(points[i]);
      parts.insert(labels[i]);
    }
  EXPECT_EQ(boxes.size(), parts.size());
  const double tolerance = 1e-3 * bounds.diagonal().norm();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (labels[i] >= 0)
      ASSERT_TRUE(boxes.at(labels[i]).contains(points[i], tolerance)) << "point " << i;
}

TriangleMesh
loadQuietly(const std::string& path)
{
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); // PCL names the colour properties
  TriangleMesh mesh = io::loadMesh(path);
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
  return mesh;
}

} // namespace

TEST(SegmatMeshOptions, BoxesHoldTheirPartsAndOpenAsPly)
{
  const std::string prefix = test::scratchDir() + "teddy_boxes";
  const test::ProgramRun run =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --boxes");
  ASSERT_EQ(run.status, 0) << run.err;
  const TriangleMesh teddy = io::loadMesh(kTeddy + "teddy.off");
  const std::vector<int> labels = io::loadSeg(prefix + ".seg", 19092);
  const std::map<int, OrientedBox> boxes = readBoxes(prefix + "_boxes.json");
  std::vector<Eigen::Vector3d> corners;
  std::vector<int> corner_labels;
  for (std::size_t f = 0; f < teddy.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) {
      corners.push_back(teddy.vertices[teddy.faces[f][k]]);
      corner_labels.push_back(labels[f]);
    }
  expectBoxesHoldTheirParts(boxes, corners, corner_labels);
  const TriangleMesh ply = loadQuietly(prefix + "_boxes.ply");
  EXPECT_EQ(ply.numVertices(), 8 * boxes.size());
  EXPECT_EQ(ply.numFaces(), 12 * boxes.size());
}

TEST(SegmatMeshOptions, HierarchyLevelsNestAndNameTheirFiles)
{
  const std::string prefix = test::scratchDir() + "teddy_levels";
  const test::ProgramRun run =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --hierarchy");
  ASSERT_EQ(run.status, 0) << run.err;
  boost::property_tree::ptree json;
  boost::property_tree::read_json(prefix + "_hierarchy.json", json);
  std::vector<std::vector<int>> levels, parents;
  for (const auto& level : json.get_child("levels")) {
    const std::string file = level.second.get<std::string>("file");
    EXPECT_EQ(file, "teddy_levels_level" + std::to_string(levels.size()) + ".seg");
    levels.push_back(io::loadSeg(test::scratchDir() + file, 19092));
    parents.emplace_back();
    for (const auto& p : level.second.get_child("parents"))
      parents.back().push_back(p.second.get_value<int>());
    EXPECT_EQ(level.second.get<std::size_t>("parts"), parents.back().size());
  }
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(json.get_child("levels").front().second.get<std::string>("name"), "coarse");
  for (std::size_t k = 0; k < levels.size(); ++k)
    for (std::size_t f = 0; f < levels[k].size(); ++f) {
      const int part = levels[k][f];
      ASSERT_GE(part, 0);
      ASSERT_LT(part, static_cast<int>(parents[k].size()));
      // Every face of a part lies in the part's parent: the levels nest.
      ASSERT_EQ(parents[k][part], k ? levels[k - 1][f] : -1) << "level " << k << " face " << f;
    }
  EXPECT_LT(parents.front().size(), parents.back().size());

  // --level sets δ and η together; a bad level is a usage error.
  const test::ProgramRun fine =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix + "_fine") + " --level fine");
  ASSERT_EQ(fine.status, 0) << fine.err;
  const test::ProgramRun bad =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --level 3");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("level '3'"), std::string::npos) << bad.err;
}

TEST(SegmatCloudOptions, BoxesHoldTheirPoints)
{
  const auto cloud = test::dumbbellCloud(4000, 3).toPointNormal();
  const std::string input = test::scratchDir() + "dumbbell_boxes.pcd";
  ASSERT_EQ(pcl::io::savePCDFileBinary(input, *cloud), 0);
  const std::string prefix = test::scratchDir() + "dumbbell_parts"; // not the input's name
  const test::ProgramRun run =
      test::runProgram("segmat_cloud", input + " -o " + prefix + " --boxes --threads 1");
  ASSERT_EQ(run.status, 0) << run.err;
  const std::vector<int> labels = io::loadSeg(prefix + ".labels", 4000);
  std::vector<Eigen::Vector3d> points;
  for (const auto& p : *cloud)
    points.push_back(p.getVector3fMap().cast<double>());
  expectBoxesHoldTheirParts(readBoxes(prefix + "_boxes.json"), points, labels);
  EXPECT_EQ(loadQuietly(prefix + "_boxes.ply").numFaces() % 12, 0u);

  const test::ProgramRun bad =
      test::runProgram("segmat_cloud", input + " -o " + prefix + " --level finest");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("level 'finest'"), std::string::npos) << bad.err;
}
