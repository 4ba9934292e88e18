// The segmat_mesh command-line program: outputs, JSON, exit codes and messages.
#include <segmat/io/seg.h>

#include <util/run_program.h>
#include <util/temp_files.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

using namespace segmat;

namespace {

const std::string kTeddy = std::string(SEGMAT_DATA_DIR) + "/teddy/";

} // namespace

TEST(SegmatMesh, WritesSegAndPlyAndPrintsJson)
{
  const std::string prefix = test::scratchDir() + "teddy_cli";
  const test::ProgramRun run =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --json");
  ASSERT_EQ(run.status, 0) << run.err;
  ASSERT_TRUE(test::fileExists(prefix + ".seg"));
  ASSERT_TRUE(test::fileExists(prefix + ".ply"));
  const std::vector<int> labels = io::loadSeg(prefix + ".seg", 19092); // exactly 19092 lines
  EXPECT_EQ(labels.size(), 19092u);
  EXPECT_EQ(test::readWholeFile(prefix + ".ply").rfind("ply", 0), 0u);

  std::istringstream in(run.out);
  boost::property_tree::ptree json;
  boost::property_tree::read_json(in, json);
  EXPECT_EQ(json.get<int>("parts"), 8);
  std::size_t total = 0, n = 0;
  for (const auto& c : json.get_child("face_counts")) {
    total += c.second.get_value<std::size_t>();
    ++n;
  }
  EXPECT_EQ(n, 8u);
  EXPECT_EQ(total, 19092u);
  for (const char* stage :
       {"load", "mat", "graph", "tags", "surface_tree", "grow_merge", "transfer", "write"})
    EXPECT_GE(json.get<double>(std::string("seconds.") + stage), 0.0) << stage;
  EXPECT_EQ(json.get<double>("seconds.mat"), 0.0); // given, not computed
  EXPECT_FALSE(json.get<bool>("mat_computed"));
  EXPECT_EQ(json.get<int>("samples"), 0); // nothing sampled
  EXPECT_EQ(json.get<int>("initial_spheres"), 0);
  EXPECT_EQ(json.get<int>("base_spheres"), 2000);

  // Plain output says the same.
  const test::ProgramRun plain =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix + "_plain"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.out.find("parts: 8"), std::string::npos) << plain.out;
  EXPECT_EQ(io::loadSeg(prefix + "_plain.seg"), labels);
}

TEST(SegmatMesh, ComputesTheMedialMeshesWhenNotGiven)
{
  const std::string prefix = test::scratchDir() + "teddy_nomat";
  const test::ProgramRun run =
      test::runProgram("segmat_mesh", kTeddy + "teddy.off -o " + prefix + " --save-mat --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const std::vector<int> labels = io::loadSeg(prefix + ".seg", 19092); // exactly 19092 lines
  EXPECT_EQ(labels.size(), 19092u);
  ASSERT_TRUE(test::fileExists(prefix + ".ply"));
  // The computed medial meshes, in Q-MAT's .ma format: "V E F" header, then V sphere lines.
  const std::string base = test::readWholeFile(prefix + "_base.ma");
  const std::string structured = test::readWholeFile(prefix + "_struct.ma");
  EXPECT_EQ(base.rfind("2000 ", 0), 0u) << base.substr(0, 40);
  EXPECT_FALSE(structured.empty());

  std::istringstream in(run.out);
  boost::property_tree::ptree json;
  boost::property_tree::read_json(in, json);
  EXPECT_TRUE(json.get<bool>("mat_computed"));
  EXPECT_EQ(json.get<int>("base_spheres"), 2000);
  EXPECT_GE(json.get<int>("structured_spheres"), 15); // the estimator's lower bound
  // Every one of teddy's 9548 vertices is a sample, within the default limit of 12000; the
  // base MAT's 2000 spheres are simplified from the initial ones.
  EXPECT_GE(json.get<int>("samples"), 9548);
  EXPECT_LE(json.get<int>("samples"), 12000);
  EXPECT_GT(json.get<int>("initial_spheres"), 2000);
  EXPECT_EQ(json.get<int>("parts"), 8);
  std::size_t total = 0;
  for (const auto& c : json.get_child("face_counts"))
    total += c.second.get_value<std::size_t>();
  EXPECT_EQ(total, 19092u);
  for (const char* stage :
       {"load", "mat", "graph", "tags", "surface_tree", "grow_merge", "transfer", "write"})
    EXPECT_GE(json.get<double>(std::string("seconds.") + stage), 0.0) << stage;
  EXPECT_GT(json.get<double>("seconds.mat"), 0.0);

  // The saved medial meshes given back with -b/-s give the same labels.
  const test::ProgramRun again =
      test::runProgram("segmat_mesh", kTeddy + "teddy.off -b " + prefix + "_base.ma -s " + prefix +
                                          "_struct.ma -o " + prefix + "_given");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(io::loadSeg(prefix + "_given.seg"), labels);
}

TEST(SegmatMesh, BadInputNamesTheFileAndFails)
{
  const std::string prefix = test::scratchDir() + "bad_cli";
  // Missing mesh file.
  test::ProgramRun run = test::runProgram(
      "segmat_mesh", kTeddy + "no_such.off -b " + kTeddy + "teddy_mat.ma -s " + kTeddy +
                         "teddy_smat.ma -o " + prefix);
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("no_such.off"), std::string::npos) << run.err;
  EXPECT_FALSE(test::fileExists(prefix + ".seg"));

  // Malformed base MAT.
  const std::string broken = test::writeScratchFile("broken.ma", "3 0 0\nv 0 0 0 1\nv 1 0 zz 1\n");
  run = test::runProgram("segmat_mesh", kTeddy + "teddy.off -b " + broken + " -s " + kTeddy +
                                            "teddy_smat.ma -o " + prefix);
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("broken.ma"), std::string::npos) << run.err;
  EXPECT_FALSE(test::fileExists(prefix + ".seg"));

  // Usage errors (exit 2): one medial mesh without the other, no -o, --save-mat with given ones.
  run = test::runProgram("segmat_mesh", kTeddy + "teddy.off -b " + kTeddy + "teddy_mat.ma -o " +
                                            prefix);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("usage"), std::string::npos);
  EXPECT_NE(run.err.find("-b and -s"), std::string::npos) << run.err;
  run = test::runProgram("segmat_mesh", kTeddy + "teddy.off -s " + kTeddy + "teddy_smat.ma -o " +
                                            prefix);
  EXPECT_EQ(run.status, 2);
  run = test::runProgram("segmat_mesh", kTeddy + "teddy.off");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("usage"), std::string::npos);
  run = test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --save-mat");
  EXPECT_EQ(run.status, 2);

  // A mesh that encloses nothing: the medial meshes cannot be computed (exit 1, a message).
  const std::string sheet = test::writeScratchFile(
      "sheet.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  run = test::runProgram("segmat_mesh", sheet + " -o " + prefix);
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.err.find("sheet.off"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("MedialMeshEstimation"), std::string::npos) << run.err;
  run = test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " -g abc");
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("-g"), std::string::npos);
  run = test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --max-bend 0");
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("--max-bend"), std::string::npos) << run.err;
  EXPECT_FALSE(test::fileExists(prefix + ".seg"));
}

// --boxes and --hierarchy are outputs of the run like the labels: they appear with them, and a
// run whose extra output cannot be written leaves no output at all, before any work is done.
TEST(SegmatMesh, BoxesAndHierarchyAppearTogetherWithTheLabels)
{
  const std::string prefix = test::scratchDir() + "teddy_all";
  const test::ProgramRun run =
    test::runProgram("segmat_mesh", test::teddyMeshArgs(prefix) + " --boxes --hierarchy");
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* suffix : {".seg", ".ply", "_boxes.json", "_boxes.ply", "_level0.seg",
                             "_level1.seg", "_level2.seg", "_hierarchy.json"})
    EXPECT_TRUE(test::fileExists(prefix + suffix)) << suffix;

  const std::string other = test::scratchDir() + "teddy_none";
  const test::ProgramRun refused = test::runProgram(
    "segmat_mesh", test::teddyMeshArgs(other) + " --boxes --png " + test::scratchDir() +
                       "no_such_folder/teddy.png");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("no_such_folder"), std::string::npos) << refused.err;
  for (const char* suffix : {".seg", ".ply", "_boxes.json", "_boxes.ply"})
    EXPECT_FALSE(test::fileExists(other + suffix)) << suffix;
}
