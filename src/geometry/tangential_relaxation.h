/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: evens out the spacing of a denoised mesh's vertices without changing its
// shape (the tangential half of vertex noise).

#include "face_neighbourhoods.h"

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Moves each vertex towards the mean of its edge neighbours, within its surface only.
 *
 * Vertex noise moves vertices along the surface as well as across it. Denoising removes the
 * part across it; the part along it is left, and it makes some edges much longer than the
 * original ones, which the surface sampler then fills with extra samples. Each of
 * \a iterations Jacobi steps moves a vertex by half of the offset to its neighbours' mean,
 * projected onto the directions in which its faces are flat: the eigenvectors of the
 * area-weighted normal tensor Σ a_f n_f n_fᵀ whose eigenvalue is below 3 % of the largest (a
 * smooth vertex moves in its tangent plane, a crease vertex along its crease, a corner not at
 * all). A vertex never ends farther than \a max_move from where it started: tangential noise is
 * of the size of the noise, and a larger move would only redistribute a triangulation that was
 * uneven by design. Vertices of no face, and vertices on a boundary or non-manifold edge, stay
 * where they are.
 */
void
relaxTangentially(std::vector<Eigen::Vector3d>& vertices,
                  const std::vector<Eigen::Vector3i>& faces, double max_move, int iterations,
                  int threads);

/** \brief relaxTangentially() with the faces around each vertex built beforehand. */
void
relaxTangentially(std::vector<Eigen::Vector3d>& vertices, const std::vector<Eigen::Vector3i>& faces,
                  const FaceNeighbourhoods& around, double max_move, int iterations, int threads);

} // namespace detail
} // namespace segmat
