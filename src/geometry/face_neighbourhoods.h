/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: which faces of a triangle mesh touch which, built once for the steps of mesh
// denoising that read them (the bilateral normal filters and the tangential relaxation).

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace segmat {
namespace detail {

/** \brief Whether face \a f has three distinct vertices below \a vertex_count. */
bool
validFace(const Eigen::Vector3i& f, std::size_t vertex_count);

/** \brief The faces around each face, built once for every step that reads them
 * on the same connectivity. */
struct FaceNeighbourhoods
{
  /// Builds the lists of \a faces over \a vertex_count vertices.
  FaceNeighbourhoods(const std::vector<Eigen::Vector3i>& faces, std::size_t vertex_count);

  std::vector<char> valid; ///< per face: three distinct vertices in range
  /// Faces of vertex v: vertex_faces[vertex_first[v]] .. [vertex_first[v + 1] − 1], ascending.
  std::vector<std::size_t> vertex_first;
  std::vector<int> vertex_faces;
  /// Every other face sharing a vertex with face f: neighbours[first[f]] .. [first[f + 1] − 1],
  /// ascending. mirror[a] is the entry of the same pair in the other face's list, and
  /// shares_edge[a] whether the pair shares two vertices.
  std::vector<std::size_t> first;
  std::vector<int> neighbours;
  std::vector<std::size_t> mirror;
  std::vector<char> shares_edge;
};

} // namespace detail
} // namespace segmat
