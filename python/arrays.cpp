/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "arrays.h"

#include <cmath>
#include <cstring>
#include <string>

namespace segmat_python {

namespace {

/** \a array as a numpy array of shape (n, columns) (columns 0: 1-D), n > 0, whose dtype kind is
 * one of \a kinds ("f": real, "iu": integer). */
py::array
checkedArray(const py::handle& handle, const char* what, py::ssize_t columns, const char* kinds)
{
  const std::string name(what);
  if (handle.is_none())
    throw py::value_error(name + ": expected an array, got None");
  py::array array = py::array::ensure(handle);
  if (!array)
    throw py::value_error(name + ": cannot be read as an array");
  const char kind = array.dtype().kind();
  if (std::strchr(kinds, kind) == nullptr || kind == '\0') {
    throw py::value_error(name + ": dtype " + std::string(py::str(array.dtype())) + " is not " +
                          (std::strchr(kinds, 'f') ? "a floating-point type" : "an integer type"));
  }
  const std::string wanted = columns > 0 ? "(n, " + std::to_string(columns) + ")" : "(n,)";
  std::string shape = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d)
    shape += (d ? ", " : "") + std::to_string(array.shape(d));
  shape += array.ndim() == 1 ? ",)" : ")";
  if (array.ndim() != (columns > 0 ? 2 : 1) || (columns > 0 && array.shape(1) != columns))
    throw py::value_error(name + ": shape " + shape + " is not " + wanted);
  if (array.shape(0) == 0)
    throw py::value_error(name + ": is empty");
  return array;
}

} // namespace

std::vector<Eigen::Vector3d>
toRows3d(const py::handle& handle, const char* what)
{
  const py::array checked = checkedArray(handle, what, 3, "f");
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(checked);
  const std::size_t n = static_cast<std::size_t>(values.shape(0));
  std::vector<Eigen::Vector3d> rows(n);
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "rows are packed doubles");
  std::memcpy(static_cast<void*>(rows.data()), values.data(), n * sizeof(Eigen::Vector3d));
  for (std::size_t i = 0; i < n; ++i)
    if (!rows[i].allFinite())
      throw py::value_error(std::string(what) + ": row " + std::to_string(i) +
                            " has a non-finite value (NaN or inf)");
  return rows;
}

std::vector<Eigen::Vector3i>
toFaces(const py::handle& handle, std::size_t num_vertices, const char* what)
{
  const py::array checked = checkedArray(handle, what, 3, "iu");
  const auto values =
      py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(checked);
  const std::size_t m = static_cast<std::size_t>(values.shape(0));
  const long long* data = values.data();
  std::vector<Eigen::Vector3i> faces(m);
  for (std::size_t f = 0; f < m; ++f)
    for (int c = 0; c < 3; ++c) {
      const long long v = data[3 * f + c];
      if (v < 0 || static_cast<unsigned long long>(v) >= num_vertices)
        throw py::value_error(std::string(what) + ": face " + std::to_string(f) +
                              " has vertex index " + std::to_string(v) + ", not in [0, " +
                              std::to_string(num_vertices) + ")");
      faces[f][c] = static_cast<int>(v);
    }
  return faces;
}

segmat::TriangleMesh::Ptr
toMesh(const py::handle& vertices, const py::handle& faces)
{
  std::vector<Eigen::Vector3d> v = toRows3d(vertices, "vertices");
  std::vector<Eigen::Vector3i> f = toFaces(faces, v.size(), "faces");
  return std::make_shared<segmat::TriangleMesh>(std::move(v), std::move(f));
}

pcl::PointCloud<pcl::PointNormal>::Ptr
toCloud(const py::handle& points, const py::handle& normals)
{
  const std::vector<Eigen::Vector3d> p = toRows3d(points, "points");
  std::vector<Eigen::Vector3d> n;
  if (!normals.is_none()) {
    n = toRows3d(normals, "normals");
    if (n.size() != p.size())
      throw py::value_error("normals: " + std::to_string(n.size()) + " rows for " +
                            std::to_string(p.size()) + " points");
  }
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  cloud->resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    pcl::PointNormal& q = (*cloud)[i];
    q.getVector3fMap() = p[i].cast<float>();
    q.getNormalVector3fMap() = n.empty() ? Eigen::Vector3f::Zero() : Eigen::Vector3f(n[i].cast<float>());
    q.curvature = 0.0f;
  }
  return cloud;
}

std::vector<int>
toLabels(const py::handle& handle, std::size_t expected, const char* what)
{
  const py::array checked = checkedArray(handle, what, 0, "iu");
  const auto values =
      py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(checked);
  const std::size_t n = static_cast<std::size_t>(values.shape(0));
  if (expected > 0 && n != expected)
    throw py::value_error(std::string(what) + ": " + std::to_string(n) + " labels, expected " +
                          std::to_string(expected));
  std::vector<int> labels(n);
  for (std::size_t i = 0; i < n; ++i) {
    const long long l = values.data()[i];
    if (l < -2147483648LL || l > 2147483647LL)
      throw py::value_error(std::string(what) + ": label " + std::to_string(l) +
                            " does not fit in 32 bits");
    labels[i] = static_cast<int>(l);
  }
  return labels;
}

py::array_t<int>
toArray(std::vector<int>&& values)
{
  auto* owned = new std::vector<int>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<int>*>(p); });
  return py::array_t<int>({static_cast<py::ssize_t>(owned->size())}, owned->data(), owner);
}

namespace {

/** A read-only (rows, columns) view of \a data (rows of packed Scalar), kept alive by \a owner. */
template <typename Scalar>
py::array
view(const Scalar* data, std::size_t rows, py::ssize_t columns, const py::capsule& owner)
{
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(rows)};
  if (columns > 0)
    shape.push_back(columns);
  py::array_t<Scalar> array(shape, data, owner);
  array.attr("setflags")(py::arg("write") = false);
  return std::move(array);
}

} // namespace

py::tuple
toArrays(const segmat::MedialMesh::ConstPtr& mat)
{
  auto* kept = new segmat::MedialMesh::ConstPtr(mat);
  py::capsule owner(kept, [](void* p) { delete static_cast<segmat::MedialMesh::ConstPtr*>(p); });
  return py::make_tuple(view(mat->centers().empty() ? nullptr : mat->centers()[0].data(),
                             mat->numVertices(), 3, owner),
                        view(mat->radii().data(), mat->numVertices(), 0, owner),
                        view(mat->edges().empty() ? nullptr : mat->edges()[0].data(),
                             mat->numEdges(), 2, owner),
                        view(mat->triangles().empty() ? nullptr : mat->triangles()[0].data(),
                             mat->numTriangles(), 3, owner));
}

} // namespace segmat_python
