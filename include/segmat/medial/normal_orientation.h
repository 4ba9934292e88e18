/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <memory>

namespace segmat {

/** \brief Consistent outward orientation of unoriented point normals.
 *
 * Hoppe et al., "Surface reconstruction from unorganized points" (SIGGRAPH 1992, §3.3):
 * propagate an orientation over a minimum spanning tree of the symmetric k-NN graph, so that the
 * sign is carried across the flattest, closest neighbour pairs first. PCL has no such step
 * (NormalEstimation only flips towards a viewpoint).
 *
 *  - Edge weight: 1 − |n_i·n_j| (Hoppe) plus |n_i·d̂|·|n_j·d̂|, d̂ the unit vector from p_i to
 *    p_j. The second term is ours: it is ~0 between neighbours on one sheet and ~1 between the
 *    two sides of a plate thinner than the sampling, which plain Hoppe weights as free (|n_i·n_j|
 *    = 1) and would then orient alike. It can be switched off (setTangentPlaneTermFlag).
 *  - Kruskal with Boost's disjoint sets; edges sorted by (weight, i, j), so ties are explicit.
 *  - Per connected component the seed is the point with the largest x (lowest index on a tie);
 *    its normal is made to point +x, which is outward for any closed surface.
 *  - Global outward check per component (optional, on by default): with c the component's
 *    centroid, S = Σ (p−c)·n is 3·volume/density > 0 for outward normals of a closed surface
 *    (divergence theorem). When S < −0.1 Σ |(p−c)·n| the whole component is reversed. Open,
 *    flat components (S ≈ 0) keep the seed's decision.
 */
class NormalOrientation
{
public:
  using Ptr = std::shared_ptr<NormalOrientation>;
  using ConstPtr = std::shared_ptr<const NormalOrientation>;

  /** \brief Defaults: k = 10, tangent-plane term on, outward check on. */
  NormalOrientation();

  /** \brief Number of nearest neighbours of the propagation graph (> 0; others are ignored
   * with a warning).
   */
  void
  setKSearch(int k);

  /** \brief Number of nearest neighbours of the propagation graph. */
  int
  getKSearch() const
  {
    return k_;
  }

  /** \brief Add the tangent-plane term |n_i·d̂|·|n_j·d̂| to Hoppe's weight (default true). */
  void
  setTangentPlaneTermFlag(bool flag)
  {
    tangent_plane_term_ = flag;
  }

  /** \brief Whether the tangent-plane term is added to Hoppe's weight. */
  bool
  getTangentPlaneTermFlag() const
  {
    return tangent_plane_term_;
  }

  /** \brief Relate neighbours by the reflection in their bisector plane (default false).
   *
   * Hoppe's relation calls n_i and n_j consistent when n_i·n_j > 0. The mirror relation compares
   * n_i with R n_j, R = I − 2 d̂d̂ᵀ the reflection in the plane halfway between p_i and p_j
   * (weight 1 − |n_i·R n_j|, n_j flipped when n_i·R n_j < 0). Both agree between neighbours on
   * one sheet (d̂ ⊥ n); the mirror relation is also exact on spheres, symmetric creases and
   * across a plate thinner than the neighbourhood, whose two sides Hoppe's relation orients
   * alike. The tangent-plane term is not added (it only patches that case). */
  void
  setMirrorRelationFlag(bool flag)
  {
    mirror_relation_ = flag;
  }

  /** \brief Whether neighbours are related by the reflection in their bisector plane. */
  bool
  getMirrorRelationFlag() const
  {
    return mirror_relation_;
  }

  /** \brief Reverse a component whose normals point inward on the whole (default true). */
  void
  setOutwardCheckFlag(bool flag)
  {
    outward_check_ = flag;
  }

  /** \brief Whether components pointing inward on the whole are reversed. */
  bool
  getOutwardCheckFlag() const
  {
    return outward_check_;
  }

  /** \brief Orient the normals of \a cloud in place (only their signs change).
   * \param[in,out] cloud points with unit normals; every coordinate and normal must be finite
   *            and every normal non-zero
   * \return false (with PCL_ERROR, cloud unchanged) on an empty cloud or an invalid
   *         point/normal
   */
  bool
  orient(pcl::PointCloud<pcl::PointNormal>& cloud);

  /** \brief Connected components of the k-NN graph in the last orient() call. */
  std::size_t
  getNumberOfComponents() const
  {
    return components_;
  }

  /** \brief Normals reversed by the last orient() call. */
  std::size_t
  getNumberOfReversed() const
  {
    return reversed_;
  }

private:
  int k_;
  bool tangent_plane_term_;
  bool outward_check_;
  bool mirror_relation_ = false;
  std::size_t components_ = 0;
  std::size_t reversed_ = 0;
};

} // namespace segmat
