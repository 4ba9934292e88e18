/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/triangle_mesh.h>
#include "point_bounds.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>

namespace segmat {

Eigen::Vector3d
TriangleMesh::faceNormal(int f) const
{
  const Eigen::Vector3i& t = faces[f];
  const Eigen::Vector3d n =
      (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
  const double len = n.norm();
  return len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

double
TriangleMesh::faceArea(int f) const
{
  const Eigen::Vector3i& t = faces[f];
  return 0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
}

Eigen::Vector3d
TriangleMesh::faceCentroid(int f) const
{
  const Eigen::Vector3i& t = faces[f];
  return (vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) / 3.0;
}

std::vector<Eigen::Vector3d>
TriangleMesh::faceNormals() const
{
  std::vector<Eigen::Vector3d> normals(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    normals[f] = faceNormal(static_cast<int>(f));
  return normals;
}

double
TriangleMesh::boundingBoxDiagonal() const
{
  return detail::boundsDiagonal(vertices);
}

std::vector<FaceAdjacency>
TriangleMesh::faceAdjacency() const
{
  // Sort (edge, face) records so faces on the same edge are contiguous: O(F log F), deterministic.
  std::vector<std::array<int, 3>> records;
  records.reserve(faces.size() * 3);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Eigen::Vector3i& t = faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      continue;
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      records.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
    }
  }
  std::sort(records.begin(), records.end());
  std::vector<FaceAdjacency> pairs;
  pairs.reserve(records.size() / 2);
  for (std::size_t i = 0; i < records.size();) {
    std::size_t j = i;
    while (j < records.size() && records[j][0] == records[i][0] && records[j][1] == records[i][1])
      ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b)
        if (records[a][2] != records[b][2])
          pairs.push_back({records[a][2], records[b][2], records[i][0], records[i][1]});
    i = j;
  }
  std::sort(pairs.begin(), pairs.end(), [](const FaceAdjacency& x, const FaceAdjacency& y) {
    return std::tie(x.face_a, x.face_b, x.v0, x.v1) < std::tie(y.face_a, y.face_b, y.v0, y.v1);
  });
  return pairs;
}

} // namespace segmat
