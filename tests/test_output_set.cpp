// io::OutputSet and io::checkOutputPath: outputs checked up front, written together or not at
// all, temporaries removed on signals and by the next run.
#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/seg.h>

#include "util/temp_files.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace segmat;

namespace {
std::string
freshDir(const std::string& name)
{
  const std::string dir = test::scratchDir() + name + "/";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
} // namespace

TEST(OutputSet, CheckOutputPathRefusesInputsDirectoriesDevicesAndMissingFolders)
{
  const std::string dir = freshDir("check");
  const std::string input = test::writeScratchFile("check/in.off", "OFF\n0 0 0\n");
  EXPECT_TRUE(test::throwsFileError([&] { io::checkOutputPath(input, {input}); }, input, 0,
                                    "refusing to overwrite an input"));
  // The same file under another name: a hard link and a symbolic link.
  std::filesystem::create_hard_link(input, dir + "hard.off");
  std::filesystem::create_symlink(input, dir + "soft.off");
  for (const std::string& alias : {dir + "hard.off", dir + "soft.off", dir + "./in.off"})
    EXPECT_TRUE(test::throwsFileError([&] { io::checkOutputPath(alias, {input}); }, alias, 0,
                                      "refusing to overwrite an input"));
  EXPECT_TRUE(test::throwsFileError([&] { io::checkOutputPath(dir, {}); }, dir, 0,
                                    "is a directory"));
  EXPECT_TRUE(test::throwsFileError([&] { io::checkOutputPath("/dev/full", {}); }, "/dev/full",
                                    0, "not a regular file"));
  EXPECT_TRUE(test::throwsFileError([&] { io::checkOutputPath(dir + "no/x.seg", {}); },
                                    dir + "no/x.seg", 0, "does not exist"));
  EXPECT_NO_THROW(io::checkOutputPath(dir + "new.seg", {input}));
  EXPECT_NO_THROW(io::checkOutputPath("relative_name.seg", {input}));
}

TEST(OutputSet, CommitsEveryFileOrNone)
{
  const std::string dir = freshDir("commit");
  {
    io::OutputSet outputs;
    outputs.add(dir + "a.seg");
    outputs.add(dir + "b.seg");
    io::saveSeg(outputs.temporary(dir + "a.seg"), {1, 2});
    // b is never written: commit fails and a must not appear.
    EXPECT_TRUE(test::throwsFileError([&] { outputs.commit(); }, dir + "b.seg", 0,
                                      "was not written"));
  }
  EXPECT_FALSE(test::fileExists(dir + "a.seg"));
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "temporaries left behind";
  {
    io::OutputSet outputs;
    outputs.add(dir + "a.seg");
    outputs.add(dir + "b.seg");
    io::saveSeg(outputs.temporary(dir + "a.seg"), {1, 2});
    io::saveSeg(outputs.temporary(dir + "b.seg"), {3});
    EXPECT_FALSE(test::fileExists(dir + "a.seg"));
    outputs.commit();
  }
  EXPECT_EQ(io::loadSeg(dir + "a.seg"), (std::vector<int>{1, 2}));
  EXPECT_EQ(io::loadSeg(dir + "b.seg"), (std::vector<int>{3}));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            2);
  io::OutputSet twice;
  twice.add(dir + "c.seg");
  EXPECT_TRUE(test::throwsFileError([&] { twice.add(dir + "c.seg"); }, dir + "c.seg", 0,
                                    "given twice"));
}

TEST(OutputSet, ASignalRemovesTheTemporariesAndWritesNothing)
{
  const std::string dir = freshDir("signal");
  for (int signal_number : {SIGINT, SIGTERM}) {
    const pid_t child = fork();
    if (child == 0) {
      io::removeTemporariesOnSignal();
      io::OutputSet outputs;
      outputs.add(dir + "a.seg");
      outputs.add(dir + "b.seg");
      io::saveSeg(outputs.temporary(dir + "a.seg"), {1});
      raise(signal_number); // killed half-way: a is written, b is not
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number);
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << "left after signal " << signal_number;
  }
}

TEST(OutputSet, StaleTemporariesOfDeadProcessesOnly)
{
  const std::string dir = freshDir("stale");
  const pid_t child = fork();
  if (child == 0)
    _exit(0);
  waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child), alive = std::to_string(getpid());
  for (const std::string& name :
       {"x.seg.tmp" + dead, std::string("x.seg.tmp") + dead + ".tmp" + dead, "x.seg.tmp" + alive,
        std::string("x.seg.tmpnotapid"), "y.seg.tmp" + dead})
    std::ofstream(dir + name) << "partial";
  EXPECT_EQ(io::removeStaleTemporaries(dir + "x.seg"), 2);
  EXPECT_TRUE(test::fileExists(dir + "x.seg.tmp" + alive));
  EXPECT_TRUE(test::fileExists(dir + "x.seg.tmpnotapid"));
  EXPECT_TRUE(test::fileExists(dir + "y.seg.tmp" + dead));
  EXPECT_FALSE(test::fileExists(dir + "x.seg.tmp" + dead));
}
