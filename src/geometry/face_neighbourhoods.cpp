/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "face_neighbourhoods.h"

#include <algorithm>
#include <limits>

namespace segmat {
namespace detail {

bool
validFace(const Eigen::Vector3i& f, std::size_t vertex_count)
{
  for (int c = 0; c < 3; ++c)
    if (f[c] < 0 || std::size_t(f[c]) >= vertex_count)
      return false;
  return f[0] != f[1] && f[1] != f[2] && f[0] != f[2];
}

FaceNeighbourhoods::FaceNeighbourhoods(const std::vector<Eigen::Vector3i>& faces,
                                       std::size_t vertex_count)
{
  const std::size_t nf = faces.size();
  valid.assign(nf, 0);
  vertex_first.assign(vertex_count + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    valid[f] = validFace(faces[f], vertex_count);
    if (valid[f])
      for (int c = 0; c < 3; ++c)
        ++vertex_first[faces[f][c] + 1];
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    vertex_first[v + 1] += vertex_first[v];
  vertex_faces.resize(vertex_first[vertex_count]);
  std::vector<std::size_t> fill(vertex_first.begin(), vertex_first.end() - 1);
  for (std::size_t f = 0; f < nf; ++f)
    if (valid[f])
      for (int c = 0; c < 3; ++c)
        vertex_faces[fill[faces[f][c]]++] = int(f);
  first.assign(nf + 1, 0);
  neighbours.reserve(12 * nf);
  shares_edge.reserve(12 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    first[f] = neighbours.size();
    if (!valid[f])
      continue;
    // Merge of the three corners' ascending face lists, without repeats and without f.
    std::size_t at[3], end[3];
    for (int c = 0; c < 3; ++c) {
      at[c] = vertex_first[faces[f][c]];
      end[c] = vertex_first[faces[f][c] + 1];
    }
    for (;;) {
      int next = std::numeric_limits<int>::max();
      for (int c = 0; c < 3; ++c)
        if (at[c] < end[c])
          next = std::min(next, vertex_faces[at[c]]);
      if (next == std::numeric_limits<int>::max())
        break;
      int shared = 0; // corners of f that face `next` has
      for (int c = 0; c < 3; ++c)
        if (at[c] < end[c] && vertex_faces[at[c]] == next) {
          ++at[c];
          ++shared;
        }
      if (next != int(f)) {
        neighbours.push_back(next);
        shares_edge.push_back(shared == 2);
      }
    }
  }
  first[nf] = neighbours.size();
  // The lists are symmetric and ascending: visiting the faces in ascending order, the k-th
  // visit to j's list comes from j's k-th neighbour.
  mirror.resize(neighbours.size());
  std::vector<std::size_t> visits(nf, 0);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t a = first[f]; a < first[f + 1]; ++a) {
      const int j = neighbours[a];
      mirror[a] = first[j] + visits[j]++;
    }
}

} // namespace detail
} // namespace segmat
