// MA reader/writer: the authors' teddy MATs, header mismatch warning, exact round trip, malformed
// files.
#include <segmat/common/error.h>
#include <segmat/io/ma.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

using namespace segmat;
using segmat::test::throwsFileError;
using segmat::test::writeScratchFile;

namespace {
// Two spheres joined into a triangle with a third, plus a pure edge to a fourth.
const char* const kSmall = "4 4 1\nv 0 0 0 0.5\nv 1 0 0 0.25\nv 0 1 0 0.125\nv 5 5 5 1\n"
                           "e 0 1\ne 1 2\ne 2 0\ne 3 2\nf 0 1 2\n";

void
expectSmall(const MedialMesh& m)
{
  ASSERT_EQ(m.numVertices(), 4u);
  ASSERT_EQ(m.numEdges(), 4u);
  ASSERT_EQ(m.numTriangles(), 1u);
  EXPECT_EQ(m.sphere(1), Eigen::Vector4d(1, 0, 0, 0.25));
  EXPECT_EQ(m.triangles()[0], Eigen::Vector3i(0, 1, 2));
  const int pure = m.findEdge(2, 3);
  ASSERT_GE(pure, 0);
  EXPECT_TRUE(m.isPureEdge(pure));
}

::testing::AssertionResult
maFails(const std::string& name, const std::string& text, long line, const std::string& needle)
{
  return segmat::test::loadingFails([](const std::string& p) { io::loadMa(p); }, name, text, line,
                                    needle);
}
} // namespace

TEST(LoadMa, Small)
{
  expectSmall(io::loadMa(writeScratchFile("small.ma", kSmall)));
}

TEST(LoadMa, CrlfNoHeaderNormalsAndAnyOrder)
{
  // Edges and the face before the spheres, no header, normals, CRLF, a blank line.
  expectSmall(io::loadMa(writeScratchFile(
      "order.ma", "f 0 1 2\r\ne 0 1\r\ne 1 2\r\n\r\ne 2 0\r\ne 3 2\r\nv 0 0 0 0.5\r\nn 0 0 1\r\n"
                  "v 1 0 0 0.25\r\nv 0 1 0 0.125\r\nv 5 5 5 1\r\n")));
}

TEST(LoadMa, TeddyMat)
{
  const MedialMesh m = io::loadMa(SEGMAT_DATA_DIR "/teddy/teddy_mat.ma");
  // Counted in the file: 2000 v, 5736 e, 3744 f; radii in [0.0272, 0.2825]; centre diagonal 2.0919;
  // edge valence histogram {0: 3 pure, 1: 803, 2: 4411, 3: 473, 4: 42, 5: 4}.
  ASSERT_EQ(m.numVertices(), 2000u);
  EXPECT_EQ(m.numEdges(), 5736u);
  EXPECT_EQ(m.numTriangles(), 3744u);
  const auto [lo, hi] = std::minmax_element(m.radii().begin(), m.radii().end());
  EXPECT_NEAR(*lo, 0.0272, 5e-5);
  EXPECT_NEAR(*hi, 0.2825, 5e-5);
  EXPECT_NEAR(m.centerBoundingBoxDiagonal(), 2.0919, 5e-5);
  std::map<int, int> valence;
  for (std::size_t e = 0; e < m.numEdges(); ++e)
    ++valence[m.edgeTriangleCount(static_cast<int>(e))];
  EXPECT_EQ(valence, (std::map<int, int>{{0, 3}, {1, 803}, {2, 4411}, {3, 473}, {4, 42}, {5, 4}}));
  // First v line of the file, read to the last digit.
  EXPECT_EQ(m.sphere(0), Eigen::Vector4d(0.202462980052705, -0.519486780712404, 0.013547017299200,
                                         0.095510755656680));
}

TEST(LoadMa, TeddySmatWrongHeaderWarnsAndLoads)
{
  // The released file's header says 15 22 8; it holds 15 v, 18 e (9 pure) and 4 f lines.
  ::testing::internal::CaptureStderr();
  const MedialMesh m = io::loadMa(SEGMAT_DATA_DIR "/teddy/teddy_smat.ma");
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(m.numVertices(), 15u);
  EXPECT_EQ(m.numEdges(), 18u);
  EXPECT_EQ(m.numTriangles(), 4u);
  int pure = 0;
  for (std::size_t e = 0; e < m.numEdges(); ++e)
    pure += m.isPureEdge(static_cast<int>(e));
  EXPECT_EQ(pure, 9);
  EXPECT_NE(warning.find("teddy_smat.ma"), std::string::npos) << warning;
  EXPECT_NE(warning.find("15 22 8"), std::string::npos) << warning;
  EXPECT_NE(warning.find("15 v, 18 e and 4 f"), std::string::npos) << warning;
}

TEST(SaveMa, TeddyRoundTripIsExact)
{
  const MedialMesh m = io::loadMa(SEGMAT_DATA_DIR "/teddy/teddy_mat.ma");
  const std::string path = segmat::test::scratchDir() + "teddy_roundtrip.ma";
  io::saveMa(path, m);
  const std::string first_bytes = segmat::test::readWholeFile(path);
  EXPECT_EQ(first_bytes.substr(0, first_bytes.find('\n')), "2000 5736 3744");
  ::testing::internal::CaptureStderr();
  const MedialMesh back = io::loadMa(path);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), ""); // a correct header: no warning
  EXPECT_EQ(back.centers(), m.centers());
  EXPECT_EQ(back.radii(), m.radii());
  EXPECT_EQ(back.edges(), m.edges());
  EXPECT_EQ(back.triangles(), m.triangles());
  io::saveMa(path, back);
  EXPECT_EQ(segmat::test::readWholeFile(path), first_bytes);
}

TEST(SaveMa, AwkwardDoublesRoundTrip)
{
  const MedialMesh m({{0.1, 1.0 / 3.0, -1e-310}, {1e300, -0.0, 2.0 / 3.0}}, {1e-17, 0.0}, {{0, 1}},
                     {});
  const std::string path = segmat::test::scratchDir() + "awkward.ma";
  io::saveMa(path, m);
  const MedialMesh back = io::loadMa(path);
  EXPECT_EQ(back.centers(), m.centers());
  EXPECT_EQ(back.radii(), m.radii());
  EXPECT_EQ(back.edges(), m.edges());
}

// ---- Malformed-file catalogue ----

TEST(LoadMaErrors, MissingAndEmpty)
{
  const std::string path = segmat::test::scratchDir() + "missing.ma";
  EXPECT_TRUE(throwsFileError([&] { io::loadMa(path); }, path, 0, "cannot open"));
  EXPECT_TRUE(maFails("empty.ma", "", 0, "empty file"));
  EXPECT_TRUE(maFails("blank.ma", "\r\n\r\n", 0, "empty file"));
}

TEST(LoadMaErrors, BadHeader)
{
  EXPECT_TRUE(maFails("short_header.ma", "15 22\nv 0 0 0 1\n", 1, "missing count"));
  EXPECT_TRUE(maFails("word_header.ma", "abc 1 1\n", 1, "'abc' is not an integer"));
  EXPECT_TRUE(maFails("neg_header.ma", "1 -1 0\nv 0 0 0 1\n", 1, "negative count"));
  EXPECT_TRUE(maFails("long_header.ma", "1 0 0 7\nv 0 0 0 1\n", 1, "unexpected '7'"));
}

TEST(LoadMaErrors, UnknownTag)
{
  EXPECT_TRUE(maFails("tag.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\nx 0 1\n", 4, "unknown tag 'x'"));
  EXPECT_TRUE(maFails("number_line.ma", "2 1 0\nv 0 0 0 1\n3 4 5\n", 3, "unknown tag '3'"));
}

TEST(LoadMaErrors, WrongNumberOfValues)
{
  EXPECT_TRUE(maFails("v3.ma", "1 0 0\nv 0 0 0\n", 2, "'v' line needs 4 values, has 3"));
  EXPECT_TRUE(maFails("v5.ma", "1 0 0\nv 0 0 0 1 9\n", 2, "has more: '9'"));
  EXPECT_TRUE(maFails("e1.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0\n", 4, "'e' line needs 2"));
  EXPECT_TRUE(
      maFails("f4.ma", "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 1 2 0\n", 5, "has more"));
}

TEST(LoadMaErrors, BadRadius)
{
  EXPECT_TRUE(maFails("negr.ma", "2 0 0\nv 0 0 0 1\nv 1 0 0 -0.5\n", 3, "is negative"));
  EXPECT_TRUE(
      maFails("nanr.ma", "2 0 0\nv 0 0 0 1\nv 1 0 0 nan\n", 3, "radius 'nan' is not finite"));
  EXPECT_TRUE(maFails("nanc.ma", "2 0 0\nv 0 0 0 1\nv 1 -inf 0 1\n", 3, "not finite"));
  EXPECT_TRUE(maFails("wordr.ma", "1 0 0\nv 0 0 0 big\n", 2, "'big' is not a number"));
}

TEST(LoadMaErrors, IndexOutOfRange)
{
  EXPECT_TRUE(maFails("edge_oob.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 2\n", 4,
                      "edge refers to sphere 2 but the file has 2 spheres"));
  // The bad face comes before the spheres: still reported at its own line.
  EXPECT_TRUE(maFails("face_oob.ma", "f 0 1 3\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\n", 1,
                      "triangle refers to sphere 3"));
  EXPECT_TRUE(
      maFails("neg_index.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne -1 0\n", 4, "refers to sphere -1"));
  EXPECT_TRUE(maFails("float_index.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1.0\n", 4,
                      "'1.0' is not an integer"));
}

TEST(LoadMaErrors, BinaryJunk)
{
  EXPECT_TRUE(maFails("junk.ma", std::string("1 0 0\nv 0 0 0 1\n\x7f\x45\x4c\x46\x02", 17), 3,
                      "binary data"));
}

TEST(LoadMaErrors, DamagedCopiesFailCleanly)
{
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly(
      "damaged.ma", kSmall, [](const std::string& path) { io::loadMa(path); }));
}
