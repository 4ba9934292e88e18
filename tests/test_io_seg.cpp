// SEG reader/writer: strict one-label-per-line files, counts, the bundled teddy segmentations.
#include <segmat/common/error.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace segmat;
using segmat::test::throwsFileError;
using segmat::test::writeScratchFile;

namespace {
::testing::AssertionResult
segFails(const std::string& name, const std::string& text, long expected, long line,
         const std::string& needle)
{
  return segmat::test::loadingFails([&](const std::string& p) { io::loadSeg(p, expected); }, name,
                                    text, line, needle);
}
} // namespace

TEST(LoadSeg, PlainCrlfBlankLinesAndSpaces)
{
  EXPECT_EQ(io::loadSeg(writeScratchFile("a.seg", "0\n1\n1\n2\n")), (std::vector<int>{0, 1, 1, 2}));
  EXPECT_EQ(io::loadSeg(writeScratchFile("b.seg", " 3 \r\n\r\n-1\r\n+7\r\n12"), 4),
            (std::vector<int>{3, -1, 7, 12}));
}

TEST(LoadSeg, TeddyHumanSegmentation)
{
  const std::vector<int> labels = io::loadSeg(SEGMAT_DATA_DIR "/teddy/seg/180_0.seg", 19092);
  ASSERT_EQ(labels.size(), 19092u);
  EXPECT_EQ(labels.front(), 0); // the file starts "0\n0\n0\n"
  EXPECT_GE(*std::min_element(labels.begin(), labels.end()), 0);
  EXPECT_GT(*std::max_element(labels.begin(), labels.end()), 0);
}

TEST(LoadSeg, EmptyFileOnlyForZeroFaces)
{
  EXPECT_TRUE(io::loadSeg(writeScratchFile("zero.seg", "\n"), 0).empty());
  EXPECT_TRUE(segFails("empty.seg", "", -1, 0, "empty file"));
  EXPECT_TRUE(segFails("empty2.seg", "\n \n", 5, 0, "empty file"));
}

TEST(LoadSegErrors, MissingFile)
{
  const std::string path = segmat::test::scratchDir() + "missing.seg";
  EXPECT_TRUE(throwsFileError([&] { io::loadSeg(path); }, path, 0, "cannot open"));
}

TEST(LoadSegErrors, NotAnInteger)
{
  EXPECT_TRUE(segFails("abc.seg", "0\n0\n1\n1\n\n2\nabc\n2\n", -1, 7, "'abc' is not an integer"));
  EXPECT_TRUE(segFails("float.seg", "0\n1.0\n", -1, 2, "'1.0' is not an integer"));
  EXPECT_TRUE(segFails("huge.seg", "0\n99999999999\n", -1, 2, "out of range"));
  EXPECT_TRUE(segFails("hash.seg", "# labels\n0\n", -1, 1, "'#' is not an integer"));
}

TEST(LoadSegErrors, TwoLabelsOnALine)
{
  EXPECT_TRUE(segFails("two.seg", "0\n1 2\n", -1, 2, "more than one label"));
}

TEST(LoadSegErrors, WrongCount)
{
  std::string text;
  for (int i = 0; i < 100; ++i)
    text += std::to_string(i % 3) + "\n";
  EXPECT_TRUE(segFails("short.seg", text, 102, 0, "has 100 labels, the mesh has 102 faces"));
  EXPECT_TRUE(segFails("long.seg", text, 99, 0, "has 100 labels, the mesh has 99 faces"));
  EXPECT_EQ(io::loadSeg(writeScratchFile("exact.seg", text), 100).size(), 100u);
}

TEST(LoadSegErrors, BinaryJunk)
{
  EXPECT_TRUE(segFails("junk.seg", std::string("0\n1\n\x01\x02\x00", 7), -1, 3, "binary data"));
}

TEST(SaveSeg, RoundTripAndExactText)
{
  const std::vector<int> labels{0, 5, -1, 2147483647, 3};
  const std::string path = segmat::test::scratchDir() + "out.seg";
  io::saveSeg(path, labels);
  EXPECT_EQ(segmat::test::readWholeFile(path), "0\n5\n-1\n2147483647\n3\n");
  EXPECT_EQ(io::loadSeg(path, 5), labels);
}

TEST(LoadSeg, EveryPsbDevSegmentationMatchesItsMesh)
{
  // The 38 development meshes and their human segmentations (../shared/data, present in CI).
  const std::string root = SEGMAT_SHARED_DATA_DIR "/psb-dev";
  if (!segmat::test::fileExists(root + "/off"))
    GTEST_SKIP() << root << " is not present";
  int meshes = 0, segmentations = 0;
  for (int id = 1; id <= 400; ++id) {
    const std::string off = root + "/off/" + std::to_string(id) + ".off";
    if (!segmat::test::fileExists(off))
      continue;
    const long faces = static_cast<long>(io::loadOff(off).numFaces());
    ++meshes;
    for (int k = 0;; ++k) {
      const std::string seg = root + "/seg/Benchmark/" + std::to_string(id) + "/" +
                              std::to_string(id) + "_" + std::to_string(k) + ".seg";
      if (!segmat::test::fileExists(seg))
        break;
      EXPECT_NO_THROW(io::loadSeg(seg, faces)) << seg;
      ++segmentations;
    }
  }
  EXPECT_EQ(meshes, 38);
  EXPECT_EQ(segmentations, 443);
}
