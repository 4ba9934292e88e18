/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_fields.h"
#include "polygon_fan.h"

#include <segmat/common/error.h>
#include <segmat/io/polygon_mesh.h>

#include <pcl/conversions.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace segmat {
namespace io {

TriangleMesh
fromPolygonMesh(const pcl::PolygonMesh& mesh)
{
  TriangleMesh out;
  out.vertices = detail::readVectorField(mesh.cloud, {"x", "y", "z"});
  for (std::size_t v = 0; v < out.vertices.size(); ++v)
    if (!out.vertices[v].allFinite())
      throw Error("vertex " + std::to_string(v) + " is not finite");
  const std::size_t n = out.vertices.size();
  out.faces.reserve(mesh.polygons.size());
  for (std::size_t p = 0; p < mesh.polygons.size(); ++p) {
    const auto& corners = mesh.polygons[p].vertices;
    if (corners.size() < 3)
      throw Error("face " + std::to_string(p) + " has " + std::to_string(corners.size()) +
                  " corners; a face needs at least 3");
    for (const auto c : corners)
      if (static_cast<std::size_t>(c) >= n)
        throw Error("face " + std::to_string(p) + " refers to vertex " + std::to_string(c) +
                    " but there are " + std::to_string(n) + " vertices");
    detail::appendFan(out.faces, corners);
  }
  return out;
}

pcl::PolygonMesh
toPolygonMesh(const TriangleMesh& mesh)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices)
    cloud.push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                  static_cast<float>(p.z())));
  pcl::PolygonMesh out;
  pcl::toPCLPointCloud2(cloud, out.cloud);
  out.polygons.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    out.polygons[f].vertices = {static_cast<pcl::index_t>(mesh.faces[f][0]),
                                static_cast<pcl::index_t>(mesh.faces[f][1]),
                                static_cast<pcl::index_t>(mesh.faces[f][2])};
  return out;
}

} // namespace io
} // namespace segmat
