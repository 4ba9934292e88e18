// loadMesh/saveMesh by extension (OFF, PLY, OBJ, STL), PolygonMesh conversion, malformed PCL
// formats.
#include <segmat/common/error.h>
#include <segmat/io/mesh.h>
#include <segmat/io/off.h>
#include <segmat/io/polygon_mesh.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

using namespace segmat;
using segmat::test::scratchDir;
using segmat::test::throwsFileError;
using segmat::test::writeScratchFile;

namespace {
const char* const kTeddy = SEGMAT_DATA_DIR "/teddy/teddy.off";

// ASCII PLY of a unit square as one quad plus a triangle on top, double coordinates.
const char* const kQuadPly = "ply\nformat ascii 1.0\ncomment hand-written\n"
                             "element vertex 5\nproperty double x\nproperty double y\n"
                             "property double z\nelement face 2\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.1 0.2 0.30000000000000004\n"
                             "4 0 1 2 3\n3 0 1 4\n";

std::string
binaryPlyHeader(int vertices, int faces)
{
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_index\nend_header\n";
}

template <typename T>
void
appendBinary(std::string& out, T value)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// A binary little-endian PLY triangle (x86 and ARM are little-endian).
std::string
binaryTrianglePly()
{
  std::string ply = binaryPlyHeader(3, 1);
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.5f})
    appendBinary(ply, v);
  appendBinary<std::uint8_t>(ply, 3);
  for (std::int32_t i : {0, 1, 2})
    appendBinary(ply, i);
  return ply;
}

// Binary STL of the unit square as two triangles (80-byte header, count, 50 bytes a triangle).
std::string
binarySquareStl()
{
  std::string stl(80, ' ');
  appendBinary<std::uint32_t>(stl, 2);
  const float triangles[2][9] = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : triangles) {
    for (float n : {0.f, 0.f, 1.f})
      appendBinary(stl, n);
    for (float v : t)
      appendBinary(stl, v);
    appendBinary<std::uint16_t>(stl, 0);
  }
  return stl;
}

::testing::AssertionResult
meshFails(const std::string& name, const std::string& bytes, long line, const std::string& needle)
{
  return segmat::test::loadingFails([](const std::string& p) { io::loadMesh(p); }, name, bytes,
                                    line, needle);
}
} // namespace

TEST(LoadMesh, OffGoesToLoadOff)
{
  const TriangleMesh a = io::loadMesh(kTeddy);
  const TriangleMesh b = io::loadOff(kTeddy);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.faces, b.faces);
  // Extension in any case.
  const std::string upper =
      writeScratchFile("SQUARE.OFF", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(io::loadMesh(upper).numFaces(), 1u);
}

TEST(LoadMesh, AsciiPlyWithQuadAndDoubles)
{
  const TriangleMesh m = io::loadMesh(writeScratchFile("quad.ply", kQuadPly));
  ASSERT_EQ(m.numVertices(), 5u);
  ASSERT_EQ(m.numFaces(), 3u);
  EXPECT_EQ(m.faces[0], Eigen::Vector3i(0, 1, 2)); // fan of the quad
  EXPECT_EQ(m.faces[1], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(m.faces[2], Eigen::Vector3i(0, 1, 4));
  // Stored as double, read as double: no rounding to float.
  EXPECT_EQ(m.vertices[4], Eigen::Vector3d(0.1, 0.2, 0.30000000000000004));
}

TEST(LoadMesh, BinaryPlyWithFloats)
{
  const TriangleMesh m = io::loadMesh(writeScratchFile("tri.ply", binaryTrianglePly()));
  ASSERT_EQ(m.numVertices(), 3u);
  ASSERT_EQ(m.numFaces(), 1u);
  EXPECT_EQ(m.vertices[2], Eigen::Vector3d(0, 1, 0.5));
  EXPECT_EQ(m.faces[0], Eigen::Vector3i(0, 1, 2));
}

TEST(LoadMesh, ObjWithSlashesQuadAndRelativeIndices)
{
  const TriangleMesh m = io::loadMesh(writeScratchFile(
      "quad.obj",
      "# square\r\nmtllib a.mtl\r\no thing\r\nv 0 0 0\r\nv 1 0 0 1\r\n"
      "v 1 1 0 0.5 0.5 0.5\r\nv 0 1 0.1\r\nvt 0 0\r\nvn 0 0 1\r\ng part\r\n"
      "usemtl red\r\ns off\r\nf 1//1 2//1 3//1 4//1 # quad\r\nf -4/1/1 -3/2/1 -1/3/1\r\n"
      "l 1 2\r\n"));
  ASSERT_EQ(m.numVertices(), 4u);
  ASSERT_EQ(m.numFaces(), 3u);
  EXPECT_EQ(m.faces[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(m.faces[1], Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(m.faces[2], Eigen::Vector3i(0, 1, 3));
  EXPECT_EQ(m.vertices[3], Eigen::Vector3d(0, 1, 0.1)); // read as double
}

TEST(LoadMesh, AsciiStl)
{
  // Two triangles sharing an edge: STL repeats corners, VTK merges them.
  const std::string stl = "solid s\n"
                          "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 1 1 0\nendloop\nendfacet\n"
                          "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
  const TriangleMesh m = io::loadMesh(writeScratchFile("square.stl", stl));
  ASSERT_EQ(m.numFaces(), 2u);
  EXPECT_EQ(m.numVertices(), 4u);
  EXPECT_EQ(m.faceArea(0) + m.faceArea(1), 1.0);
  EXPECT_EQ(m.faces[0][0], m.faces[1][0]); // the shared corner (0, 0, 0) is one vertex
}

TEST(SaveMesh, RoundTripsAreExact)
{
  const TriangleMesh m = io::loadOff(kTeddy);
  const std::string ply = scratchDir() + "teddy.ply";
  io::saveMesh(ply, m);
  const TriangleMesh from_ply = io::loadMesh(ply);
  EXPECT_EQ(from_ply.vertices, m.vertices);
  EXPECT_EQ(from_ply.faces, m.faces);

  const std::string obj = scratchDir() + "teddy.obj";
  io::saveMesh(obj, m);
  const TriangleMesh from_obj = io::loadMesh(obj);
  EXPECT_EQ(from_obj.vertices, m.vertices);
  EXPECT_EQ(from_obj.faces, m.faces);

  const std::string off = scratchDir() + "teddy_copy.off";
  io::saveMesh(off, m);
  EXPECT_EQ(io::loadMesh(off).vertices, m.vertices);
}

TEST(SaveMesh, UnknownExtensionAndBadMesh)
{
  const TriangleMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const std::string stl = scratchDir() + "out.stl";
  EXPECT_TRUE(throwsFileError([&] { io::saveMesh(stl, m); }, stl, 0, ".off, .ply, .obj"));
  EXPECT_FALSE(segmat::test::fileExists(stl));
  TriangleMesh bad = m;
  bad.faces[0][2] = 7;
  const std::string ply = scratchDir() + "bad.ply";
  EXPECT_TRUE(throwsFileError([&] { io::saveMesh(ply, bad); }, ply, 0, "refers to vertex 7"));
  EXPECT_FALSE(segmat::test::fileExists(ply));
}

TEST(PolygonMesh, ConversionBothWays)
{
  const TriangleMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 1}},
                       {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}});
  const pcl::PolygonMesh pm = io::toPolygonMesh(m);
  EXPECT_EQ(pm.cloud.width * pm.cloud.height, 4u);
  ASSERT_EQ(pm.polygons.size(), 3u);
  EXPECT_EQ(pm.polygons[2].vertices, (pcl::Indices{1, 2, 3}));
  const TriangleMesh back = io::fromPolygonMesh(pm);
  EXPECT_EQ(back.vertices, m.vertices); // all exactly representable in float
  EXPECT_EQ(back.faces, m.faces);
}

TEST(PolygonMesh, FromPolygonMeshRejectsBadInput)
{
  pcl::PolygonMesh pm =
      io::toPolygonMesh(TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  pm.polygons[0].vertices = {0, 1, 3};
  EXPECT_THROW(io::fromPolygonMesh(pm), Error);
  pm.polygons[0].vertices = {0, 1};
  EXPECT_THROW(io::fromPolygonMesh(pm), Error);
  pm.polygons[0].vertices = {0, -1, 2};
  EXPECT_THROW(io::fromPolygonMesh(pm), Error);
  pm.cloud.fields.resize(2); // drop z
  pm.polygons[0].vertices = {0, 1, 2};
  EXPECT_THROW(io::fromPolygonMesh(pm), Error);
}

// ---- Malformed files: every case is a segmat::Error naming the file (line 0: PCL's readers give
// no line), never a crash. ----

TEST(LoadMeshErrors, UnknownExtension)
{
  const std::string path = writeScratchFile("mesh.vtk", "# vtk DataFile\n");
  EXPECT_TRUE(throwsFileError([&] { io::loadMesh(path); }, path, 0,
                              "unknown mesh format '.vtk' (supported: .off, .ply, .obj, .stl)"));
  const std::string none = writeScratchFile("noextension", "OFF\n0 0 0\n");
  EXPECT_TRUE(throwsFileError([&] { io::loadMesh(none); }, none, 0, "unknown mesh format"));
}

TEST(LoadMeshErrors, MissingFiles)
{
  for (const char* ext : {"off", "ply", "obj", "stl"}) {
    const std::string path = scratchDir() + "missing." + ext;
    EXPECT_TRUE(throwsFileError([&] { io::loadMesh(path); }, path, 0, "")) << ext;
  }
}

TEST(LoadMeshErrors, PlyEmptyAndJunk)
{
  // The header is checked before PCL's reader runs, so these name the header line.
  EXPECT_TRUE(meshFails("empty.ply", "", 0, "empty file"));
  EXPECT_TRUE(meshFails("junk.ply",
                        std::string("\x7f"
                                    "ELF\x02\x01\x01\x00\x00\x00",
                                    10),
                        1, "binary data in the PLY header"));
  EXPECT_TRUE(meshFails("text.ply", "hello world\nthis is not a ply\n", 1, "not a PLY file"));
  EXPECT_TRUE(meshFails("noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
                        4, "no 'end_header'"));
  EXPECT_TRUE(
      meshFails("format.ply", "ply\nformat text 1.0\nend_header\n", 2, "unknown PLY format"));
  EXPECT_TRUE(meshFails("type.ply",
                        "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n"
                        "end_header\n1\n",
                        4, "unknown PLY property type"));
  // A damaged header byte glued a line break away; PCL's reader would abort on the result.
  std::string glued = binaryTrianglePly();
  glued[glued.find("float z") + 7] = '\xcd';
  EXPECT_TRUE(meshFails("glued.ply", glued, 6, "binary data in the PLY header"));
  EXPECT_TRUE(meshFails("vertexlist.ply",
                        "ply\nformat ascii 1.0\nelement vertex 1\n"
                        "property list uchar int idx\nend_header\n1 0\n",
                        4, "list property on the 'vertex' element"));
  EXPECT_TRUE(meshFails("count.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", 3,
                        "is not a non-negative integer"));
  // Bigger counts than the data can hold: refused before PCL allocates for them.
  std::string ply = binaryTrianglePly();
  ply.replace(ply.find("element vertex 3"), 16, "element vertex 400000000");
  EXPECT_TRUE(meshFails("absurd.ply", ply, 3, "announces 400000000 items"));
  ply = binaryTrianglePly();
  EXPECT_TRUE(meshFails("trunc_binary.ply", ply.substr(0, ply.size() - 20), 3,
                        "truncated file or wrong count"));
  // Cut inside the last face: the sizes still fit, PCL's reader notices.
  EXPECT_TRUE(
      meshFails("trunc_faces.ply", ply.substr(0, ply.size() - 6), 0, "not a readable PLY file"));
}

TEST(LoadMeshErrors, PlyTruncatedText)
{
  std::string ascii = kQuadPly;
  ascii.resize(ascii.find("3 0 1 4")); // one face missing: the sizes fit, PCL's reader notices
  EXPECT_TRUE(meshFails("trunc_ascii.ply", ascii, 0, "not a readable PLY file"));
}

TEST(LoadMeshErrors, PlyBadValues)
{
  std::string ply = kQuadPly;
  ply.replace(ply.find("1 1 0"), 5, "1 x 0");
  EXPECT_TRUE(meshFails("word.ply", ply, 0, "vertex 2 is not finite")); // PCL reads a word as NaN
  ply = kQuadPly;
  ply.replace(ply.find("3 0 1 4"), 7, "3 0 1 9");
  EXPECT_TRUE(meshFails("index.ply", ply, 0, "refers to vertex 9"));
  ply = kQuadPly;
  ply.replace(ply.find("3 0 1 4"), 7, "2 0 1");
  EXPECT_TRUE(meshFails("twocorners.ply", ply, 0, "face 1 has 2 corners"));
  ply = kQuadPly;
  ply.replace(ply.find("1 0 0\n1 1"), 5, "1 nan 0");
  EXPECT_TRUE(meshFails("nan.ply", ply, 0, "vertex 1 is not finite"));
}

TEST(LoadMesh, BinaryStl)
{
  const TriangleMesh m = io::loadMesh(writeScratchFile("square_bin.stl", binarySquareStl()));
  ASSERT_EQ(m.numFaces(), 2u);
  EXPECT_EQ(m.numVertices(), 4u);
  EXPECT_EQ(m.faceArea(0) + m.faceArea(1), 1.0);
}

TEST(LoadMeshErrors, StlTruncatedAndJunk)
{
  // VTK would return the one whole triangle of a cut file, or 2 when the header claims 5.
  const std::string stl = binarySquareStl();
  EXPECT_TRUE(meshFails("cut.stl", stl.substr(0, 150), 0,
                        "announces 2 triangles, which take 184 bytes; the file has 150"));
  std::string five = stl;
  five[80] = 5;
  EXPECT_TRUE(meshFails("five.stl", five, 0, "announces 5 triangles"));
  EXPECT_TRUE(meshFails("short.stl", "\x01\x02garbage", 0, "too short for a binary STL"));
  EXPECT_TRUE(meshFails("junk.stl", "this is not an stl file at all\n", 0, "STL"));
  EXPECT_TRUE(meshFails("empty.stl", "", 0, "empty file"));
}

TEST(LoadMeshErrors, StlReadAsBinaryByItsBytes)
{
  // VTK reads a file as binary once 5 % of its first 256 bytes are not text, even after
  // "solid", and then trusts bytes 80-83 as the triangle count.
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                            "vertex 0 1 0\nendloop\nendfacet\n";
  const auto solid = [&](const std::string& name) {
    return "solid " + name + "\n" + facet + facet + facet + "endsolid\n";
  };
  // 12 of the first 256 bytes (4.7 %) are not text: ASCII, read.
  const TriangleMesh named = io::loadMesh(writeScratchFile("utf8.stl", solid(std::string(12, '\xc3'))));
  EXPECT_EQ(named.numFaces(), 3u);
  // 13 (5.1 %), here vertical tabs: binary, and its count does not fit the file.
  EXPECT_TRUE(meshFails("tabs.stl", solid(std::string(13, '\v')), 0,
                        "starts with 'solid' but 13 of its first 256 bytes are not text"));
}

TEST(LoadMeshErrors, DamagedPlyAndObjNeverCrash)
{
  const auto load = [](const std::string& path) { io::loadMesh(path); };
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly("damaged.ply", kQuadPly, load));
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly("damaged_bin.ply", binaryTrianglePly(), load));
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly(
      "damaged.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nf 1 2 3\nf 2 4 3\n", load));
}

TEST(LoadMeshErrors, ObjCatalogue)
{
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_TRUE(meshFails("empty.obj", "", 0, "empty file"));
  EXPECT_TRUE(meshFails("nov.obj", "# nothing\ng group\n", 0, "no 'v' lines"));
  EXPECT_TRUE(
      meshFails("index.obj", v3 + "f 1 2 9\n", 4, "refers to vertex 9 (1-based) but there are 3"));
  EXPECT_TRUE(meshFails("relative.obj", v3 + "f -1 -2 -4\n", 4, "refers to vertex 0 (1-based)"));
  EXPECT_TRUE(meshFails("zero.obj", v3 + "f 0 1 2\n", 4, "vertex index 0"));
  EXPECT_TRUE(meshFails("two.obj", v3 + "f 1 2\n", 4, "face has 2 corners"));
  EXPECT_TRUE(meshFails("word.obj", v3 + "f 1 two 3\n", 4, "'two' is not an integer"));
  EXPECT_TRUE(meshFails("shortv.obj", "v 0 0 0\nv 1 0\n", 2, "'v' line: missing coordinate"));
  EXPECT_TRUE(meshFails("nanv.obj", "v 0 0 0\nv 1 nan 0\n", 2, "not finite"));
  EXPECT_TRUE(
      meshFails("junk.obj", std::string("v 0 0 0\n\x00\x01\x02\x03garbage", 19), 2, "binary data"));
}
