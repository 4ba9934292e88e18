/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: reading named fields of a pcl::PCLPointCloud2 whatever their stored type.
// pcl::fromPCLPointCloud2 maps a field only when its type matches the point type's exactly, so a
// PLY with `property double x` (Open3D, MeshLab "double" export) would come back as zeros with a
// console warning; these helpers convert every numeric type instead.

#include <segmat/common/error.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace segmat {
namespace io {
namespace detail {

/** \brief Index of the field called \a name in \a cloud.fields, or -1. */
int
findField(const pcl::PCLPointCloud2& cloud, const std::string& name);

/** \brief First element of field number \a field of every point, converted to double.
 * \throws segmat::Error (no path) when the field's type is unknown or the data are shorter than
 *         width * height * point_step.
 */
std::vector<double>
readFieldAsDouble(const pcl::PCLPointCloud2& cloud, int field);

/** \brief Fields \a names[0..2] of every point as 3-vectors.
 * \throws segmat::Error (no path) when one of them is missing, or as readFieldAsDouble.
 */
std::vector<Eigen::Vector3d>
readVectorField(const pcl::PCLPointCloud2& cloud, const std::array<const char*, 3>& names);

/** \brief True when \a cloud has all three fields \a names. */
bool
hasFields(const pcl::PCLPointCloud2& cloud, const std::array<const char*, 3>& names);

/** \brief Runs \a read, a call of one of PCL's readers on \a path returning true on success, and
 * turns every way it can fail into segmat::Error(path, 0, ...): a missing file (checked first, so
 * PCL prints nothing), an exception, a failure code. PCL prints its own reason to the console. */
void
runPclReader(const std::string& path, const char* format, const std::function<bool()>& read);

/** \brief Returns \a convert(), re-throwing a segmat::Error it throws with \a path added. */
template <typename Convert>
auto
withPath(const std::string& path, const Convert& convert) -> decltype(convert())
{
  try {
    return convert();
  } catch (const Error& e) {
    throw Error(path, 0, e.message());
  }
}

} // namespace detail
} // namespace io
} // namespace segmat
