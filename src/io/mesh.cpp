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
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
// The only file that includes VTK-based PCL I/O (heavy headers, VTK link interface).
#include <pcl/io/vtk_lib_io.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include <vtkStringOutputWindow.h>

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

// ": REASON" from VTK's captured messages ("... vtkSTLReader (0x...): STLReader: REASON"), or "".
std::string
vtkReason(const std::string& text)
{
  const std::string tag = "Reader: ";
  const std::size_t at = text.find(tag);
  if (at == std::string::npos)
    return "";
  const std::size_t start = at + tag.size();
  return ": " + text.substr(start, text.find('\n', start) - start);
}
} // namespace

TriangleMesh
loadMesh(const std::string& path)
{
  detail::requireRegularFile(path);
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
    // VTK prints its reason through its output window, in terminal colours, and PCL adds a
    // line of its own: capture VTK's instead, put it into the error, and keep PCL quiet.
    const vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
    vtkNew<vtkStringOutputWindow> capture;
    vtkOutputWindow::SetInstance(capture);
    const vtkLogger::Verbosity logged = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    const pcl::console::VERBOSITY_LEVEL verbosity = pcl::console::getVerbosityLevel();
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    pcl::PolygonMesh polygons;
    bool read = false;
    try {
      // Returns the number of points read; VTK reports a bad file by reading none.
      read = pcl::io::loadPolygonFileSTL(path, polygons) > 0;
    } catch (...) {
    }
    vtkOutputWindow::SetInstance(previous);
    vtkLogger::SetStderrVerbosity(logged);
    pcl::console::setVerbosityLevel(verbosity);
    if (!read)
      throw Error(path, 0, "not a readable STL file" + vtkReason(capture->GetOutput()));
    return detail::withPath(path, [&] { return fromPolygonMesh(polygons); });
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
