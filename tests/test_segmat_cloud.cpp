// The segmat_cloud command-line program: outputs, JSON, exit codes and messages.
#include "util/cloud_sampler.h"

#include <segmat/io/cloud.h>
#include <segmat/io/seg.h>

#include <util/run_program.h>
#include <util/temp_files.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

using namespace segmat;

namespace {

/// A dumbbell of 8000 points with normals and two NaN points (3 and 5000), as a binary PCD.
std::string
writeDumbbellPcd(const std::string& name)
{
  auto cloud = test::dumbbellCloud(8000, 3).toPointNormal();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  (*cloud)[3].x = nan;
  (*cloud)[5000].y = nan;
  cloud->is_dense = false;
  const std::string path = test::scratchDir() + name;
  EXPECT_EQ(pcl::io::savePCDFileBinary(path, *cloud), 0);
  return path;
}

/// The dumbbell of writeDumbbellPcd (without NaNs) as text, every coordinate moved by \a shift.
std::string
writeDumbbellXyz(const std::string& name, double shift)
{
  const auto cloud = test::dumbbellCloud(8000, 3).toPointNormal();
  const std::string path = test::scratchDir() + name;
  std::ofstream out(path);
  out.precision(17);
  for (const pcl::PointNormal& p : *cloud)
    out << p.x + shift << ' ' << p.y + shift << ' ' << p.z + shift << ' ' << p.normal_x << ' '
        << p.normal_y << ' ' << p.normal_z << '\n';
  return path;
}

} // namespace

TEST(SegmatCloud, CloudFarFromOriginGetsTheSameLabelsAndKeepsItsFrame)
{
  // Two million units out, float steps are 0.25 — a third of the dumbbell's bar radius, so read
  // as floats the cloud would be a coarse grid. The reader moves it next to 0, exactly.
  const std::string near = writeDumbbellXyz("dumbbell_near.xyz", 0.0);
  const std::string far = writeDumbbellXyz("dumbbell_far.xyz", 2e6);
  const std::string prefix = test::scratchDir() + "dumbbell_far";
  const test::ProgramRun near_run =
      test::runProgram("segmat_cloud", near + " -o " + prefix + "_near --json");
  const test::ProgramRun far_run = test::runProgram("segmat_cloud", far + " -o " + prefix + " --json");
  ASSERT_EQ(near_run.status, 0) << near_run.err;
  ASSERT_EQ(far_run.status, 0) << far_run.err;
  const std::vector<int> labels = io::loadSeg(prefix + ".labels", 8000);
  EXPECT_EQ(labels, io::loadSeg(prefix + "_near.labels", 8000));
  EXPECT_EQ(std::set<int>(labels.begin(), labels.end()).size(), 3u);

  std::istringstream in(far_run.out);
  boost::property_tree::ptree json;
  boost::property_tree::read_json(in, json);
  std::vector<double> origin;
  for (const auto& c : json.get_child("origin"))
    origin.push_back(c.second.get_value<double>());
  EXPECT_EQ(origin, std::vector<double>(3, 2e6));
  // The labelled PCD is in the file's frame (to float precision there: 0.25).
  const auto input = test::dumbbellCloud(8000, 3).toPointNormal();
  pcl::PointCloud<pcl::PointXYZL> written;
  ASSERT_EQ(pcl::io::loadPCDFile(prefix + ".pcd", written), 0);
  ASSERT_EQ(written.size(), 8000u);
  for (std::size_t i = 0; i < written.size(); i += 997)
    EXPECT_LT((written[i].getVector3fMap().cast<double>() -
               (*input)[i].getVector3fMap().cast<double>() - Eigen::Vector3d::Constant(2e6))
                  .norm(),
              0.25)
        << i;
}

TEST(SegmatCloud, WritesPcdPlyLabelsAndPrintsJson)
{
  const std::string input = writeDumbbellPcd("dumbbell.pcd");
  const std::string prefix = test::scratchDir() + "dumbbell_cli";
  const test::ProgramRun run = test::runProgram("segmat_cloud", input + " -o " + prefix + " --json");
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* ext : {".pcd", ".ply", ".labels"})
    ASSERT_TRUE(test::fileExists(prefix + ext)) << ext;

  // One label per input point, in input order; -1 for the two NaN points.
  const std::vector<int> labels = io::loadSeg(prefix + ".labels", 8000);
  EXPECT_EQ(labels[3], -1);
  EXPECT_EQ(labels[5000], -1);
  EXPECT_EQ(std::count(labels.begin(), labels.end(), -1), 2);
  // The labelled PCD carries the same labels.
  const io::LoadedCloud labelled = io::loadCloud(prefix + ".pcd");
  EXPECT_EQ(labelled.cloud->size(), 8000u);
  EXPECT_EQ(test::readWholeFile(prefix + ".ply").rfind("ply", 0), 0u);

  std::istringstream in(run.out);
  boost::property_tree::ptree json;
  boost::property_tree::read_json(in, json);
  EXPECT_EQ(json.get<int>("parts"), 3);
  std::size_t total = 0, n = 0;
  for (const auto& c : json.get_child("point_counts")) {
    total += c.second.get_value<std::size_t>();
    ++n;
  }
  EXPECT_EQ(n, 3u);
  EXPECT_EQ(total, 7998u);
  for (const char* stage : {"load", "preprocessing", "medial", "graph", "grow_merge", "transfer",
                            "labels", "write"})
    EXPECT_GE(json.get<double>(std::string("seconds.") + stage), 0.0) << stage;
  // The file's normals are used: the noise is measured, the cloud found clean (σ̂ below a
  // tenth of the spacing) and taken as it is.
  EXPECT_GT(json.get<double>("noise.sigma"), 0.0);
  EXPECT_LT(json.get<double>("noise.sigma"), 0.1 * json.get<double>("noise.spacing"));
  EXPECT_EQ(json.get<int>("noise.passes"), 0);
  // Every finite point is a working point and a Voronoi sample (the working size is 20000);
  // the base MAT's 2000 spheres come from the initial ones.
  EXPECT_EQ(json.get<int>("samples"), 7998);
  EXPECT_GT(json.get<int>("initial_spheres"), 2000);
  EXPECT_EQ(json.get<int>("base_spheres"), 2000);
  EXPECT_GE(json.get<int>("structured_spheres"), 15);

  // Plain output, and the same labels again (deterministic), also with estimated normals.
  const test::ProgramRun plain =
      test::runProgram("segmat_cloud", input + " -o " + prefix + "_plain --threads 1");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.out.find("parts: 3"), std::string::npos) << plain.out;
  EXPECT_EQ(io::loadSeg(prefix + "_plain.labels"), labels);
  const test::ProgramRun estimated = test::runProgram(
      "segmat_cloud", input + " -o " + prefix + "_est --estimate-normals --json");
  ASSERT_EQ(estimated.status, 0) << estimated.err;
  std::istringstream estimated_out(estimated.out);
  boost::property_tree::ptree estimated_json;
  boost::property_tree::read_json(estimated_out, estimated_json);
  EXPECT_EQ(estimated_json.get<int>("parts"), 3);
  // Estimated normals: the noise is measured; a clean sampling has noise well below its
  // spacing and is not smoothed.
  const double spacing = estimated_json.get<double>("noise.spacing");
  EXPECT_GT(spacing, 0.0);
  EXPECT_LT(estimated_json.get<double>("noise.sigma"), 0.1 * spacing);
  EXPECT_EQ(estimated_json.get<int>("noise.passes"), 0);
}

TEST(SegmatCloud, BadArgumentsAndFilesFailWithAMessage)
{
  const std::string prefix = test::scratchDir() + "bad_cli";
  test::ProgramRun run = test::runProgram("segmat_cloud", "");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("usage"), std::string::npos);
  run = test::runProgram("segmat_cloud", "x.pcd -o " + prefix + " -g abc");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("-g"), std::string::npos) << run.err;
  run = test::runProgram("segmat_cloud", "x.pcd -o " + prefix + " -k 0");
  EXPECT_EQ(run.status, 2);
  run = test::runProgram("segmat_cloud", "x.pcd -o " + prefix + " --max-bend 120");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--max-bend"), std::string::npos) << run.err;
  run = test::runProgram("segmat_cloud", "x.pcd -o " + prefix + " --frobnicate");
  EXPECT_EQ(run.status, 2);
  // A missing file or an empty cloud is bad input (exit 2); an all-NaN cloud cannot be
  // segmented (exit 1). Nothing is written.
  run = test::runProgram("segmat_cloud", test::scratchDir() + "missing.pcd -o " + prefix);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("missing.pcd"), std::string::npos) << run.err;
  const std::string empty = test::writeScratchFile("empty.xyz", "# nothing\n");
  run = test::runProgram("segmat_cloud", empty + " -o " + prefix);
  EXPECT_EQ(run.status, 2) << run.err;
  pcl::PointCloud<pcl::PointXYZ> nans;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nans.resize(10, pcl::PointXYZ(nan, nan, nan));
  nans.is_dense = false;
  const std::string nan_path = test::scratchDir() + "nans.pcd";
  ASSERT_EQ(pcl::io::savePCDFileBinary(nan_path, nans), 0);
  run = test::runProgram("segmat_cloud", nan_path + " -o " + prefix);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_FALSE(test::fileExists(prefix + ".labels"));
}
