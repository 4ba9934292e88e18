// The segmat_mat command-line program: files written, counts reported, errors reported.
#include <segmat/io/ma.h>
#include <segmat/io/off.h>

#include "util/run_program.h"
#include "util/synthetic_mesh.h"
#include "util/temp_files.h"

#include <gtest/gtest.h>

#include <string>

using namespace segmat;

TEST(SegmatMat, WritesBothMatsAndReportsThem)
{
  const std::string mesh = test::scratchDir() + "capsule.off";
  io::saveOff(mesh, test::capsule(0.3, 2.0, 24, 12, 6));
  const std::string prefix = test::scratchDir() + "capsule";
  const test::ProgramRun run =
      test::runProgram("segmat_mat", mesh + " -o " + prefix + " --base 120 --struct 5 --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const MedialMesh base = io::loadMa(prefix + "_base.ma");
  const MedialMesh structured = io::loadMa(prefix + "_struct.ma");
  EXPECT_EQ(base.numVertices(), 120u);
  EXPECT_EQ(structured.numVertices(), 5u);
  EXPECT_NE(run.out.find("\"base\": {\"spheres\": 120,"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"structured\": {\"spheres\": 5,"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"simplification\": "), std::string::npos) << run.out;

  const test::ProgramRun text = test::runProgram("segmat_mat", mesh + " -o " + prefix + "_text");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("base MAT    "), std::string::npos) << text.out;
  EXPECT_TRUE(test::fileExists(prefix + "_text_struct.ma"));
}

TEST(SegmatMat, ErrorsExitNonZeroWithAMessage)
{
  const std::string prefix = test::scratchDir() + "bad";
  test::ProgramRun run = test::runProgram("segmat_mat", "no_such.off -o " + prefix);
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("no_such.off"), std::string::npos) << run.err;

  run = test::runProgram("segmat_mat", std::string(SEGMAT_DATA_DIR) + "/teddy/teddy.off");
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("-o PREFIX"), std::string::npos) << run.err;

  run = test::runProgram("segmat_mat", std::string(SEGMAT_DATA_DIR) + "/teddy/teddy.off -o " +
                                           prefix + " --base 0");
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.err.find("--base"), std::string::npos) << run.err;

  // One open triangle encloses no medial sphere: no file may be written.
  const std::string open_mesh =
      test::writeScratchFile("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  run = test::runProgram("segmat_mat", open_mesh + " -o " + prefix);
  EXPECT_NE(run.status, 0);
  EXPECT_FALSE(run.err.empty());
  EXPECT_FALSE(test::fileExists(prefix + "_base.ma"));
}
