/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "program_files.h"

#include "option_parser.h"

#include <segmat/geometry/mesh_edge_counts.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace segmat {
namespace cli {

void
declareOutputs(io::OutputSet& outputs, const std::string& prefix,
               const std::vector<std::string>& suffixes)
{
  if (prefix.empty())
    throw UsageError("the output prefix (-o) is empty");
  if (prefix.back() == '/' || std::filesystem::is_directory(prefix))
    throw UsageError(prefix, 0,
                     "-o takes a file prefix, not a directory (for example " +
                         (prefix.back() == '/' ? prefix : prefix + "/") + "name)");
  std::error_code ec;
  const auto status = std::filesystem::status(prefix, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw UsageError(prefix, 0, "-o takes a file prefix; this names a device or another special "
                                "file");
  io::removeTemporariesOnSignal();
  asInput([&] {
    for (const std::string& suffix : suffixes)
      outputs.add(prefix + suffix);
  });
}

void
checkInputFile(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UsageError(path, 0, "is a directory, not a file");
}

void
checkMeshSize(const std::string& path, const TriangleMesh& mesh)
{
  const double diagonal = mesh.boundingBoxDiagonal();
  if (std::isinf(diagonal))
    throw UsageError(path, 0,
                     "the coordinates are so large that the mesh's size overflows (its bounding-"
                     "box diagonal exceeds the largest double); rescale the mesh");
  if (!(diagonal > 0.0))
    throw UsageError(path, 0, "the mesh has no extent (all vertices at one point)");
}

void
warnIfNotClosed(const std::string& program, const std::string& path, const TriangleMesh& mesh)
{
  const MeshEdgeCounts counts = countMeshEdges(mesh);
  if (counts.closedManifold())
    return;
  std::fprintf(stderr,
               "%s: warning: %s is not a closed manifold surface: %zu boundary edge(s), %zu "
               "non-manifold edge(s) of %zu; the medial axis assumes a closed surface, parts "
               "may be wrong near them\n",
               program.c_str(), path.c_str(), counts.boundary, counts.non_manifold, counts.edges);
}

} // namespace cli
} // namespace segmat
