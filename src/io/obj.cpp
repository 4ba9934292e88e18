/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "polygon_fan.h"
#include "text_file.h"

#include <segmat/common/error.h>
#include <segmat/io/obj.h>

namespace segmat {
namespace io {

TriangleMesh
loadObj(const std::string& path)
{
  detail::TextFile file(path, "OBJ", true);
  TriangleMesh mesh;
  // Corners are checked once every vertex is known (a face may precede a later `v` line).
  struct PendingFace
  {
    std::vector<long> corners;
    long line;
  };
  std::vector<PendingFace> faces;
  std::string_view line, token;
  while (file.nextLine(line)) {
    detail::Tokens tokens(line);
    tokens.next(token);
    if (token == "v") {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k)
        p[k] = file.parseFinite(file.require(tokens, "'v' line", "coordinate"), "coordinate");
      mesh.vertices.push_back(p); // w or vertex colours may follow: ignored
    } else if (token == "f") {
      PendingFace face{{}, file.lineNumber()};
      while (tokens.next(token)) {
        // "i", "i/t", "i/t/n", "i//n": the vertex index is the part before the first slash.
        const long index = file.parseLong(token.substr(0, token.find('/')), "vertex index");
        if (index == 0)
          file.fail("vertex index 0 (OBJ indices start at 1)");
        // Negative indices count back from the last vertex read so far.
        face.corners.push_back(index > 0 ? index - 1
                                         : static_cast<long>(mesh.vertices.size()) + index);
      }
      if (face.corners.size() < 3)
        file.fail("face has " + std::to_string(face.corners.size()) +
                  " corners; a face needs at least 3");
      faces.push_back(std::move(face));
    }
  }
  if (mesh.vertices.empty())
    file.failFile(file.lineNumber() == 0 ? "empty file" : "no 'v' lines: not an OBJ mesh");

  const long n = static_cast<long>(mesh.vertices.size());
  mesh.faces.reserve(faces.size());
  for (const PendingFace& face : faces) {
    for (long c : face.corners)
      if (c < 0 || c >= n)
        throw Error(path, face.line,
                    "face refers to vertex " + std::to_string(c + 1) + " (1-based) but there are " +
                        std::to_string(n) + " vertices");
    detail::appendFan(mesh.faces, face.corners);
  }
  return mesh;
}

void
saveObj(const std::string& path, const TriangleMesh& mesh)
{
  detail::checkMeshForWriting(path, mesh);
  std::string text = "# written by segmat\n";
  for (const Eigen::Vector3d& p : mesh.vertices)
    detail::appendLine(text, "v", p);
  for (const Eigen::Vector3i& f : mesh.faces)
    detail::appendLine(text, "f", (f.array() + 1).eval()); // OBJ counts from 1
  detail::writeTextAtomically(path, text);
}

} // namespace io
} // namespace segmat
