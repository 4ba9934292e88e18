/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: the frame the front classes segment in, so that where a shape lies, how big
// it is and the order its file lists things in cannot change its parts.

#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief p ↦ (p − centre) × scale: centred on the bounding box's centre, scaled so that the
 * diagonal lies in [1/√2, √2); optionally then turned onto the principal axes:
 * p ↦ rotation · ((p − centre) × scale − shift).
 *
 * The scale is a power of two, so multiplying by it is exact: an input scaled by 2^k maps to
 * the very same numbers (the centre scales exactly too, and rounding commutes with powers of two),
 * and every later step sees identical input, hence identical labels. Any other factor would round
 * differently at each scale. Absolute tolerances inside the pipeline then act at one size.
 */
struct NormalizedFrame
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0; ///< a power of two
  bool rotated = false;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< rows: the principal axes
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();        ///< the scaled points' centroid

  /** \brief The frame of the finite points of \a points (identity when none, or no extent).
   *
   * With \a principal_axes, the points are also turned so that their principal axes (of the
   * vertices' covariance, largest variance first; each of the first two pointing where the
   * third moment is positive, the third their cross product) become x, y and z, centred on their
   * centroid, and the diagonal of their box in that orientation is brought into [1/√2, √2). A
   * rotated input then gives the same frame coordinates up to rounding, so every axis-aligned
   * step after it (sampling, jitter, the Delaunay grid, trees) acts the same. Shapes whose
   * principal variances (nearly) coincide, or that are symmetric about a principal plane, have
   * no such unique orientation; the sums are taken in sorted order, so the frame does not
   * depend on the order of the points.
   */
  static NormalizedFrame
  of(const std::vector<Eigen::Vector3d>& points, bool principal_axes = false);

  Eigen::Vector3d
  toFrame(const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d q = (p - centre) * scale;
    return rotated ? Eigen::Vector3d(rotation * (q - shift)) : q;
  }

  Eigen::Vector3d
  fromFrame(const Eigen::Vector3d& q) const
  {
    const Eigen::Vector3d p = rotated ? Eigen::Vector3d(rotation.transpose() * q + shift) : q;
    return p / scale + centre;
  }

  /** \brief The mesh moved into the frame, vertex for vertex, faces as they are (the caller
   * then puts it into position order: sortMeshByPosition()). */
  TriangleMesh
  toFrame(const TriangleMesh& mesh) const;

  /** \brief Centres and radii mapped into the frame (toFrame) or back (fromFrame). */
  MedialMesh
  toFrame(const MedialMesh& mat) const;
  MedialMesh
  fromFrame(const MedialMesh& mat) const;
};

} // namespace detail
} // namespace segmat
