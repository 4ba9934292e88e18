/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: feature-preserving mesh denoising. Bilateral filtering of face normals
// (Zheng, Fu, Au, Tai, "Bilateral Normal Filtering for Mesh Denoising", IEEE TVCG 2011) and
// vertex positions updated to fit the filtered normals (Sun, Rosin, Martin, Langbein, "Fast and
// Effective Feature-Preserving Mesh Denoising", IEEE TVCG 2007).

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief What bilateralNormalFilter() did. */
struct NormalFiltering
{
  int normal_iterations = 0;  ///< normal filtering iterations run
  double spatial_sigma = 0.0; ///< σ_s: mean distance between the centroids of adjacent faces
};

/** \brief Moves \a vertices so that the faces follow their bilaterally filtered normals.
 *
 * Each iteration replaces a face's normal by the average of its edge-and-vertex neighbours'
 * normals, weighted by area, by a Gaussian of the centroid distance (σ_s = mean distance between
 * adjacent centroids) and by a Gaussian of the normal difference (σ_r = \a range_sigma, in
 * units of |n_i − n_j|). Normals across a sharp crease differ by far more than σ_r and stay
 * apart, so flat faces of CAD shapes become flat again with their creases, while smooth
 * surfaces are smoothed. Filtering stops once an iteration turns the normals by less than
 * \a still_degrees on average (at most \a max_iterations). Then \a vertex_iterations steps move
 * every vertex onto the planes of its faces (filtered normal through the face centroid).
 * Degenerate faces are skipped; vertices of no face stay where they are.
 */
NormalFiltering
bilateralNormalFilter(std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& faces, double range_sigma,
                      int max_iterations, double still_degrees, int vertex_iterations, int threads);

} // namespace detail
} // namespace segmat
