/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/face_orientation.h>
#include <segmat/geometry/weld_points.h>

#include "edge_records.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <deque>

namespace segmat {

std::size_t
orientFacesOutward(TriangleMesh& mesh, double weld_tolerance)
{
  if (mesh.faces.empty())
    return 0;
  return orientFacesOutward(mesh, weldPoints(mesh.vertices, weld_tolerance));
}

std::size_t
orientFacesOutward(TriangleMesh& mesh, const std::vector<int>& rep)
{
  const int nf = static_cast<int>(mesh.faces.size());
  const int nv = static_cast<int>(std::min(mesh.vertices.size(), rep.size()));
  if (nf == 0)
    return 0;
  auto corner = [&](int f, int k) {
    const int v = mesh.faces[f][k];
    return (v >= 0 && v < nv) ? rep[v] : -1;
  };
  auto usable = [&](int f) {
    const int a = corner(f, 0), b = corner(f, 1), c = corner(f, 2);
    return a >= 0 && b >= 0 && c >= 0 && a != b && b != c && a != c;
  };

  // (lo, hi, face, +1 when the face walks lo→hi) sorted so the faces of an edge are contiguous.
  std::vector<std::array<int, 4>> records;
  records.reserve(static_cast<std::size_t>(nf) * 3);
  for (int f = 0; f < nf; ++f) {
    if (!usable(f))
      continue;
    for (int k = 0; k < 3; ++k) {
      const int a = corner(f, k), b = corner(f, (k + 1) % 3);
      records.push_back({std::min(a, b), std::max(a, b), f, a < b ? 1 : 0});
    }
  }
  detail::sortEdgeRecords(records, nv);

  // Manifold edges only: link (f, g, same) where `same` says whether the two faces walk the edge
  // in the same direction, i.e. need opposite flip states.
  // At most three links per face (one per side): flat arrays, no per-face allocation.
  std::vector<std::array<int, 2>> links(static_cast<std::size_t>(nf) * 3);
  std::vector<unsigned char> num_links(nf, 0);
  for (std::size_t i = 0; i < records.size();) {
    std::size_t j = i;
    while (j < records.size() && records[j][0] == records[i][0] && records[j][1] == records[i][1])
      ++j;
    if (j - i == 2 && records[i][2] != records[i + 1][2]) {
      const int f = records[i][2], g = records[i + 1][2];
      const int same = records[i][3] == records[i + 1][3] ? 1 : 0;
      links[3 * f + num_links[f]++] = {g, same};
      links[3 * g + num_links[g]++] = {f, same};
    }
    i = j;
  }

  std::vector<int> flip(nf, 0), component(nf, -1);
  std::vector<int> members;
  std::deque<int> queue;
  std::size_t flipped = 0;
  int num_components = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (component[seed] >= 0 || !usable(seed))
      continue;
    const int id = num_components++;
    members.clear();
    component[seed] = id;
    queue.push_back(seed);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      members.push_back(f);
      for (int l = 0; l < num_links[f]; ++l) {
        const auto& link = links[3 * f + l];
        const int g = link[0];
        if (component[g] >= 0)
          continue;
        component[g] = id;
        flip[g] = flip[f] ^ link[1];
        queue.push_back(g);
      }
    }
    // Signed volume about the component's centroid (origin-independent for closed components,
    // and less sensitive to small holes than the volume about the origin).
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int f : members)
      centroid += mesh.faceCentroid(f);
    centroid /= static_cast<double>(members.size());
    double six_volume = 0.0;
    for (int f : members) {
      const Eigen::Vector3d a = mesh.vertices[mesh.faces[f][0]] - centroid;
      const Eigen::Vector3d b = mesh.vertices[mesh.faces[f][1]] - centroid;
      const Eigen::Vector3d c = mesh.vertices[mesh.faces[f][2]] - centroid;
      const double v = a.dot(b.cross(c));
      six_volume += flip[f] ? -v : v;
    }
    if (six_volume < 0.0)
      for (int f : members)
        flip[f] ^= 1;
    for (int f : members)
      if (flip[f]) {
        std::swap(mesh.faces[f][1], mesh.faces[f][2]);
        ++flipped;
      }
  }
  return flipped;
}

} // namespace segmat
