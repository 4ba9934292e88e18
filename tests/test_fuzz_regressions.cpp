// Replays every file of tests/fuzz/regressions/ (inputs the fuzz targets of tests/fuzz/ once
// crashed or hung on, and hand-made hostile files) through the reader its extension selects:
// each must be read or refused with segmat::Error, within the test's time.
#include "read_any.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace {
std::vector<std::string>
regressionFiles()
{
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(SEGMAT_FUZZ_REGRESSIONS_DIR))
    if (entry.is_regular_file() && entry.path().extension() != ".md")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}
} // namespace

TEST(FuzzRegressions, EveryPastFindingIsReadOrRefusedWithAnError)
{
  const std::vector<std::string> files = regressionFiles();
  std::set<std::string> formats;
  for (const std::string& path : files) {
    formats.insert(segmat::io::extensionOf(path));
    EXPECT_NO_THROW(segmat::test::readAny(path)) << path;
  }
  // The corpus covers every reader.
  EXPECT_EQ(formats, (std::set<std::string>{"off", "ply", "obj", "stl", "pcd", "ma", "seg"}));
}
