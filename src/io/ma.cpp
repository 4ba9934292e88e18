/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "text_file.h"

#include <segmat/common/error.h>
#include <segmat/io/ma.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <array>

namespace segmat {
namespace io {
namespace {
using detail::TextFile;
using detail::Tokens;

bool
isTag(std::string_view token)
{
  return token == "v" || token == "e" || token == "f" || token == "n";
}

// Reads exactly \a count numbers after a tag; a missing or an extra value is an error.
template <int Count, typename Parse>
void
readValues(const TextFile& file, Tokens& tokens, const char* tag, const Parse& parse)
{
  std::string_view token;
  for (int k = 0; k < Count; ++k) {
    if (!tokens.next(token))
      file.fail(std::string("'") + tag + "' line needs " + std::to_string(Count) + " values, has " +
                std::to_string(k));
    parse(k, token);
  }
  if (tokens.next(token))
    file.fail(std::string("'") + tag + "' line needs " + std::to_string(Count) +
              " values, has more: " + detail::quoted(token));
}

// An edge or triangle with the line it came from: indices are checked once every sphere is known,
// so the order of the v/e/f lines does not matter.
template <typename Cell> struct Located
{
  Cell cell;
  long line;
};

template <typename Cell>
std::vector<Cell>
checkedCells(const std::string& path, const std::vector<Located<Cell>>& cells, long num_spheres,
             const char* what)
{
  std::vector<Cell> out;
  out.reserve(cells.size());
  for (const Located<Cell>& c : cells) {
    for (int k = 0; k < c.cell.size(); ++k)
      if (c.cell[k] < 0 || c.cell[k] >= num_spheres)
        throw Error(path, c.line,
                    std::string(what) + " refers to sphere " + std::to_string(c.cell[k]) +
                        " but the file has " + std::to_string(num_spheres) +
                        " spheres (indices are 0-based)");
    out.push_back(c.cell);
  }
  return out;
}
} // namespace

MedialMesh
loadMa(const std::string& path)
{
  // Q-MAT writes no comments; '#' lines are accepted because they cannot be mistaken for data.
  TextFile file(path, "MA", true);
  std::string_view line;
  if (!file.nextLine(line))
    file.failFile("empty file");

  // Optional header "NV NE NF": SEG-MAT's reader ignores it, Q-MAT's trusts it; real files have
  // wrong ones (teddy_smat.ma), so it is only compared at the end.
  long header[3] = {-1, -1, -1};
  bool has_header = false;
  Tokens first(line);
  std::string_view token;
  first.next(token);
  if (!isTag(token)) {
    Tokens counts(line);
    for (long& count : header) {
      count = file.parseLong(file.require(counts, "header 'NV NE NF'", "count"), "header count");
      if (count < 0)
        file.fail("negative count in the header 'NV NE NF'");
    }
    if (counts.next(token))
      file.fail("unexpected " + detail::quoted(token) + " after the header 'NV NE NF'");
    has_header = true;
  }

  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
  std::vector<Located<Eigen::Vector2i>> edges;
  std::vector<Located<Eigen::Vector3i>> triangles;
  // The header only sizes the buffers, and never beyond what the file could hold.
  const auto cap = [&](long count) {
    return static_cast<std::size_t>(std::clamp<long>(count, 0, file.size() / 6));
  };
  centers.reserve(cap(header[0]));
  radii.reserve(cap(header[0]));
  edges.reserve(cap(header[1]));
  triangles.reserve(cap(header[2]));

  for (bool more = has_header ? file.nextLine(line) : true; more; more = file.nextLine(line)) {
    Tokens tokens(line);
    tokens.next(token);
    if (token == "v") {
      Eigen::Vector4d s;
      readValues<4>(file, tokens, "v", [&](int k, std::string_view t) {
        s[k] = file.parseFinite(t, k < 3 ? "coordinate" : "radius");
      });
      if (s[3] < 0.0)
        file.fail("radius " + std::to_string(s[3]) + " is negative");
      centers.push_back(s.head<3>());
      radii.push_back(s[3]);
    } else if (token == "e") {
      Eigen::Vector2i e;
      readValues<2>(file, tokens, "e",
                    [&](int k, std::string_view t) { e[k] = file.parseInt(t, "index"); });
      edges.push_back({e, file.lineNumber()});
    } else if (token == "f") {
      Eigen::Vector3i f;
      readValues<3>(file, tokens, "f",
                    [&](int k, std::string_view t) { f[k] = file.parseInt(t, "index"); });
      triangles.push_back({f, file.lineNumber()});
    } else if (token == "n") {
      // Per-sphere normals of SEG-MAT's unused point-cloud path: checked, then dropped, since
      // MedialMesh holds no normals.
      readValues<3>(file, tokens, "n",
                    [&](int, std::string_view t) { file.parseFinite(t, "normal component"); });
    } else {
      file.fail("unknown tag " + detail::quoted(token) + " (expected v, e, f or n)");
    }
  }

  const long nv = static_cast<long>(centers.size());
  if (has_header && (header[0] != nv || header[1] != static_cast<long>(edges.size()) ||
                     header[2] != static_cast<long>(triangles.size())))
    PCL_WARN("[segmat::io::loadMa] %s: the header says %ld %ld %ld but the file holds %ld v, %zu "
             "e and %zu f lines; using the lines\n",
             path.c_str(), header[0], header[1], header[2], nv, edges.size(), triangles.size());

  std::vector<Eigen::Vector2i> edge_list = checkedCells(path, edges, nv, "edge");
  std::vector<Eigen::Vector3i> triangle_list = checkedCells(path, triangles, nv, "triangle");
  try {
    return MedialMesh(std::move(centers), std::move(radii), edge_list, triangle_list);
  } catch (const Error& e) {
    throw Error(path, 0, e.message()); // unreachable after the checks above; keeps the path
  }
}

void
saveMa(const std::string& path, const MedialMesh& mat)
{
  std::string text;
  text.reserve(mat.numVertices() * 80 + (mat.numEdges() + mat.numTriangles()) * 20);
  detail::appendLine(text, "",
                     std::array<long, 3>{static_cast<long>(mat.numVertices()),
                                         static_cast<long>(mat.numEdges()),
                                         static_cast<long>(mat.numTriangles())});
  // Shortest round-trip text (std::to_chars): reading it back gives the same doubles bit for bit.
  for (std::size_t v = 0; v < mat.numVertices(); ++v)
    detail::appendLine(text, "v", mat.sphere(static_cast<int>(v)));
  // Every edge, sides of triangles included, as Q-MAT writes them.
  for (const Eigen::Vector2i& e : mat.edges())
    detail::appendLine(text, "e", e);
  for (const Eigen::Vector3i& f : mat.triangles())
    detail::appendLine(text, "f", f);
  detail::writeTextAtomically(path, text);
}
} // namespace io
} // namespace segmat
