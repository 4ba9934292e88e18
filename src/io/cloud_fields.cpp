/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_fields.h"
#include "file_headers.h"

#include <segmat/common/error.h>

#include <cstdint>
#include <cstring>
#include <fstream>

namespace segmat {
namespace io {
namespace detail {
namespace {
template <typename T>
double
at(const std::uint8_t* p)
{
  T value;
  std::memcpy(&value, p, sizeof value); // unaligned-safe
  return static_cast<double>(value);
}

using Reader = double (*)(const std::uint8_t*);

template <typename T>
void
reader(Reader& read, std::size_t& size)
{
  read = at<T>;
  size = sizeof(T);
}
} // namespace

int
findField(const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (std::size_t i = 0; i < cloud.fields.size(); ++i)
    if (cloud.fields[i].name == name)
      return static_cast<int>(i);
  return -1;
}

std::vector<double>
readFieldAsDouble(const pcl::PCLPointCloud2& cloud, int field)
{
  const pcl::PCLPointField& f = cloud.fields[field];
  const std::size_t n = static_cast<std::size_t>(cloud.width) * cloud.height;
  Reader read = nullptr;
  std::size_t size = 0;
  switch (f.datatype) {
  case pcl::PCLPointField::INT8: reader<std::int8_t>(read, size); break;
  case pcl::PCLPointField::UINT8: reader<std::uint8_t>(read, size); break;
  case pcl::PCLPointField::INT16: reader<std::int16_t>(read, size); break;
  case pcl::PCLPointField::UINT16: reader<std::uint16_t>(read, size); break;
  case pcl::PCLPointField::INT32: reader<std::int32_t>(read, size); break;
  case pcl::PCLPointField::UINT32: reader<std::uint32_t>(read, size); break;
  case pcl::PCLPointField::INT64: reader<std::int64_t>(read, size); break;
  case pcl::PCLPointField::UINT64: reader<std::uint64_t>(read, size); break;
  case pcl::PCLPointField::FLOAT32: reader<float>(read, size); break;
  case pcl::PCLPointField::FLOAT64: reader<double>(read, size); break;
  default:
    throw Error("field '" + f.name + "' has an unknown type (" + std::to_string(f.datatype) + ")");
  }
  // Every point must lie inside the buffer: a reader that under-filled it must not make us read
  // past its end.
  if (n > 0 && (f.offset + size > cloud.point_step ||
                cloud.data.size() < (n - 1) * cloud.point_step + f.offset + size))
    throw Error("point data shorter than the " + std::to_string(n) + " points announced");
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i)
    values[i] = read(cloud.data.data() + i * cloud.point_step + f.offset);
  return values;
}

bool
hasFields(const pcl::PCLPointCloud2& cloud, const std::array<const char*, 3>& names)
{
  for (const char* name : names)
    if (findField(cloud, name) < 0)
      return false;
  return true;
}

std::vector<Eigen::Vector3d>
readVectorField(const pcl::PCLPointCloud2& cloud, const std::array<const char*, 3>& names)
{
  std::vector<Eigen::Vector3d> out(static_cast<std::size_t>(cloud.width) * cloud.height);
  for (int k = 0; k < 3; ++k) {
    const int field = findField(cloud, names[k]);
    if (field < 0)
      throw Error(std::string("no '") + names[k] + "' field");
    const std::vector<double> values = readFieldAsDouble(cloud, field);
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i][k] = values[i];
  }
  return out;
}

void
runPclReader(const std::string& path, const char* format, const std::function<bool()>& read)
{
  requireRegularFile(path);
  if (!std::ifstream(path))
    throw Error(path, 0, "cannot open the file (missing or unreadable)");
  bool ok = false;
  try {
    ok = read();
  } catch (const std::exception& e) {
    throw Error(path, 0, std::string("not a readable ") + format + " file: " + e.what());
  }
  if (!ok)
    throw Error(path, 0, std::string("not a readable ") + format + " file (PCL's reader failed)");
}

} // namespace detail
} // namespace io
} // namespace segmat
