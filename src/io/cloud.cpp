/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_fields.h"
#include "file_headers.h"
#include "text_file.h"

#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/cloud.h>
#include <segmat/io/seg.h>

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace segmat {
namespace io {
namespace {
const char* const kCloudFormats = ".pcd, .ply, .xyz, .txt";

/// LoadedCloud::origin for these points: zero near 0, else the bounding box's centre rounded to
/// a power of ten no larger than the diagonal (a readable shift that keeps float precision).
Eigen::Vector3d
recentringOrigin(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite())
      box.extend(p);
  if (box.isEmpty())
    return Eigen::Vector3d::Zero();
  const Eigen::Vector3d centre = box.center();
  const double diagonal = box.diagonal().norm();
  // Float resolves ~1.2e-7 of a coordinate: 100 diagonals away that is ~1e-5 of the diagonal,
  // below any sampling; far beyond it the cloud turns into a grid (1e6 from 0, teddy's 1.7
  // diagonal is 0.06 per float step).
  if (!(centre.cwiseAbs().maxCoeff() > 100.0 * diagonal))
    return Eigen::Vector3d::Zero();
  const double step = diagonal > 0.0 ? std::pow(10.0, std::floor(std::log10(diagonal))) : 1.0;
  return (centre / step).array().round().matrix() * step;
}

LoadedCloud
makeCloud(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>* normals)
{
  LoadedCloud out;
  out.origin = recentringOrigin(points);
  out.cloud.reset(new pcl::PointCloud<pcl::PointNormal>);
  out.cloud->resize(points.size());
  out.has_normals = normals != nullptr;
  bool dense = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    pcl::PointNormal& p = (*out.cloud)[i];
    p.getVector3fMap() = (points[i] - out.origin).cast<float>();
    if (normals)
      p.getNormalVector3fMap() = (*normals)[i].cast<float>();
    else
      p.getNormalVector3fMap().setZero();
    p.curvature = 0.f;
    dense = dense && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }
  out.cloud->is_dense = dense;
  return out;
}

// PCD and PLY through PCL into a PCLPointCloud2, then every field converted by name.
LoadedCloud
loadWithPcl(const std::string& path, const char* format,
            const std::function<int(pcl::PCLPointCloud2&)>& read)
{
  pcl::PCLPointCloud2 blob;
  detail::runPclReader(path, format, [&] { return read(blob) >= 0; });
  return detail::withPath(path, [&] {
    const std::vector<Eigen::Vector3d> points = detail::readVectorField(blob, {"x", "y", "z"});
    // PCL's PLY reader renames nx/ny/nz to normal_x/y/z; other writers may not.
    using Names = std::array<const char*, 3>;
    for (const Names& names :
         {Names{"normal_x", "normal_y", "normal_z"}, Names{"nx", "ny", "nz"}}) {
      if (detail::hasFields(blob, names)) {
        const std::vector<Eigen::Vector3d> normals = detail::readVectorField(blob, names);
        return makeCloud(points, &normals);
      }
    }
    return makeCloud(points, nullptr);
  });
}

LoadedCloud
loadXyz(const std::string& path)
{
  detail::TextFile file(path, "XYZ", true);
  std::vector<Eigen::Vector3d> points, normals;
  std::string_view line, token;
  std::string spaced;
  while (file.nextLine(line)) {
    spaced.assign(line.begin(), line.end());
    std::replace(spaced.begin(), spaced.end(), ',', ' '); // CSV-style exports
    detail::Tokens tokens(spaced);
    double values[6];
    int n = 0;
    while (tokens.next(token)) {
      if (n == 6)
        file.fail("more than 6 values (x y z nx ny nz) on a line");
      values[n++] = file.parseFinite(token, "value");
    }
    if (n != 3 && n != 6)
      file.fail(std::to_string(n) + " values; a line holds x y z or x y z nx ny nz");
    if (!points.empty() && (n == 6) != (normals.size() == points.size()))
      file.fail("mixes lines with and without normals");
    points.emplace_back(values[0], values[1], values[2]);
    if (n == 6)
      normals.emplace_back(values[3], values[4], values[5]);
  }
  if (points.empty())
    file.failFile("no points");
  return makeCloud(points, normals.empty() ? nullptr : &normals);
}
} // namespace

LoadedCloud
loadCloud(const std::string& path)
{
  detail::requireRegularFile(path);
  const std::string ext = extensionOf(path);
  if (ext == "pcd") {
    detail::checkPcdHeader(path);
    return loadWithPcl(path, "PCD",
                       [&](pcl::PCLPointCloud2& blob) { return pcl::io::loadPCDFile(path, blob); });
  }
  if (ext == "ply") {
    detail::checkPlyHeader(path);
    return loadWithPcl(path, "PLY",
                       [&](pcl::PCLPointCloud2& blob) { return pcl::io::loadPLYFile(path, blob); });
  }
  if (ext == "xyz" || ext == "txt")
    return loadXyz(path);
  throw Error(path, 0,
              "unknown point-cloud format '." + ext + "' (supported: " + kCloudFormats + ")");
}

void
saveLabeledCloudPcd(const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud)
{
  writeFileAtomicallyByName(path, [&](const std::string& tmp) {
    try {
      // PCL's binary writer complains about an empty cloud; ASCII writes the same header quietly.
      return (cloud.empty() ? pcl::io::savePCDFileASCII(tmp, cloud)
                            : pcl::io::savePCDFileBinary(tmp, cloud)) == 0;
    } catch (const std::exception& e) { // pcl::IOException when the file cannot be opened
      throw Error(path, 0, std::string("cannot write the file: ") + e.what());
    }
  });
}

void
saveLabels(const std::string& path, const std::vector<int>& labels)
{
  saveSeg(path, labels);
}

} // namespace io
} // namespace segmat
