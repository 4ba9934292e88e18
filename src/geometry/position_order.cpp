/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "position_order.h"

#include "point_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace segmat {
namespace detail {

std::vector<int>
positionOrder(const std::vector<Eigen::Vector3d>& points)
{
  const int n = static_cast<int>(points.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  const Eigen::AlignedBox3d box = finiteBounds(points);
  const double extent = box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
  if (!(extent > 0.0) || !std::isfinite(extent))
    return order;
  const double cells = std::ldexp(1.0, 30) / extent;
  const double offset = 0.6180339887498949; // the golden ratio's fraction
  constexpr std::int64_t kLast = std::numeric_limits<std::int64_t>::max();
  // (cell, input index): sorting these whole orders equal cells by input index, as a stable
  // sort would, without an indirection per comparison.
  std::vector<std::pair<std::array<std::int64_t, 3>, int>> keyed(n);
  for (int i = 0; i < n; ++i) {
    keyed[i].second = i;
    for (int k = 0; k < 3; ++k)
      keyed[i].first[k] = points[i].allFinite()
                              ? static_cast<std::int64_t>(
                                    std::floor((points[i][k] - box.min()[k]) * cells + offset))
                              : kLast;
  }
  std::sort(keyed.begin(), keyed.end());
  for (int i = 0; i < n; ++i)
    order[i] = keyed[i].second;
  return order;
}

std::vector<int>
sortMeshByPosition(TriangleMesh& mesh)
{
  const int nv = static_cast<int>(mesh.vertices.size());
  const std::vector<int> vertex_order = positionOrder(mesh.vertices);
  std::vector<int> new_index(nv);
  std::vector<Eigen::Vector3d> vertices(nv);
  for (int k = 0; k < nv; ++k) {
    new_index[vertex_order[k]] = k;
    vertices[k] = mesh.vertices[vertex_order[k]];
  }
  mesh.vertices.swap(vertices);
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<Eigen::Vector3i> faces(nf);
  for (int f = 0; f < nf; ++f) {
    Eigen::Vector3i face = mesh.faces[f];
    if (face.minCoeff() >= 0 && face.maxCoeff() < nv) // invalid faces are reported later
      for (int k = 0; k < 3; ++k)
        face[k] = new_index[face[k]];
    int first = 0;
    for (int k = 1; k < 3; ++k)
      if (face[k] < face[first])
        first = k;
    faces[f] = Eigen::Vector3i(face[first], face[(first + 1) % 3], face[(first + 2) % 3]);
  }
  std::vector<int> face_of(nf);
  std::iota(face_of.begin(), face_of.end(), 0);
  std::stable_sort(face_of.begin(), face_of.end(), [&](int a, int b) {
    return std::lexicographical_compare(faces[a].data(), faces[a].data() + 3, faces[b].data(),
                                        faces[b].data() + 3);
  });
  mesh.faces.resize(nf);
  for (int k = 0; k < nf; ++k)
    mesh.faces[k] = faces[face_of[k]];
  return face_of;
}

} // namespace detail
} // namespace segmat
