// loadCloud (PCD, PLY, XYZ), normals detection, labelled-cloud and label saving, malformed files.
#include <segmat/common/error.h>
#include <segmat/io/cloud.h>
#include <segmat/io/seg.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <cstring>

using namespace segmat;
using segmat::test::scratchDir;
using segmat::test::throwsFileError;
using segmat::test::writeScratchFile;

namespace {
pcl::PointCloud<pcl::PointNormal>
twoPointsWithNormals()
{
  pcl::PointCloud<pcl::PointNormal> c;
  pcl::PointNormal p;
  p.x = 1.5f, p.y = -2.f, p.z = 0.25f, p.normal_x = 0.f, p.normal_y = 0.f, p.normal_z = 1.f;
  c.push_back(p);
  p.x = 3.f, p.y = 4.f, p.z = 5.f, p.normal_x = 1.f, p.normal_y = 0.f, p.normal_z = 0.f;
  c.push_back(p);
  return c;
}

const char* const kAsciiPcd = "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                              "COUNT 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n"
                              "DATA ascii\n0 0 0\n1 0 0\n0 1 0.5\n";

::testing::AssertionResult
cloudFails(const std::string& name, const std::string& bytes, long line, const std::string& needle)
{
  return segmat::test::loadingFails([](const std::string& p) { io::loadCloud(p); }, name, bytes,
                                    line, needle);
}
} // namespace

TEST(LoadCloud, PcdWithNormals)
{
  const std::string path = scratchDir() + "normals.pcd";
  ASSERT_EQ(pcl::io::savePCDFileBinary(path, twoPointsWithNormals()), 0);
  const io::LoadedCloud c = io::loadCloud(path);
  ASSERT_TRUE(c.cloud);
  ASSERT_EQ(c.cloud->size(), 2u);
  EXPECT_TRUE(c.has_normals);
  EXPECT_TRUE(c.cloud->is_dense);
  EXPECT_EQ((*c.cloud)[0].getVector3fMap(), Eigen::Vector3f(1.5f, -2.f, 0.25f));
  EXPECT_EQ((*c.cloud)[1].getNormalVector3fMap(), Eigen::Vector3f(1.f, 0.f, 0.f));
}

TEST(LoadCloud, AsciiPcdWithoutNormals)
{
  const io::LoadedCloud c = io::loadCloud(writeScratchFile("plain.pcd", kAsciiPcd));
  ASSERT_EQ(c.cloud->size(), 3u);
  EXPECT_FALSE(c.has_normals);
  EXPECT_EQ((*c.cloud)[2].getVector3fMap(), Eigen::Vector3f(0.f, 1.f, 0.5f));
  EXPECT_EQ((*c.cloud)[2].getNormalVector3fMap(), Eigen::Vector3f::Zero());
}

TEST(LoadCloud, DoubleAndIntegerFieldsAreConverted)
{
  // pcl::fromPCLPointCloud2 would leave such fields unmapped (zeros); loadCloud converts them.
  for (const char* types : {"SIZE 8 8 8\nTYPE F F F", "SIZE 2 2 2\nTYPE I I I"}) {
    std::string pcd = kAsciiPcd;
    pcd.replace(pcd.find("SIZE 4 4 4\nTYPE F F F"), 21, types);
    pcd.replace(pcd.find("0 1 0.5"), 7, "0 1 -7");
    const io::LoadedCloud c = io::loadCloud(writeScratchFile("converted.pcd", pcd));
    ASSERT_EQ(c.cloud->size(), 3u) << types;
    EXPECT_EQ((*c.cloud)[2].getVector3fMap(), Eigen::Vector3f(0.f, 1.f, -7.f)) << types;
  }
}

TEST(LoadCloud, NanPointsAreKeptAndMarkNotDense)
{
  std::string pcd = kAsciiPcd;
  pcd.replace(pcd.find("1 0 0\n"), 6, "nan nan nan\n");
  const io::LoadedCloud c = io::loadCloud(writeScratchFile("nan.pcd", pcd));
  ASSERT_EQ(c.cloud->size(), 3u);
  EXPECT_FALSE(c.cloud->is_dense);
  EXPECT_TRUE(std::isnan((*c.cloud)[1].x));
}

TEST(LoadCloud, PlyWithAndWithoutNormals)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\n"
                             "property double y\nproperty double z\n";
  io::LoadedCloud c = io::loadCloud(writeScratchFile(
      "n.ply", header + "property float nx\nproperty float ny\nproperty float nz\nend_header\n"
                        "0 0 0 0 0 1\n1 2 3 0 1 0\n"));
  ASSERT_EQ(c.cloud->size(), 2u);
  EXPECT_TRUE(c.has_normals);
  EXPECT_EQ((*c.cloud)[1].getVector3fMap(), Eigen::Vector3f(1, 2, 3));
  EXPECT_EQ((*c.cloud)[1].getNormalVector3fMap(), Eigen::Vector3f(0, 1, 0));

  // A mesh PLY: its vertices are the points, the faces are ignored.
  c = io::loadCloud(writeScratchFile(
      "mesh.ply", header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 2 3\n3 0 1 1\n"));
  EXPECT_EQ(c.cloud->size(), 2u);
  EXPECT_FALSE(c.has_normals);
}

TEST(LoadCloud, XyzWithAndWithoutNormals)
{
  io::LoadedCloud c =
      io::loadCloud(writeScratchFile("p.xyz", "# scan\n0 0 0\n1.5 2 3\r\n\n4,5,6\n"));
  ASSERT_EQ(c.cloud->size(), 3u);
  EXPECT_FALSE(c.has_normals);
  EXPECT_EQ((*c.cloud)[2].getVector3fMap(), Eigen::Vector3f(4, 5, 6));
  c = io::loadCloud(writeScratchFile("n.txt", "0 0 0 0 0 1\n1 1 1 1 0 0\n"));
  ASSERT_EQ(c.cloud->size(), 2u);
  EXPECT_TRUE(c.has_normals);
  EXPECT_EQ((*c.cloud)[1].getNormalVector3fMap(), Eigen::Vector3f(1, 0, 0));
}

TEST(LoadCloud, FarFromOriginIsReadRelativeToARoundedOrigin)
{
  // A 1.5-unit patch two million units out (a georeferenced scan): float keeps only steps of
  // 0.125–0.25 there, which would merge the y values 0.001 apart and the z values 0.002 apart.
  const std::string text = "1000000.25 2000000.5 -3000000.75\n"
                           "1000001.75 2000000.5 -3000000.75\n"
                           "1000000.25 2000000.501 -3000000.75\n"
                           "1000000.25 2000000.5 -3000000.748\n";
  const io::LoadedCloud c = io::loadCloud(writeScratchFile("far.xyz", text));
  ASSERT_EQ(c.cloud->size(), 4u);
  // Box centre (1000001, 2000000.5005, -3000000.749); diagonal ~1.5, so whole units.
  EXPECT_EQ(c.origin, Eigen::Vector3d(1000001, 2000001, -3000001));
  const Eigen::Vector3d file[4] = {{1000000.25, 2000000.5, -3000000.75},
                                   {1000001.75, 2000000.5, -3000000.75},
                                   {1000000.25, 2000000.501, -3000000.75},
                                   {1000000.25, 2000000.5, -3000000.748}};
  for (int i = 0; i < 4; ++i)
    EXPECT_LT(((*c.cloud)[i].getVector3fMap().cast<double>() + c.origin - file[i]).norm(), 1e-6)
        << i;
  EXPECT_NEAR((*c.cloud)[2].y - (*c.cloud)[0].y, 0.001, 1e-6);
  EXPECT_NEAR((*c.cloud)[3].z - (*c.cloud)[0].z, 0.002, 1e-6);

  // Near 0 (centre within 100 diagonals) nothing moves: 50 units out, diagonal 1.
  const io::LoadedCloud near = io::loadCloud(writeScratchFile("near.xyz", "50 0 0\n51 0 0\n"));
  EXPECT_TRUE(near.origin.isZero());
  EXPECT_EQ((*near.cloud)[1].getVector3fMap(), Eigen::Vector3f(51, 0, 0));
}

// ---- Malformed files ----

TEST(LoadCloudErrors, MissingUnknownAndEmpty)
{
  for (const char* ext : {"pcd", "ply", "xyz"}) {
    const std::string path = scratchDir() + "missing_cloud." + ext;
    EXPECT_TRUE(throwsFileError([&] { io::loadCloud(path); }, path, 0, "cannot open")) << ext;
  }
  EXPECT_TRUE(cloudFails("cloud.las", "LASF", 0,
                         "unknown point-cloud format '.las' "
                         "(supported: .pcd, .ply, .xyz, .txt)"));
  EXPECT_TRUE(cloudFails("empty.pcd", "", 0, "empty file")); // PCL's reader would crash
  EXPECT_TRUE(cloudFails("empty.xyz", "# nothing\n", 0, "no points"));
  EXPECT_TRUE(cloudFails("empty.ply", "", 0, "empty file"));
}

TEST(LoadCloudErrors, PcdHeaderCatalogue)
{
  // segmat checks the header first: PCL 1.13's reader crashes on some of these.
  EXPECT_TRUE(cloudFails("junk.pcd", std::string("\x89PNG\r\n\x1a\n\x00\x00", 10), 1,
                         "binary data in the PCD header"));
  EXPECT_TRUE(cloudFails("comment.pcd", "# hi\n", 1, "no 'DATA' line"));
  const auto edited = [](const std::string& from, const std::string& to,
                         std::string pcd = kAsciiPcd) {
    pcd.replace(pcd.find(from), from.size(), to);
    return pcd;
  };
  // Checks of the header as a whole are reported at its last line (DATA, line 11).
  EXPECT_TRUE(cloudFails("nofields.pcd", edited("FIELDS x y z\n", ""), 10, "no FIELDS line"));
  EXPECT_TRUE(cloudFails("sizes.pcd", edited("SIZE 4 4 4", "SIZE 4 4"), 11,
                         "FIELDS, SIZE, TYPE and COUNT list different numbers"));
  EXPECT_TRUE(cloudFails("size3.pcd", edited("SIZE 4 4 4", "SIZE 4 3 4"), 4, "SIZE 3 is not"));
  EXPECT_TRUE(cloudFails("typeq.pcd", edited("TYPE F F F", "TYPE F Q F"), 5, "TYPE 'Q'"));
  EXPECT_TRUE(cloudFails("count0.pcd", edited("COUNT 1 1 1", "COUNT 1 0 1"), 6,
                         "COUNT value '0' is not a positive integer"));
  EXPECT_TRUE(cloudFails("points.pcd", edited("POINTS 3", "POINTS 4"), 11,
                         "POINTS 4 is not WIDTH x HEIGHT = 3"));
  EXPECT_TRUE(cloudFails("width.pcd", edited("WIDTH 3", "WIDTH -3"), 7, "WIDTH needs one"));
  EXPECT_TRUE(cloudFails("data.pcd", edited("DATA ascii", "DATA text"), 11, "DATA must be"));
  EXPECT_TRUE(cloudFails("keyword.pcd", edited("VIEWPOINT", "VIEWPINT"), 9, "unknown PCD header"));
  // PCL 1.13 sizes the points at POINTS and then writes past them (heap corruption).
  EXPECT_TRUE(cloudFails("repeat.pcd", edited("COUNT 1 1 1\n", "COUNT 1 1 1\nSIZE 8 8 8\n"), 7,
                         "the PCD header repeats SIZE"));
  EXPECT_TRUE(cloudFails("columns.pcd", edited("COUNT 1 1 1\n", "COUNT 1 1 1\nCOLUMNS x y z\n"),
                         7, "the PCD header repeats FIELDS"));
  EXPECT_TRUE(cloudFails("late.pcd",
                         edited("POINTS 3\n", "POINTS 3\nSIZE 8 8 8\n", edited("SIZE 4 4 4\n", "")),
                         10, "SIZE after POINTS in the PCD header"));
  EXPECT_TRUE(cloudFails(
      "huge.pcd", edited("POINTS 3", "POINTS 300000000", edited("WIDTH 3", "WIDTH 300000000")), 11,
      "300000000 points need at least 1799999999 bytes"));
}

TEST(LoadCloudErrors, PcdTruncatedAndNoXyz)
{
  std::string pcd = kAsciiPcd;
  EXPECT_TRUE(cloudFails("trunc.pcd", pcd.substr(0, pcd.size() - 6), 11, "truncated file"));
  pcd.replace(pcd.find("FIELDS x y z"), 12, "FIELDS a b c");
  EXPECT_TRUE(cloudFails("abc.pcd", pcd, 0, "no 'x' field"));

  const std::string binary = scratchDir() + "binary.pcd";
  ASSERT_EQ(pcl::io::savePCDFileBinary(binary, twoPointsWithNormals()), 0);
  const std::string bytes = segmat::test::readWholeFile(binary);
  EXPECT_TRUE(cloudFails("trunc_binary.pcd", bytes.substr(0, bytes.size() - 10), 11,
                         "2 points need at least 56 bytes of data, the file has 46"));
}

TEST(LoadCloudErrors, PcdDataChecked)
{
  const std::string pcd = kAsciiPcd;
  const std::string header = pcd.substr(0, pcd.find("DATA ascii\n") + 11);
  // PCL's parser would take these lines for header lines (and then write past its buffers).
  EXPECT_TRUE(cloudFails("fields.pcd", header + "\nFIELDS\n0 0 0\n1 0 0\n0 1 0\n", 13,
                         "the data starts with the header keyword 'FIELDS'"));
  EXPECT_TRUE(cloudFails("points.pcd", header + "POINTS 1\n0 0 0\n1 0 0\n0 1 0\n", 12,
                         "header keyword 'POINTS'"));
  // ASCII points hold as many numbers as the fields need.
  EXPECT_TRUE(cloudFails("word.pcd", header + "0 0 0\n1 x 0\n0 1 0\n", 13,
                         "value 'x' is not a number"));
  EXPECT_TRUE(cloudFails("two.pcd", header + "0.5 0.5 0\n1 0 0\n0 1\n", 14,
                         "point 3 has 2 values, the fields need 3"));
  EXPECT_TRUE(cloudFails("short.pcd", header + "0.000000 0 0\n\n1.000000 0 0\n", 14,
                         "the data holds 2 points, the header announces 3"));
  // Empty lines, CRLF and NaN are fine.
  const io::LoadedCloud read =
      io::loadCloud(writeScratchFile("crlf.pcd", header + "0 0 0\r\n\n1 0 nan\r\n0 1 0.5\r\n"));
  EXPECT_EQ(read.cloud->size(), 3u);
}

TEST(LoadCloudErrors, XyzCatalogue)
{
  EXPECT_TRUE(cloudFails("four.xyz", "0 0 0\n1 2 3 4\n", 2, "4 values"));
  EXPECT_TRUE(cloudFails("seven.xyz", "0 0 0 0 0 1 9\n", 1, "more than 6 values"));
  EXPECT_TRUE(cloudFails("mixed.xyz", "0 0 0\n0 0 0 0 0 1\n", 2, "mixes lines"));
  EXPECT_TRUE(cloudFails("word.xyz", "0 0 0\n0 zero 0\n", 2, "'zero' is not a number"));
  EXPECT_TRUE(cloudFails("nan.xyz", "0 0 0\n0 nan 0\n", 2, "not finite"));
  EXPECT_TRUE(cloudFails("junk.xyz", std::string("0 0 0\n\x00\x01", 8), 2, "binary data"));
}

TEST(LoadCloudErrors, PlyHeaderChecked)
{
  EXPECT_TRUE(cloudFails("absurd.ply",
                         "ply\nformat binary_little_endian 1.0\nelement vertex "
                         "900000000\nproperty float x\nproperty float y\n"
                         "property float z\nend_header\n",
                         3, "announces 900000000 items"));
}

TEST(LoadCloudErrors, DamagedPcdFailsCleanly)
{
  const auto load = [](const std::string& path) { io::loadCloud(path); };
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly("damaged.pcd", kAsciiPcd, load));
  const std::string binary = scratchDir() + "to_damage.pcd";
  ASSERT_EQ(pcl::io::savePCDFileBinary(binary, twoPointsWithNormals()), 0);
  EXPECT_TRUE(segmat::test::damagedCopiesFailCleanly("damaged_binary.pcd",
                                                     segmat::test::readWholeFile(binary), load));
}

// ---- Writing ----

TEST(SaveLabeledCloudPcd, RoundTripAndEmpty)
{
  pcl::PointCloud<pcl::PointXYZL> cloud;
  for (int i = 0; i < 5; ++i) {
    pcl::PointXYZL p;
    p.x = 0.5f * i, p.y = -1.f * i, p.z = 2.f, p.label = static_cast<std::uint32_t>(i % 3);
    cloud.push_back(p);
  }
  const std::string path = scratchDir() + "labels.pcd";
  io::saveLabeledCloudPcd(path, cloud);
  pcl::PointCloud<pcl::PointXYZL> back;
  ASSERT_EQ(pcl::io::loadPCDFile(path, back), 0);
  ASSERT_EQ(back.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(back[i].getVector3fMap(), cloud[i].getVector3fMap());
    EXPECT_EQ(back[i].label, cloud[i].label);
  }
  // And loadCloud reads its points.
  EXPECT_EQ(io::loadCloud(path).cloud->size(), 5u);

  const std::string empty = scratchDir() + "empty_labels.pcd";
  io::saveLabeledCloudPcd(empty, pcl::PointCloud<pcl::PointXYZL>());
  EXPECT_TRUE(segmat::test::fileExists(empty));
}

TEST(SaveLabeledCloudPcd, UnwritablePathThrowsAndLeavesNothing)
{
  const std::string path = scratchDir() + "no_such_dir/labels.pcd";
  pcl::PointCloud<pcl::PointXYZL> cloud;
  cloud.push_back(pcl::PointXYZL());
  EXPECT_TRUE(throwsFileError([&] { io::saveLabeledCloudPcd(path, cloud); }, path, 0,
                              "cannot write the file"));
  EXPECT_FALSE(segmat::test::fileExists(path));
}

TEST(SaveLabels, SameFormatAsSeg)
{
  const std::string path = scratchDir() + "cloud_labels.txt";
  io::saveLabels(path, {2, 0, 1});
  EXPECT_EQ(segmat::test::readWholeFile(path), "2\n0\n1\n");
  EXPECT_EQ(io::loadSeg(path, 3), (std::vector<int>{2, 0, 1}));
}
