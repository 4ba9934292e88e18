/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "polygon_fan.h"
#include "text_file.h"

#include <segmat/io/off.h>

#include <array>
#include <cstdint>

namespace segmat {
namespace io {
namespace {
using detail::quoted;
using detail::TextFile;
using detail::Tokens;

// Returns the header line's text after "OFF" (counts may be glued on: "OFF4 2 0"). The OFF family's
// prefixes ST/C/N only add per-vertex values, which are ignored; 4OFF and nOFF change the
// dimension and are refused.
std::string_view
afterHeader(const TextFile& file, std::string_view line)
{
  const std::size_t at = line.find("OFF");
  if (at == std::string_view::npos || at > 4 ||
      line.substr(0, at).find_first_not_of("STCN") != std::string_view::npos)
    file.fail("no OFF header: the file starts with " + quoted(line.substr(0, 16)));
  return line.substr(at + 3);
}
} // namespace

TriangleMesh
loadOff(const std::string& path)
{
  TextFile file(path, "OFF", true);
  std::string_view line;
  if (!file.nextLine(line))
    file.failFile("empty file");
  std::string_view counts_text = afterHeader(file, line);
  Tokens probe(counts_text);
  std::string_view unused;
  if (!probe.next(unused)) {
    if (!file.nextLine(line))
      file.fail("missing vertex and face counts after the OFF header");
    counts_text = line;
  }

  Tokens counts(counts_text);
  const long nv = file.parseLong(file.require(counts, "counts", "vertex count"), "vertex count");
  const long nf = file.parseLong(file.require(counts, "counts", "face count"), "face count");
  std::string_view edge_count;
  if (counts.next(edge_count)) // edge count: read for validity, value ignored
    file.parseLong(edge_count, "edge count");
  if (counts.next(unused))
    file.fail("unexpected " + quoted(unused) + " after the counts 'vertices faces edges'");
  if (nv < 0 || nf < 0)
    file.fail("negative count (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
              " faces)");
  // The shortest vertex line is "0 0 0\n", the shortest face "3 0 0 0\n": larger counts cannot be
  // true and would only make us reserve absurd memory.
  const std::uint64_t least_bytes =
      static_cast<std::uint64_t>(nv) * 6u + static_cast<std::uint64_t>(nf) * 8u;
  if (nv > 2147483647L || nf > 2147483647L || least_bytes > file.size() + 1)
    file.fail("counts of " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
              " faces cannot fit in a file of " + std::to_string(file.size()) + " bytes");

  TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(nv));
  mesh.faces.reserve(static_cast<std::size_t>(nf));
  for (long v = 0; v < nv; ++v) {
    if (!file.nextLine(line))
      file.fail("file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    Tokens tokens(line);
    const std::string context = "vertex " + std::to_string(v);
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k)
      p[k] = file.parseFinite(file.require(tokens, context, "coordinate"), "coordinate");
    mesh.vertices.push_back(p); // further values (colours, normals) are ignored
  }

  std::vector<int> corners;
  for (long f = 0; f < nf; ++f) {
    if (!file.nextLine(line))
      file.fail("file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    Tokens tokens(line);
    const std::string context = "face " + std::to_string(f);
    const long n = file.parseLong(file.require(tokens, context, "vertex count"), "face size");
    if (n < 3)
      file.fail(context + " has " + std::to_string(n) + " vertices; a face needs at least 3");
    if (static_cast<std::size_t>(n) > tokens.remaining())
      file.fail(context + " announces " + std::to_string(n) + " vertices but lists only " +
                std::to_string(tokens.remaining()) + " values");
    corners.clear();
    for (long k = 0; k < n; ++k) {
      const int index = file.parseInt(file.require(tokens, context, "index"), "vertex index");
      if (index < 0 || index >= nv)
        file.fail(context + " refers to vertex " + std::to_string(index) + " but there are " +
                  std::to_string(nv) + " vertices");
      corners.push_back(index);
    }
    detail::appendFan(mesh.faces, corners);
    // Anything after the indices (per-face colours) is ignored.
  }

  if (file.nextLine(line))
    file.fail("data after the " + std::to_string(nf) +
              " faces the header announces (are the counts wrong?)");
  return mesh;
}

void
saveOff(const std::string& path, const TriangleMesh& mesh)
{
  detail::checkMeshForWriting(path, mesh);
  std::string text = "OFF\n";
  detail::appendLine(text, "",
                     std::array<long, 3>{static_cast<long>(mesh.vertices.size()),
                                         static_cast<long>(mesh.faces.size()), 0L});
  for (const Eigen::Vector3d& p : mesh.vertices)
    detail::appendLine(text, "", p);
  for (const Eigen::Vector3i& f : mesh.faces)
    detail::appendLine(text, "3", f);
  detail::writeTextAtomically(path, text);
}

} // namespace io
} // namespace segmat
