/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace segmat {
namespace io {

/** \brief A point cloud as read from a file, with whether the file carried normals. */
struct LoadedCloud
{
  /** \brief Points; normal_x/y/z are the file's normals when has_normals, else 0. Points with a
   * non-finite coordinate are kept (organised PCD files use NaN for "no return"); is_dense says
   * whether there are any. Never null after loadCloud. */
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud;
  /** \brief True when the file has all three normal fields (`normal_x/y/z`, or `nx/ny/nz`). */
  bool has_normals = false;
  /** \brief Where the points were moved from: a file point is `cloud` point + origin. Zero
   * unless the file's points lie far from 0 for their size (more than 100 times their bounding
   * box's diagonal, as georeferenced scans do): PCL stores float coordinates, which resolve only
   * about 1e-7 of their magnitude, so such a cloud is read relative to its bounding box's centre,
   * rounded to a multiple of the largest power of ten not above the diagonal (full precision
   * is kept where the file stores double or text coordinates). */
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/** \brief Reads a point cloud, choosing the reader by extension (any case).
 *
 *  - `.pcd`: PCL's reader (ASCII, binary, binary_compressed);
 *  - `.ply`: PCL's reader after segmat's header check (the vertex element; faces are ignored);
 *  - `.xyz`, `.txt`: segmat's reader, one point per line, `x y z` or `x y z nx ny nz`
 *    (separated by blanks or commas, `#` comments); normals when every line has six values.
 * Fields stored as float, double or integers are all read.
 * \throws segmat::Error naming \a path for a missing file, a file the reader rejects, no x/y/z
 *         fields, an unknown extension (with the supported list); with the line for `.xyz`/`.txt`
 *         and for PLY header problems.
 */
LoadedCloud
loadCloud(const std::string& path);

/** \brief Writes a labelled cloud as a binary PCD (x y z label), whole or not at all.
 * \throws segmat::Error naming \a path when the file cannot be written.
 */
void
saveLabeledCloudPcd(const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud);

/** \brief Writes per-point labels one integer per line: the `.seg` format (saveSeg), so
 * loadSeg(path, cloud size) reads them back. Whole or not at all. */
void
saveLabels(const std::string& path, const std::vector<int>& labels);

} // namespace io
} // namespace segmat
