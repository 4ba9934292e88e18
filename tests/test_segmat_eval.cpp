// segmat_eval (the CLI) and evaluatePsbFolder on the psb-dev data: JSON output against the
// library and the psb-metrics.md fixture, the folder mode, exit codes and messages.
#include <segmat/common/error.h>
#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <util/temp_files.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace segmat;

namespace {

const std::string kPsbDev = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev";

struct CliRun
{
  int status = -1;
  std::string out;
  std::string err;
};

CliRun
runEval(const std::string& args)
{
  const std::string out = test::scratchDir() + "eval.out", err = test::scratchDir() + "eval.err";
  const std::string cmd =
      std::string(SEGMAT_BIN_DIR) + "/segmat_eval " + args + " >" + out + " 2>" + err;
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = test::readWholeFile(out);
  r.err = test::readWholeFile(err);
  return r;
}

boost::property_tree::ptree
parseJson(const std::string& text)
{
  std::istringstream in(text);
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(in, tree);
  return tree;
}

std::string
human(int model, int k)
{
  const std::string n = std::to_string(model);
  return kPsbDev + "/seg/Benchmark/" + n + "/" + n + "_" + std::to_string(k) + ".seg";
}

// A prediction folder holding N.seg = human #0 of each given model.
std::string
predictionFolder(const std::string& name, const std::vector<int>& models)
{
  const std::string dir = test::scratchDir() + name;
  std::filesystem::create_directories(dir);
  for (int m : models)
    io::saveSeg(dir + "/" + std::to_string(m) + ".seg", io::loadSeg(human(m, 0)));
  return dir;
}

class SegmatEval : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    if (!test::fileExists(kPsbDev + "/off/21.off"))
      GTEST_SKIP() << "no " << kPsbDev;
  }
};

} // namespace

TEST_F(SegmatEval, JsonMatchesTheLibraryAndTheFixture)
{
  // Model 21 (Cup, 15 humans): human #0 against all; fixture CD 0.282548, HD 0.053240.
  const TriangleMesh mesh = io::loadOff(kPsbDev + "/off/21.off");
  const PsbEvaluator evaluator(mesh);
  std::vector<std::vector<int>> humans;
  std::string truths;
  for (int k = 0; k < 15; ++k) {
    humans.push_back(io::loadSeg(human(21, k)));
    truths += " " + human(21, k);
  }
  PsbScores lib;
  ASSERT_TRUE(evaluator.scoreAgainstAll(humans[0], humans, lib));

  const CliRun r = runEval("--mesh " + kPsbDev + "/off/21.off --pred " + human(21, 0) + " --truth" +
                        truths + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.out.find('\n'), r.out.size() - 1) << "one line: " << r.out;
  const auto json = parseJson(r.out);
  const std::pair<const char*, double> expected[] = {
      {"RI", lib.RI}, {"CD", lib.CD}, {"GCE", lib.GCE}, {"LCE", lib.LCE}, {"HD", lib.HD},
      {"Rm", lib.Rm}, {"Rf", lib.Rf}, {"GCEf", lib.GCEf}, {"LCEf", lib.LCEf}};
  for (const auto& [key, value] : expected)
    EXPECT_NEAR(json.get<double>(key), value, 1e-9 * (1 + value)) << key;
  EXPECT_EQ(json.get<int>("humans"), 15);
  EXPECT_EQ(json.get<int>("cd_count"), 15);
  EXPECT_NEAR(json.get<double>("CD"), 0.282548, 6e-7);
  EXPECT_NEAR(json.get<double>("HD"), 0.053240, 6e-7);

  // Text mode prints the same numbers in a table.
  const CliRun text = runEval("--mesh " + kPsbDev + "/off/21.off --pred " + human(21, 0) +
                           " --truth" + truths);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("0.2825"), std::string::npos) << text.out;
}

TEST_F(SegmatEval, SingleSegmentPredictionHasNullCD)
{
  const std::size_t n = io::loadOff(kPsbDev + "/off/21.off").numFaces();
  const std::string pred = test::scratchDir() + "one_segment.seg";
  io::saveSeg(pred, std::vector<int>(n, 7));
  const CliRun r = runEval("--mesh " + kPsbDev + "/off/21.off --pred " + pred + " --truth " +
                        human(21, 0) + " " + human(21, 1) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto json = parseJson(r.out);
  EXPECT_EQ(json.get<std::string>("CD"), "null");
  EXPECT_EQ(json.get<int>("cd_count"), 0);
  EXPECT_EQ(json.get<double>("GCE"), 0.0); // trivial case
  EXPECT_EQ(json.get<double>("Rm"), 0.0); // every human segment lies inside the one segment
  EXPECT_GT(json.get<double>("Rf"), 0.01); // ... which matches only the largest of them
}

TEST_F(SegmatEval, BadPredictionFilesExitWithTwoAndNameTheFile)
{
  std::vector<int> labels = io::loadSeg(human(21, 0));
  labels.pop_back(); // one line short: the official reader would silently accept it
  const std::string shorter = test::writeScratchFile("short.seg", [&] {
    std::string s;
    for (int l : labels)
      s += std::to_string(l) + "\n";
    return s;
  }());
  CliRun r = runEval("--mesh " + kPsbDev + "/off/21.off --pred " + shorter + " --truth " +
                  human(21, 0));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(shorter), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(std::to_string(labels.size())), std::string::npos) << r.err;

  const std::string word = test::writeScratchFile("word.seg", "0\n1\nzero\n");
  r = runEval("--mesh " + kPsbDev + "/off/21.off --pred " + word + " --truth " + human(21, 0));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(word + ":3:"), std::string::npos) << r.err;

  r = runEval("--mesh " + kPsbDev + "/off/no_such_mesh.off --pred " + word + " --truth " +
              human(21, 0));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("no_such_mesh.off"), std::string::npos) << r.err;
}

TEST_F(SegmatEval, BadUsageExitsWithTwo)
{
  for (const std::string& args :
       {std::string(), std::string("--bogus"), std::string("--mesh a.off --pred b.seg"),
        std::string("--psb x --pred y --models 5-2"), std::string("--truth")}) {
    const CliRun r = runEval(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find("usage"), std::string::npos) << args;
  }
  EXPECT_EQ(runEval("--help").status, 0);
}

TEST_F(SegmatEval, FolderModeModelsCategoriesOverall)
{
  // Cup models 21 and 26, human #0 as prediction: fixture CD 0.282548 and 0.029161.
  const std::string pred = predictionFolder("pred_cup", {21, 26});
  const CliRun r = runEval("--psb " + kPsbDev + " --pred " + pred + " --models 21,26 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto json = parseJson(r.out);
  EXPECT_NEAR(json.get<double>("models.21.CD"), 0.282548, 6e-7);
  EXPECT_NEAR(json.get<double>("models.26.CD"), 0.029161, 6e-7);
  EXPECT_EQ(json.get<int>("models.26.humans"), 10);
  EXPECT_EQ(json.get_child("categories").size(), 1u);
  EXPECT_NEAR(json.get<double>("categories.Cup.CD"), (0.282548 + 0.029161) / 2, 1e-6);
  EXPECT_NEAR(json.get<double>("overall.HD"), (0.053240 + 0.004446) / 2, 1e-6);
  EXPECT_EQ(json.get<int>("overall.models"), 2);

  // Without --models: the other 36 meshes have no prediction and are reported as skipped.
  const PsbBenchmarkResult all = evaluatePsbFolder(kPsbDev, pred);
  EXPECT_EQ(all.models.size(), 2u);
  EXPECT_EQ(all.skipped.size(), 36u);
  EXPECT_NEAR(all.overall.CD, json.get<double>("overall.CD"), 1e-9);
  const CliRun text = runEval("--psb " + kPsbDev + " --pred " + pred);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("skipped 36"), std::string::npos) << text.out;

  // A requested model without a prediction is an error naming the missing file.
  const CliRun missing = runEval("--psb " + kPsbDev + " --pred " + pred + " --models 21,41");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("41.seg"), std::string::npos) << missing.err;
  EXPECT_THROW(evaluatePsbFolder(kPsbDev, pred, {21, 41}), Error);
}

TEST(PsbCategories, NamesByIdRange)
{
  EXPECT_STREQ(psbCategoryName(1), "Human");
  EXPECT_STREQ(psbCategoryName(20), "Human");
  EXPECT_STREQ(psbCategoryName(21), "Cup");
  EXPECT_STREQ(psbCategoryName(180), "Teddy");
  EXPECT_STREQ(psbCategoryName(281), "Armadillo");
  EXPECT_STREQ(psbCategoryName(400), "FourLeg");
  EXPECT_STREQ(psbCategoryName(0), "");
  EXPECT_STREQ(psbCategoryName(401), "");
  EXPECT_EQ(psbCategoryIndex(261), 13); // Spring: a valid id range, absent from the data
}
