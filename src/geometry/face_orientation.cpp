/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/face_orientation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace segmat {
namespace {

// +1 when face t walks v0→v1, −1 when it walks v1→v0, 0 when the edge is not a side of t.
int
edgeDirection(const Eigen::Vector3i& t, int v0, int v1)
{
  for (int k = 0; k < 3; ++k) {
    const int a = t[k], b = t[(k + 1) % 3];
    if (a == v0 && b == v1)
      return 1;
    if (a == v1 && b == v0)
      return -1;
  }
  return 0;
}

} // namespace

std::vector<int>
computeOutwardFaceSigns(const TriangleMesh& mesh, const std::vector<FaceAdjacency>& adjacency)
{
  const int num_faces = static_cast<int>(mesh.numFaces());
  std::vector<int> sign(num_faces, 1);
  if (num_faces == 0)
    return sign;

  // Manifold edges are those that occur in exactly one face pair.
  std::vector<int> order(adjacency.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return std::tie(adjacency[x].v0, adjacency[x].v1, x) <
           std::tie(adjacency[y].v0, adjacency[y].v1, y);
  });
  std::vector<std::vector<int>> links(num_faces); // adjacency record indices per face
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && adjacency[order[j]].v0 == adjacency[order[i]].v0 &&
           adjacency[order[j]].v1 == adjacency[order[i]].v1)
      ++j;
    if (j == i + 1) {
      const FaceAdjacency& p = adjacency[order[i]];
      links[p.face_a].push_back(order[i]);
      links[p.face_b].push_back(order[i]);
    }
    i = j;
  }
  for (auto& l : links)
    std::sort(l.begin(), l.end()); // deterministic visiting order

  std::vector<int> component(num_faces, -1);
  std::vector<int> queue;
  queue.reserve(num_faces);
  for (int seed = 0; seed < num_faces; ++seed) {
    if (component[seed] >= 0)
      continue;
    queue.clear();
    queue.push_back(seed);
    component[seed] = seed;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int k : links[f]) {
        const FaceAdjacency& p = adjacency[k];
        const int g = p.face_a == f ? p.face_b : p.face_a;
        if (component[g] >= 0)
          continue;
        // Consistent neighbours walk the shared edge in opposite directions.
        const int df = edgeDirection(mesh.faces[f], p.v0, p.v1);
        const int dg = edgeDirection(mesh.faces[g], p.v0, p.v1);
        sign[g] = df * dg > 0 ? -sign[f] : sign[f];
        component[g] = seed;
        queue.push_back(g);
      }
    }
    // Outward: non-negative signed volume about the component's centroid (translation-free for
    // closed components, and a sensible choice for open ones).
    // Faces with a non-finite corner are left out of both sums.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    int finite = 0;
    for (int f : queue) {
      const Eigen::Vector3d c = mesh.faceCentroid(f);
      if (c.allFinite()) {
        centre += c;
        ++finite;
      }
    }
    centre /= std::max(finite, 1);
    double volume = 0.0;
    for (int f : queue) {
      const Eigen::Vector3i& t = mesh.faces[f];
      const Eigen::Vector3d a = mesh.vertices[t[0]] - centre, b = mesh.vertices[t[1]] - centre,
                            c = mesh.vertices[t[2]] - centre;
      const double v = a.dot(b.cross(c));
      if (std::isfinite(v))
        volume += sign[f] * v;
    }
    if (volume < 0.0)
      for (int f : queue)
        sign[f] = -sign[f];
  }
  return sign;
}

} // namespace segmat
