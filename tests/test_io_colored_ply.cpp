// Label colours and coloured PLY output, read back with PCL's reader and by parsing the text.
#include <segmat/common/error.h>
#include <segmat/io/cloud.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/mesh.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>
#include <pcl/common/colors.h>
#include <pcl/io/ply_io.h>

#include <set>
#include <sstream>

using namespace segmat;
using segmat::test::readWholeFile;
using segmat::test::scratchDir;
using segmat::test::throwsFileError;

namespace {
// The colour columns (last three values) of every line of element \a element in an ASCII PLY
// written by segmat, parsed independently of the writer.
std::vector<io::Rgb>
colorsOf(const std::string& ply_text, const std::string& element)
{
  std::istringstream in(ply_text);
  std::string line;
  std::vector<std::pair<std::string, std::size_t>> elements;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string keyword, name;
    std::size_t count = 0;
    if (words >> keyword && keyword == "element" && words >> name >> count)
      elements.emplace_back(name, count);
  }
  std::vector<io::Rgb> colors;
  for (const auto& [name, count] : elements)
    for (std::size_t i = 0; i < count && std::getline(in, line); ++i) {
      if (name != element)
        continue;
      std::istringstream words(line);
      std::vector<std::string> values;
      for (std::string w; words >> w;)
        values.push_back(w);
      const std::size_t n = values.size();
      colors.push_back({static_cast<std::uint8_t>(std::stoi(values.at(n - 3))),
                        static_cast<std::uint8_t>(std::stoi(values.at(n - 2))),
                        static_cast<std::uint8_t>(std::stoi(values.at(n - 1)))});
    }
  return colors;
}
} // namespace

TEST(LabelColor, GlasbeyTableCycledAndGreyForUnlabelled)
{
  // 256 distinct colours, then the table repeats.
  std::set<io::Rgb> distinct;
  for (int l = 0; l < 256; ++l)
    distinct.insert(io::labelColor(l));
  EXPECT_EQ(distinct.size(), 256u);
  EXPECT_EQ(io::labelColor(256), io::labelColor(0));
  EXPECT_EQ(io::labelColor(300), io::labelColor(44));
  EXPECT_EQ(io::labelColor(-1), (io::Rgb{128, 128, 128}));
  const pcl::RGB first = pcl::GlasbeyLUT::at(0);
  EXPECT_EQ(io::labelColor(0), (io::Rgb{first.r, first.g, first.b}));
}

TEST(SaveColoredMeshPly, TeddyFaceColoursMatchLabels)
{
  const TriangleMesh mesh = io::loadOff(SEGMAT_DATA_DIR "/teddy/teddy.off");
  const std::vector<int> labels = io::loadSeg(SEGMAT_DATA_DIR "/teddy/seg/180_0.seg", 19092);
  const std::string path = scratchDir() + "teddy_colored.ply";
  io::saveColoredMeshPly(path, mesh, labels);
  const std::string text = readWholeFile(path);

  const std::vector<io::Rgb> colors = colorsOf(text, "face");
  ASSERT_EQ(colors.size(), 19092u);
  for (std::size_t f : {std::size_t(0), std::size_t(1), std::size_t(9000), std::size_t(19091)})
    EXPECT_EQ(colors[f], io::labelColor(labels[f])) << f;
  for (std::size_t f = 0; f < colors.size(); ++f)
    ASSERT_EQ(colors[f], io::labelColor(labels[f])) << f;

  // PCL reads it as a mesh, with the same geometry (double coordinates).
  const TriangleMesh back = io::loadMesh(path);
  EXPECT_EQ(back.vertices, mesh.vertices);
  EXPECT_EQ(back.faces, mesh.faces);

  // Same input, same bytes.
  const std::string again = scratchDir() + "teddy_colored_again.ply";
  io::saveColoredMeshPly(again, mesh, labels);
  EXPECT_EQ(readWholeFile(again), text);
}

TEST(SaveColoredMeshPly, LabelCountMismatchWritesNothing)
{
  const TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const std::string path = scratchDir() + "mismatch.ply";
  EXPECT_TRUE(throwsFileError(
      [&] {
        io::saveColoredMeshPly(path, mesh, {0, 1});
      },
      path, 0, "2 labels for 1 faces"));
  EXPECT_FALSE(segmat::test::fileExists(path));
}

TEST(SaveColoredCloudPly, VertexColoursReadByPcl)
{
  const std::vector<Eigen::Vector3d> points{{0, 0, 0}, {1, 0.5, 0}, {0, 1, 2}, {3, 3, 3}};
  const std::vector<int> labels{4, 0, -1, 260};
  const std::string path = scratchDir() + "colored_cloud.ply";
  io::saveColoredCloudPly(path, points, labels);

  pcl::PointCloud<pcl::PointXYZRGB> rgb;
  ASSERT_EQ(pcl::io::loadPLYFile(path, rgb), 0);
  ASSERT_EQ(rgb.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ((io::Rgb{rgb[i].r, rgb[i].g, rgb[i].b}), io::labelColor(labels[i])) << i;
  EXPECT_EQ(colorsOf(readWholeFile(path), "vertex")[3], io::labelColor(4)); // 260 mod 256
  // The positions come back exactly through loadCloud.
  const io::LoadedCloud back = io::loadCloud(path);
  ASSERT_EQ(back.cloud->size(), 4u);
  EXPECT_EQ((*back.cloud)[1].getVector3fMap(), Eigen::Vector3f(1, 0.5f, 0));
}

TEST(SaveColoredCloudPly, LabelledPclCloudGivesSameBytes)
{
  pcl::PointCloud<pcl::PointXYZL> cloud;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> labels;
  for (int i = 0; i < 6; ++i) {
    pcl::PointXYZL p;
    p.x = 0.25f * i, p.y = 1.f, p.z = -0.5f * i, p.label = static_cast<std::uint32_t>(i / 2);
    cloud.push_back(p);
    points.push_back(p.getVector3fMap().cast<double>());
    labels.push_back(i / 2);
  }
  const std::string a = scratchDir() + "xyzl.ply", b = scratchDir() + "vectors.ply";
  io::saveColoredCloudPly(a, cloud);
  io::saveColoredCloudPly(b, points, labels);
  EXPECT_EQ(readWholeFile(a), readWholeFile(b));
  const std::string path = scratchDir() + "cloud_mismatch.ply";
  EXPECT_TRUE(throwsFileError([&] { io::saveColoredCloudPly(path, points, {1}); }, path, 0,
                              "1 labels for 6 points"));
}
