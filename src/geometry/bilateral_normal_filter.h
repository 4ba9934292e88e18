/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: feature-preserving mesh denoising. Bilateral filtering of face normals
// (Zheng, Fu, Au, Tai, "Bilateral Normal Filtering for Mesh Denoising", IEEE TVCG 2011) and
// vertex positions updated to fit the filtered normals (Sun, Rosin, Martin, Langbein, "Fast and
// Effective Feature-Preserving Mesh Denoising", IEEE TVCG 2007).

#include "face_neighbourhoods.h"

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Settings of bilateralNormalFilter(). */
struct NormalFilterSettings
{
  /// σ_r, in units of |n_i − n_j|: 0.35 ≈ 20°, the value of Zheng et al.
  double range_sigma = 0.35;
  /// σ_r = max(range_sigma, median |n_i − n_j| over the pairs of faces sharing an edge),
  /// re-estimated from the filtered normals before every iteration. Vertex noise tilts adjacent
  /// faces apart by about that much; a fixed σ_r below it would keep the noise as if it were
  /// creases, and one kept at the noise's level after the noise is gone rounds off every crease
  /// of about that turn (the steps of a stepped shaft, for one).
  bool range_from_normals = false;
  int max_iterations = 20;    ///< at most this many normal filtering iterations
  double still_degrees = 0.5; ///< stop once an iteration turns the normals less, on average
  int vertex_iterations = 10; ///< steps moving the vertices onto their faces' planes
};

/** \brief What bilateralNormalFilter() did. */
struct NormalFiltering
{
  int normal_iterations = 0;  ///< normal filtering iterations run
  double spatial_sigma = 0.0; ///< σ_s: mean distance between the centroids of adjacent faces
  double range_sigma = 0.0;   ///< σ_r of the first iteration
};

/** \brief Moves \a vertices so that the faces follow their bilaterally filtered normals.
 *
 * Each iteration replaces a face's normal by the average of its edge-and-vertex neighbours'
 * normals, weighted by area, by a Gaussian of the centroid distance (σ_s = mean distance between
 * adjacent centroids) and by a Gaussian of the normal difference (σ_r, NormalFilterSettings).
 * Normals across a crease much sharper than σ_r stay apart, so flat faces of CAD shapes become
 * flat again with their creases, while smooth surfaces are smoothed. Filtering stops once an
 * iteration turns the normals by less than \a still_degrees on average (at most
 * \a max_iterations). Then \a vertex_iterations steps move every vertex onto the planes of its
 * faces (filtered normal through the face centroid). Degenerate faces are skipped; vertices of
 * no face stay where they are.
 */
NormalFiltering
bilateralNormalFilter(std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& faces,
                      const NormalFilterSettings& settings, int threads);

/** \brief bilateralNormalFilter() with the neighbourhoods of \a faces built beforehand. */
NormalFiltering
bilateralNormalFilter(std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& faces, const FaceNeighbourhoods& around,
                      const NormalFilterSettings& settings, int threads);

} // namespace detail
} // namespace segmat
