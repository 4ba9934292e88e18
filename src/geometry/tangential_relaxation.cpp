/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "tangential_relaxation.h"

#include "edge_records.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>

namespace segmat {
namespace detail {

void
relaxTangentially(std::vector<Eigen::Vector3d>& vertices,
                  const std::vector<Eigen::Vector3i>& faces, double max_move, int iterations,
                  int threads)
{
  relaxTangentially(vertices, faces, FaceNeighbourhoods(faces, vertices.size()), max_move,
                    iterations, threads);
}

void
relaxTangentially(std::vector<Eigen::Vector3d>& vertices, const std::vector<Eigen::Vector3i>& faces,
                  const FaceNeighbourhoods& around, double max_move, int iterations, int threads)
{
  const long nv = static_cast<long>(vertices.size());
  // Every side of a valid face as an (smaller, larger) edge record.
  std::vector<std::vector<int>> ring(nv);
  std::vector<std::array<int, 2>> sides;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!around.valid[f])
      continue;
    const Eigen::Vector3i& t = faces[f];
    for (int c = 0; c < 3; ++c)
      sides.push_back({std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])});
  }
  // Edge neighbours from the distinct edges. A vertex on an edge of one face (a hole's rim) or
  // of three and more (non-manifold) stays: its neighbours' mean lies off to one side, and
  // moving it would widen the hole.
  sortEdgeRecords(sides, static_cast<int>(nv));
  std::vector<char> pinned(nv, 0);
  for (std::size_t a = 0; a < sides.size();) {
    std::size_t b = a + 1;
    while (b < sides.size() && sides[b] == sides[a])
      ++b;
    const int u = sides[a][0], v = sides[a][1];
    ring[u].push_back(v);
    ring[v].push_back(u);
    if (b - a != 2)
      pinned[u] = pinned[v] = 1;
    a = b;
  }
  for (long v = 0; v < nv; ++v)
    if (pinned[v])
      ring[v].clear();
    else
      std::sort(ring[v].begin(), ring[v].end());
  constexpr double kFlatEigenvalue = 0.03;
  const std::vector<Eigen::Vector3d> start = vertices;
  std::vector<Eigen::Vector3d> area_normals(faces.size()), moved(nv);
  for (int it = 0; it < iterations; ++it) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Eigen::Vector3i& t = faces[f];
      area_normals[f] = Eigen::Vector3d::Zero();
      if (t.minCoeff() >= 0 && t.maxCoeff() < nv)
        area_normals[f] =
            0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    }
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long v = 0; v < nv; ++v) {
      moved[v] = vertices[v];
      if (ring[v].empty())
        continue;
      Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
      for (std::size_t a = around.vertex_first[v]; a < around.vertex_first[v + 1]; ++a) {
        const int f = around.vertex_faces[a];
        const double area = area_normals[f].norm();
        if (area > 0.0)
          tensor += area_normals[f] * area_normals[f].transpose() / area; // a n nᵀ
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
      eigen.computeDirect(tensor);
      const Eigen::Vector3d& values = eigen.eigenvalues(); // ascending
      if (!(values[2] > 0.0))
        continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int u : ring[v])
        mean += vertices[u];
      const Eigen::Vector3d offset = mean / double(ring[v].size()) - vertices[v];
      Eigen::Vector3d step = Eigen::Vector3d::Zero();
      for (int k = 0; k < 2; ++k)
        if (values[k] < kFlatEigenvalue * values[2]) {
          const Eigen::Vector3d e = eigen.eigenvectors().col(k);
          step += e * e.dot(offset);
        }
      Eigen::Vector3d to = vertices[v] + 0.5 * step;
      const Eigen::Vector3d from_start = to - start[v];
      const double distance = from_start.norm();
      if (distance > max_move)
        to = start[v] + from_start * (max_move / distance);
      moved[v] = to;
    }
    vertices.swap(moved);
  }
}

} // namespace detail
} // namespace segmat
