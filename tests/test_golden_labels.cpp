// Golden labels: MeshSegmentation with its defaults (medial meshes computed from the mesh, one
// thread) on teddy and on every psb-dev shape must give the part count and label checksum
// recorded in tests/golden/mesh_labels.txt. Refactoring must not change labels; a deliberate
// change of the algorithm regenerates the table with scripts/regenerate_golden.sh.
#include <segmat/io/mesh.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <util/label_hash.h>

#include <gtest/gtest.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

using namespace segmat;

namespace {

const std::string kTable = SEGMAT_GOLDEN_DIR "/mesh_labels.txt";

/** One row of the table: a mesh (relative to the bundled or the shared data folder). */
struct GoldenRow
{
  std::string name;  // gtest-safe name
  std::string mesh;  // "data/…" (bundled) or "shared/…" (../shared/data)
  int parts = 0;
  std::uint64_t hash = 0;
};

std::string
meshPath(const std::string& mesh)
{
  if (mesh.rfind("data/", 0) == 0)
    return std::string(SEGMAT_DATA_DIR) + mesh.substr(4);
  return std::string(SEGMAT_SHARED_DATA_DIR) + mesh.substr(6);
}

std::vector<GoldenRow>
readTable()
{
  std::vector<GoldenRow> rows;
  std::ifstream in(kTable);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream fields(line);
    GoldenRow row;
    if (fields >> row.name >> row.mesh >> row.parts >> row.hash)
      rows.push_back(row);
  }
  return rows;
}

/** Part count and checksum of the default segmentation, or parts = −1 when segment() fails. */
GoldenRow
segmentDefault(const GoldenRow& row)
{
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  MeshSegmentation seg;
  seg.setNumberOfThreads(1);
  seg.setInputMesh(std::make_shared<TriangleMesh>(io::loadMesh(meshPath(row.mesh))));
  std::vector<int> labels;
  GoldenRow got = row;
  got.parts = seg.segment(labels) ? *std::max_element(labels.begin(), labels.end()) + 1 : -1;
  got.hash = test::labelHash(labels);
  return got;
}

bool
meshPresent(const GoldenRow& row)
{
  return std::ifstream(meshPath(row.mesh)).good();
}

/** gtest prints a row by its mesh (test names and failures). */
void
PrintTo(const GoldenRow& row, std::ostream* os)
{
  *os << row.mesh;
}

class GoldenLabels : public ::testing::TestWithParam<GoldenRow>
{};

} // namespace

TEST(GoldenTable, IsReadable)
{
  const std::vector<GoldenRow> rows = readTable();
  ASSERT_FALSE(rows.empty()) << kTable << ": no row";
  EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const GoldenRow& r) {
    return r.mesh == "data/teddy/teddy.off";
  })) << kTable << ": teddy is missing";
}

TEST_P(GoldenLabels, DefaultSegmentationIsUnchanged)
{
  const GoldenRow& row = GetParam();
  if (!meshPresent(row))
    GTEST_SKIP() << meshPath(row.mesh) << " not present (../shared beside the clone)";
  const GoldenRow got = segmentDefault(row);
  EXPECT_EQ(got.parts, row.parts) << row.mesh;
  EXPECT_EQ(got.hash, row.hash) << row.mesh << ": labels changed";
}

INSTANTIATE_TEST_SUITE_P(Shapes, GoldenLabels, ::testing::ValuesIn(readTable()),
                         [](const ::testing::TestParamInfo<GoldenRow>& info) {
                           return info.param.name;
                         });

// Writes the table anew from the current code (only when SEGMAT_GOLDEN_WRITE is set; see
// scripts/regenerate_golden.sh). Rows: teddy, then the psb-dev shapes present.
TEST(GoldenTable, Regenerate)
{
  const char* out = std::getenv("SEGMAT_GOLDEN_WRITE");
  if (out == nullptr || *out == '\0')
    GTEST_SKIP() << "set SEGMAT_GOLDEN_WRITE=<file> to regenerate the table";
  std::vector<GoldenRow> rows;
  rows.push_back({"teddy", "data/teddy/teddy.off", 0, 0});
  for (const GoldenRow& old : readTable())
    if (old.mesh != "data/teddy/teddy.off")
      rows.push_back(old);
  std::ostringstream text;
  text << "# Golden labels of MeshSegmentation (defaults, medial meshes computed, one thread).\n"
          "# name mesh parts fnv1a(labels)   -- mesh: data/... bundled, shared/... in ../shared/data\n"
          "# Regenerate after a deliberate change of the labels: scripts/regenerate_golden.sh\n";
  for (const GoldenRow& row : rows) {
    ASSERT_TRUE(meshPresent(row)) << meshPath(row.mesh) << " missing: cannot regenerate";
    const GoldenRow got = segmentDefault(row);
    text << got.name << ' ' << got.mesh << ' ' << got.parts << ' ' << got.hash << '\n';
  }
  std::ofstream file(out);
  file << text.str();
  ASSERT_TRUE(file.good()) << out << ": cannot write";
}
