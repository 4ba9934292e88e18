// OFF reader/writer: accepted variants, the malformed-file catalogue, the bundled teddy, round
// trip.
#include <segmat/common/error.h>
#include <segmat/io/off.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace segmat;
using segmat::test::throwsFileError;
using segmat::test::writeScratchFile;

namespace {
// A unit square split in two, plus a lifted vertex: 4 vertices, 2 faces.
const char* const kSquare = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n3 0 1 2\n3 0 2 3\n";

void
expectSquare(const TriangleMesh& m)
{
  ASSERT_EQ(m.numVertices(), 4u);
  ASSERT_EQ(m.numFaces(), 2u);
  EXPECT_EQ(m.vertices[3], Eigen::Vector3d(0, 1, 0.5));
  EXPECT_EQ(m.faces[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(m.faces[1], Eigen::Vector3i(0, 2, 3));
}

// Asserts that loading \a text (saved as \a name) fails at \a line with \a needle in the message.
::testing::AssertionResult
offFails(const std::string& name, const std::string& text, long line, const std::string& needle)
{
  return segmat::test::loadingFails([](const std::string& p) { io::loadOff(p); }, name, text, line,
                                    needle);
}
} // namespace

TEST(LoadOff, PlainFile)
{
  expectSquare(io::loadOff(writeScratchFile("plain.off", kSquare)));
}

TEST(LoadOff, CountsGluedToHeaderOrOnItsLine)
{
  expectSquare(io::loadOff(
      writeScratchFile("glued.off", "OFF4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n3 0 1 2\n3 0 2 3\n")));
  expectSquare(io::loadOff(writeScratchFile(
      "sameline.off", "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n3 0 1 2\n3 0 2 3\n")));
  // Edge count is optional and its value ignored.
  expectSquare(io::loadOff(writeScratchFile(
      "noedges.off", "OFF\n4 2\n0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n3 0 1 2\n3 0 2 3\n")));
}

TEST(LoadOff, CommentsBlankLinesCrlfAndNoFinalNewline)
{
  const std::string text = "# made by hand\r\nOFF # header\r\n\r\n# counts next\r\n4 2 99\r\n"
                           "0 0 0\r\n1 0 0 # a comment\r\n\r\n1 1 0\r\n  0 1 0.5\r\n"
                           "#\r\n3 0 1 2\r\n3 0 2 3";
  expectSquare(io::loadOff(writeScratchFile("crlf.off", text)));
}

TEST(LoadOff, ExtraVertexAndFaceValuesAreIgnored)
{
  // COFF-style vertex colours and per-face RGB(A) colours, as PSB and Princeton files carry.
  expectSquare(io::loadOff(writeScratchFile(
      "colours.off", "COFF\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 1 2 3 4\n1 1 0 0 0 0 0\n"
                     "0 1 0.5 9 9 9 9\n3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1\n")));
}

TEST(LoadOff, PolygonsAreFanTriangulatedInOrder)
{
  // A pentagon then a quad: (v0, v_{k-1}, v_k) for k = 2..n-1.
  const TriangleMesh m = io::loadOff(
      writeScratchFile("poly.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 5 5\n"
                                   "5 0 1 2 3 4\n4 5 4 3 2\n"));
  ASSERT_EQ(m.numFaces(), 5u);
  EXPECT_EQ(m.faces[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(m.faces[1], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(m.faces[2], Eigen::Vector3i(0, 3, 4));
  EXPECT_EQ(m.faces[3], Eigen::Vector3i(5, 4, 3));
  EXPECT_EQ(m.faces[4], Eigen::Vector3i(5, 3, 2));
}

TEST(LoadOff, EmptyMeshIsValid)
{
  const TriangleMesh m = io::loadOff(writeScratchFile("zero.off", "OFF\n0 0 0\n"));
  EXPECT_TRUE(m.empty());
  EXPECT_EQ(m.numVertices(), 0u);
}

TEST(LoadOff, Teddy)
{
  const TriangleMesh m = io::loadOff(SEGMAT_DATA_DIR "/teddy/teddy.off");
  ASSERT_EQ(m.numVertices(), 9548u);
  ASSERT_EQ(m.numFaces(), 19092u);
  // First and last lines of each block, read off the file.
  EXPECT_EQ(m.vertices.front(), Eigen::Vector3d(0.019834, -0.014369, 0.293315));
  EXPECT_EQ(m.vertices.back(), Eigen::Vector3d(-0.056131, -0.225574, -0.259953));
  EXPECT_EQ(m.faces.front(), Eigen::Vector3i(3, 2, 0));
  EXPECT_EQ(m.faces.back(), Eigen::Vector3i(9540, 9547, 9541));
  // Measured independently: bounding-box diagonal 2.255.
  EXPECT_NEAR(m.boundingBoxDiagonal(), 2.255, 5e-4);
}

// ---- Malformed-file catalogue: each case names the path and the line. ----

TEST(LoadOffErrors, MissingFile)
{
  const std::string path = segmat::test::scratchDir() + "does_not_exist.off";
  EXPECT_TRUE(throwsFileError([&] { io::loadOff(path); }, path, 0, "cannot open"));
}

TEST(LoadOffErrors, EmptyFile)
{
  EXPECT_TRUE(offFails("empty.off", "", 0, "empty file"));
  EXPECT_TRUE(offFails("blank.off", "\n\n  \n# only a comment\n", 0, "empty file"));
}

TEST(LoadOffErrors, NoHeader)
{
  EXPECT_TRUE(offFails("noheader.off", "4 2 0\n0 0 0\n", 1, "no OFF header"));
  EXPECT_TRUE(offFails("plyheader.off", "\n# c\nply\nformat ascii 1.0\n", 3, "no OFF header"));
  EXPECT_TRUE(offFails("4off.off", "4OFF\n1 0 0\n", 1, "no OFF header"));
}

TEST(LoadOffErrors, CountsMissing)
{
  EXPECT_TRUE(offFails("nocounts.off", "OFF\n", 1, "missing vertex and face counts"));
  EXPECT_TRUE(offFails("onecount.off", "OFF\n\n4\n", 3, "missing face count"));
}

TEST(LoadOffErrors, CountsNotNumbers)
{
  EXPECT_TRUE(offFails("wordcount.off", "OFF\nfour 2 0\n", 2, "'four' is not an integer"));
  EXPECT_TRUE(offFails("floatcount.off", "OFF\n4.0 2 0\n", 2, "'4.0' is not an integer"));
  EXPECT_TRUE(offFails("extracount.off", "OFF\n4 2 0 7\n", 2, "unexpected '7'"));
}

TEST(LoadOffErrors, CountsNegative)
{
  EXPECT_TRUE(offFails("negcount.off", "OFF\n-4 2 0\n", 2, "negative count"));
  EXPECT_TRUE(offFails("negfaces.off", "OFF 4 -2 0\n", 1, "negative count"));
}

TEST(LoadOffErrors, CountsAbsurd)
{
  EXPECT_TRUE(offFails("hugecount.off", "OFF\n1000000000 2 0\n0 0 0\n", 2, "cannot fit"));
  EXPECT_TRUE(offFails("overflow.off", "OFF\n99999999999999999999 2 0\n", 2, "out of range"));
}

TEST(LoadOffErrors, TruncatedVertexList)
{
  // 3 of 4 vertices; the file ends at line 5. (Long numbers, as real files have: a file too short
  // for even the shortest lines fails earlier, on its counts, see CountsAbsurd.)
  EXPECT_TRUE(offFails("truncv.off",
                       "OFF\n4 1 0\n0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n"
                       "1.000000 1.000000 0.000000\n",
                       5, "file ends after 3 of 4 vertices"));
}

TEST(LoadOffErrors, TruncatedFaceList)
{
  EXPECT_TRUE(offFails("truncf.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n", 7,
                       "file ends after 1 of 2 faces"));
}

TEST(LoadOffErrors, VertexCountTooSmallLeavesData)
{
  // The header says 3 vertices but 4 follow: the 4th is read as a face and fails there.
  EXPECT_TRUE(offFails("wrongnv.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n", 6,
                       "face 0 has 1 vertices"));
  EXPECT_TRUE(offFails("trailing.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", 7,
                       "data after the 1 faces"));
}

TEST(LoadOffErrors, NonNumericCoordinate)
{
  EXPECT_TRUE(offFails("abc.off", "OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", 4,
                       "'abc' is not a number"));
  EXPECT_TRUE(offFails("comma.off", "OFF\n3 1 0\n0 0 0\n1,5 0 0\n0 1 0\n3 0 1 2\n", 4,
                       "'1,5' is not a number"));
  EXPECT_TRUE(offFails("twocoords.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4,
                       "vertex 1: missing coordinate"));
}

TEST(LoadOffErrors, NonFiniteCoordinate)
{
  EXPECT_TRUE(offFails("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n", 5, "not finite"));
  EXPECT_TRUE(
      offFails("inf.off", "OFF\n3 1 0\n0 0 -inf\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "not finite"));
  EXPECT_TRUE(
      offFails("big.off", "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", 4, "out of range"));
}

TEST(LoadOffErrors, FaceWithFewerThanThreeVertices)
{
  EXPECT_TRUE(offFails("edgeface.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 6,
                       "face 0 has 2 vertices"));
  EXPECT_TRUE(offFails("shortface.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", 6,
                       "announces 4 vertices but lists only 3"));
}

TEST(LoadOffErrors, IndexOutOfRange)
{
  EXPECT_TRUE(offFails("badindex.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n", 7,
                       "face 1 refers to vertex 3 but there are 3 vertices"));
  EXPECT_TRUE(offFails("negindex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6,
                       "refers to vertex -1"));
  EXPECT_TRUE(offFails("floatindex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1.0 2\n", 6,
                       "'1.0' is not an integer"));
}

TEST(LoadOffErrors, BinaryJunk)
{
  std::string junk = "OFF\n3 1 0\n0 0 0\n";
  junk += std::string("\x00\x01\xff\xfe", 4);
  EXPECT_TRUE(offFails("junk.off", junk, 4, "binary data"));
  // A binary PLY renamed .off fails at its first control byte, not at a parse step further on.
  std::string ply = "ply\nformat binary_little_endian 1.0\nend_header\n";
  ply += std::string("\x00\x00\x80\x3f", 4);
  EXPECT_TRUE(offFails("binary.off", ply, 4, "binary data (byte 0x00)"));
}

// ---- Writing ----

TEST(SaveOff, RoundTripIsExact)
{
  TriangleMesh m(
      {{0.1, 1.0 / 3.0, -0.0},
       {1e-300, -2.5e17, std::nextafter(1.0, 2.0)},
       {std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), 7}},
      {{0, 1, 2}, {2, 1, 0}});
  const std::string path = segmat::test::scratchDir() + "roundtrip.off";
  io::saveOff(path, m);
  const TriangleMesh back = io::loadOff(path);
  ASSERT_EQ(back.numVertices(), 3u);
  for (int v = 0; v < 3; ++v)
    EXPECT_EQ(back.vertices[v], m.vertices[v]) << v;
  EXPECT_EQ(back.faces, m.faces);
}

TEST(SaveOff, TeddyRoundTripIsExact)
{
  const TriangleMesh m = io::loadOff(SEGMAT_DATA_DIR "/teddy/teddy.off");
  const std::string path = segmat::test::scratchDir() + "teddy.off";
  io::saveOff(path, m);
  const TriangleMesh back = io::loadOff(path);
  EXPECT_EQ(back.vertices, m.vertices);
  EXPECT_EQ(back.faces, m.faces);
}

TEST(SaveOff, RefusesUnreadableMeshAndLeavesOldFile)
{
  const std::string path = writeScratchFile("keep.off", kSquare);
  TriangleMesh bad({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}});
  EXPECT_TRUE(throwsFileError([&] { io::saveOff(path, bad); }, path, 0, "refers to vertex 3"));
  bad.faces = {{0, 1, 2}};
  bad.vertices[1].x() = std::nan("");
  EXPECT_TRUE(throwsFileError([&] { io::saveOff(path, bad); }, path, 0, "not finite"));
  EXPECT_EQ(segmat::test::readWholeFile(path), kSquare);
}

TEST(LoadOffErrors, DamagedCopiesFailCleanly)
{
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly(
      "damaged.off", kSquare, [](const std::string& path) { io::loadOff(path); }));
}
