/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "ply_text.h"
#include "text_file.h"

#include <segmat/common/error.h>
#include <segmat/io/colored_ply.h>

#include <pcl/common/colors.h>

namespace segmat {
namespace io {
namespace {
std::vector<Rgb>
labelColors(const std::string& path, const std::vector<int>& labels, std::size_t expected,
            const char* what)
{
  if (labels.size() != expected)
    throw Error(path, 0,
                "not written: " + std::to_string(labels.size()) + " labels for " +
                    std::to_string(expected) + " " + what);
  std::vector<Rgb> colors(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    colors[i] = labelColor(labels[i]);
  return colors;
}
} // namespace

Rgb
labelColor(int label)
{
  if (label < 0)
    return {128, 128, 128};
  const pcl::RGB c = pcl::GlasbeyLUT::at(static_cast<std::size_t>(label) % pcl::GlasbeyLUT::size());
  return {c.r, c.g, c.b};
}

void
saveColoredMeshPly(const std::string& path, const TriangleMesh& mesh,
                   const std::vector<int>& face_labels)
{
  detail::checkMeshForWriting(path, mesh);
  const std::vector<Rgb> colors = labelColors(path, face_labels, mesh.faces.size(), "faces");
  detail::writeTextAtomically(path, detail::plyText(mesh.vertices, nullptr, &mesh.faces, &colors));
}

void
saveColoredCloudPly(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<int>& labels)
{
  const std::vector<Rgb> colors = labelColors(path, labels, points.size(), "points");
  detail::writeTextAtomically(path, detail::plyText(points, &colors, nullptr, nullptr));
}

void
saveColoredCloudPly(const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud)
{
  std::vector<Eigen::Vector3d> points(cloud.size());
  std::vector<int> labels(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    points[i] = cloud[i].getVector3fMap().cast<double>();
    labels[i] = static_cast<int>(cloud[i].label);
  }
  saveColoredCloudPly(path, points, labels);
}

} // namespace io
} // namespace segmat
