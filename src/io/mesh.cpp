/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_fields.h"
#include "file_headers.h"
#include "ply_text.h"
#include "text_file.h"

#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/mesh.h>
#include <segmat/io/obj.h>
#include <segmat/io/off.h>
#include <segmat/io/polygon_mesh.h>

#include <pcl/PolygonMesh.h>
#include <pcl/io/ply_io.h>
// The only file that includes VTK-based PCL I/O (heavy headers, VTK link interface).
#include <pcl/io/vtk_lib_io.h>

#include <functional>

namespace segmat {
namespace io {
namespace {
const char* const kLoadFormats = ".off, .ply, .obj, .stl";
const char* const kSaveFormats = ".off, .ply, .obj";

TriangleMesh
loadWithPcl(const std::string& path, const char* format,
            const std::function<bool(pcl::PolygonMesh&)>& read)
{
  pcl::PolygonMesh polygons;
  detail::runPclReader(path, format, [&] { return read(polygons); });
  return detail::withPath(path, [&] { return fromPolygonMesh(polygons); });
}
} // namespace

TriangleMesh
loadMesh(const std::string& path)
{
  const std::string ext = extensionOf(path);
  if (ext == "off")
    return loadOff(path);
  if (ext == "ply") {
    detail::checkPlyHeader(path);
    return loadWithPcl(path, "PLY",
                       [&](pcl::PolygonMesh& m) { return pcl::io::loadPLYFile(path, m) >= 0; });
  }
  if (ext == "obj") // segmat's reader: PCL's crashes on damaged OBJ files
    return loadObj(path);
  if (ext == "stl") {
    detail::checkStlSize(path);
    // Returns the number of points read; VTK reports a bad file by reading none.
    return loadWithPcl(
        path, "STL", [&](pcl::PolygonMesh& m) { return pcl::io::loadPolygonFileSTL(path, m) > 0; });
  }
  throw Error(path, 0, "unknown mesh format '." + ext + "' (supported: " + kLoadFormats + ")");
}

void
saveMesh(const std::string& path, const TriangleMesh& mesh)
{
  const std::string ext = extensionOf(path);
  if (ext == "off")
    return saveOff(path, mesh);
  if (ext == "obj")
    return saveObj(path, mesh);
  if (ext != "ply")
    throw Error(path, 0,
                "cannot write mesh format '." + ext + "' (supported: " + kSaveFormats + ")");
  detail::checkMeshForWriting(path, mesh);
  detail::writeTextAtomically(path, detail::plyText(mesh.vertices, nullptr, &mesh.faces, nullptr));
}

} // namespace io
} // namespace segmat
