// The bad-input catalogue: one test per class of bad input or misuse the programs must catch,
// each with the exit status (0 ok, 1 computation failed, 2 bad usage or input) and the message.
#include <segmat/io/ma.h>
#include <segmat/io/off.h>

#include "util/run_program.h"
#include "util/synthetic_mesh.h"
#include "util/temp_files.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

using namespace segmat;

namespace {
const std::string kTeddy = std::string(SEGMAT_DATA_DIR) + "/teddy/teddy.off";

// A small closed mesh that segmat_mat handles in well under a second.
std::string
capsuleOff()
{
  const std::string path = test::scratchDir() + "bad_inputs_capsule.off";
  if (!test::fileExists(path))
    io::saveOff(path, test::capsule(0.3, 2.0, 24, 12, 6));
  return path;
}

bool
contains(const std::string& text, const std::string& needle)
{
  return text.find(needle) != std::string::npos;
}
} // namespace

TEST(BadInputs, OutputThatIsTheInputIsRefusedAndTheInputKept)
{
  const std::string dir = test::scratchDir() + "same/";
  std::filesystem::create_directories(dir);
  const std::string mesh = dir + "shape.off";
  io::saveOff(mesh, test::capsule(0.3, 2.0, 24, 12, 6));
  const std::string before = test::readWholeFile(mesh);
  // segmat_mesh shape.ply -o shape would write shape.ply over its input.
  const std::string ply = dir + "shape.ply";
  test::ProgramRun mesh_run = test::runProgram("segmat_mesh", mesh + " -o " + dir + "shape --threads 1");
  EXPECT_EQ(mesh_run.status, 0) << mesh_run.err; // shape.seg and shape.ply, input shape.off
  const std::string written = test::readWholeFile(ply);
  mesh_run = test::runProgram("segmat_mesh", ply + " -o " + dir + "shape");
  EXPECT_EQ(mesh_run.status, 2);
  EXPECT_TRUE(contains(mesh_run.err, "refusing to overwrite an input")) << mesh_run.err;
  EXPECT_TRUE(contains(mesh_run.err, ply)) << mesh_run.err;
  EXPECT_EQ(test::readWholeFile(ply), written);

  // Through a symbolic link to the input.
  std::filesystem::create_symlink(mesh, dir + "link_base.ma");
  const test::ProgramRun linked = test::runProgram("segmat_mat", mesh + " -o " + dir + "link");
  EXPECT_EQ(linked.status, 2);
  EXPECT_TRUE(contains(linked.err, "refusing to overwrite an input")) << linked.err;
  EXPECT_EQ(test::readWholeFile(mesh), before);
}

TEST(BadInputs, OutputLocationIsCheckedBeforeComputing)
{
  const std::string dir = test::scratchDir() + "outloc/";
  std::filesystem::create_directories(dir);
  // A bare directory as prefix: no hidden dir/.seg.
  test::ProgramRun run = test::runProgram("segmat_mesh", kTeddy + " -o " + dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "not a directory")) << run.err;
  EXPECT_FALSE(test::fileExists(dir + ".seg"));
  EXPECT_FALSE(test::fileExists(dir + ".ply"));
  // A directory that does not exist: refused at once (the teddy would take seconds).
  run = test::runProgram("segmat_mesh", kTeddy + " -o " + dir + "missing/teddy");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "does not exist")) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  // A device.
  run = test::runProgram("segmat_mat", capsuleOff() + " -o /dev/full");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "/dev/full")) << run.err;
  EXPECT_FALSE(test::fileExists("/dev/full_base.ma"));
  // An existing output that is not a regular file.
  std::filesystem::create_directories(dir + "taken_base.ma");
  run = test::runProgram("segmat_mat", capsuleOff() + " -o " + dir + "taken");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, dir + "taken_base.ma")) << run.err;
  EXPECT_FALSE(test::fileExists(dir + "taken_struct.ma"));
}

TEST(BadInputs, StaleTemporariesOfADeadRunAreRemoved)
{
  const std::string dir = test::scratchDir() + "stale/";
  std::filesystem::create_directories(dir);
  // A process id that surely no longer runs: a child that has exited and been reaped.
  const pid_t child = fork();
  if (child == 0)
    _exit(0);
  waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child);
  const std::string stale = dir + "cap_base.ma.tmp" + dead;
  test::writeScratchFile("stale/cap_base.ma.tmp" + dead, "partial");
  test::writeScratchFile("stale/cap_struct.ma.tmp" + dead + ".tmp" + dead, "partial");
  // A live process's temporary (ours) stays.
  const std::string live = "stale/cap_base.ma.tmp" + std::to_string(getpid());
  test::writeScratchFile(live, "in progress");
  const test::ProgramRun run = test::runProgram("segmat_mat", capsuleOff() + " -o " + dir + "cap");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_FALSE(test::fileExists(stale));
  EXPECT_FALSE(test::fileExists(dir + "cap_struct.ma.tmp" + dead + ".tmp" + dead));
  EXPECT_TRUE(test::fileExists(test::scratchDir() + live));
  EXPECT_TRUE(test::fileExists(dir + "cap_base.ma"));
}

TEST(BadInputs, DirectoryAsInputIsNamed)
{
  const std::string dir = test::scratchDir() + "a_folder.off";
  std::filesystem::create_directories(dir);
  for (const char* program : {"segmat_mesh", "segmat_mat"}) {
    const test::ProgramRun run = test::runProgram(program, dir + " -o " + test::scratchDir() + "x");
    EXPECT_EQ(run.status, 2) << program;
    EXPECT_TRUE(contains(run.err, dir + ": is a directory")) << program << ": " << run.err;
  }
  std::filesystem::create_directories(test::scratchDir() + "a_folder.pcd");
  const test::ProgramRun run = test::runProgram(
      "segmat_cloud", test::scratchDir() + "a_folder.pcd -o " + test::scratchDir() + "x");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "a_folder.pcd: is a directory")) << run.err;
}

TEST(BadInputs, AsciiStlErrorsCarryNoTerminalColours)
{
  const std::string stl = test::writeScratchFile(
      "broken.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n"
                    "endloop\nendfacet\nendsolid x\n");
  const test::ProgramRun run = test::runProgram("segmat_mesh", stl + " -o " + test::scratchDir() + "stl");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, stl)) << run.err;
  EXPECT_FALSE(contains(run.err, "\033[")) << run.err;
}

TEST(BadInputs, CoordinatesNearTheDoubleLimitReportAnOverflow)
{
  const std::string off = test::writeScratchFile(
      "huge.off", "OFF\n4 4 0\n-1e308 -1e308 -1e308\n1e308 -1e308 -1e308\n-1e308 1e308 -1e308\n"
                  "-1e308 -1e308 1e308\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  for (const char* program : {"segmat_mesh", "segmat_mat"}) {
    const test::ProgramRun run = test::runProgram(program, off + " -o " + test::scratchDir() + "huge");
    EXPECT_EQ(run.status, 2) << program;
    EXPECT_TRUE(contains(run.err, "overflow")) << program << ": " << run.err;
    EXPECT_FALSE(contains(run.err, "no extent")) << run.err;
  }
}

TEST(BadInputs, GivenMedialMeshesMustFitTheMesh)
{
  const MedialMesh base = io::loadMa(std::string(SEGMAT_DATA_DIR) + "/teddy/teddy_mat.ma");
  const std::string structured = std::string(SEGMAT_DATA_DIR) + "/teddy/teddy_smat.ma";
  // One absurd radius.
  std::vector<double> radii = base.radii();
  radii[7] = 50.0;
  const std::string absurd = test::scratchDir() + "absurd.ma";
  io::saveMa(absurd, MedialMesh(base.centers(), radii, base.edges(), base.triangles()));
  test::ProgramRun run = test::runProgram(
      "segmat_mesh", kTeddy + " -b " + absurd + " -s " + structured + " -o " + test::scratchDir() + "t");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, absurd + ": does not fit the mesh")) << run.err;
  EXPECT_TRUE(contains(run.err, "sphere 7")) << run.err;
  // Another shape's MAT: the teddy's moved by three of its sizes.
  std::vector<Eigen::Vector3d> centres = base.centers();
  for (Eigen::Vector3d& c : centres)
    c.x() += 3.0;
  const std::string other = test::scratchDir() + "other.ma";
  io::saveMa(other, MedialMesh(centres, base.radii(), base.edges(), base.triangles()));
  run = test::runProgram("segmat_mesh", kTeddy + " -b " + other + " -s " + structured + " -o " +
                                            test::scratchDir() + "t");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, other)) << run.err;
  EXPECT_TRUE(contains(run.err, "another shape")) << run.err;
}

TEST(BadInputs, ThreadCountsAboveTheMachineAreClampedWithAWarning)
{
  for (const char* program : {"segmat_mat", "segmat_mesh"}) {
    const test::ProgramRun run =
        test::runProgram(program, capsuleOff() + " -o " + test::scratchDir() + "threads_" + program +
                                      " --threads 100000");
    EXPECT_EQ(run.status, 0) << program << ": " << run.err;
    EXPECT_TRUE(contains(run.err, "warning: --threads 100000 is more than the machine's"))
        << program << ": " << run.err;
  }
}

TEST(BadInputs, ASamplingBeyondTheMemoryStopsAtOnce)
{
  const test::ProgramRun run = test::runProgram(
      "segmat_mat", kTeddy + " -o " + test::scratchDir() + "dense --spacing 1e-6 --max-samples 0");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "GB available")) << run.err;
  EXPECT_TRUE(contains(run.err, kTeddy)) << run.err;
}

TEST(BadInputs, OpenSurfacesAreNamedInAWarning)
{
  // The capsule without its last face: three boundary edges.
  TriangleMesh open = test::capsule(0.3, 2.0, 24, 12, 6);
  open.faces.pop_back();
  const std::string path = test::scratchDir() + "open_capsule.off";
  io::saveOff(path, open);
  const test::ProgramRun run = test::runProgram("segmat_mat", path + " -o " + test::scratchDir() + "open");
  EXPECT_TRUE(contains(run.err, path + " is not a closed manifold surface: 3 boundary edge(s), 0 "
                                       "non-manifold"))
      << run.err;
}

TEST(BadInputs, UsageErrorsExitWithTwoEverywhere)
{
  for (const char* program : {"segmat_mesh", "segmat_mat", "segmat_cloud", "segmat_eval"}) {
    test::ProgramRun run = test::runProgram(program, "--no-such-option");
    EXPECT_EQ(run.status, 2) << program;
    EXPECT_TRUE(contains(run.err, "unknown option --no-such-option")) << program << run.err;
    run = test::runProgram(program, "--help");
    EXPECT_EQ(run.status, 0) << program;
    for (const char* section : {"usage:", "example:", "Input:", "Output:", "exit status: 0"})
      EXPECT_TRUE(contains(run.out, section)) << program << " --help lacks " << section;
  }
  for (const char* program : {"segmat_mesh", "segmat_mat", "segmat_cloud"}) {
    const test::ProgramRun run = test::runProgram(program, "--help");
    for (const char* section : {"Parameters:", "Performance:", "--threads", "--quiet"})
      EXPECT_TRUE(contains(run.out, section)) << program << " --help lacks " << section;
  }
  // A missing input file is bad input too (segmat_mat said 1).
  const test::ProgramRun run =
      test::runProgram("segmat_mat", "no_such.off -o " + test::scratchDir() + "none");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "no_such.off")) << run.err;
}
