/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/sphere_tree.h>

#include <Eigen/Core>

#include <limits>
#include <memory>
#include <vector>

namespace segmat {

/** \brief "Do two points see each other inside the shape?" for a shape known only by medial
 * balls: the segment between them must stay inside the union of the balls.
 *
 * SEG-MAT merges two parts only when enough segments between their balls cross no surface
 * (SEG-MAT §4.4; the mesh path tests the segments against the triangles). A cloud has
 * no triangles, but its medial balls cover its interior, so "crosses no surface" becomes "never
 * leaves the union of the balls". The test walks the segment: at a point q, with
 * d = min_i (|q − c_i| − ρ·r_i) (segmat::SphereTree), d > 0 means the segment has left the
 * shape; d ≤ 0 means q is inside the deepest ball i, and since a ball is convex the segment
 * stays inside it until it crosses that ball's sphere, so the walk jumps to half a minimal step
 * before that crossing (at least −d and at least the minimal step, 1e-3 of the balls' extent,
 * so it cannot stall on a boundary; gaps shorter than a minimal step may be bridged).
 * ρ > 1 (default 1.1) bridges the small gaps between neighbouring balls of a sampled medial
 * axis; a margin m adds a length to every radius (r·ρ + m), for radii known only up to the
 * noise of the samples they came from.
 */
class BallUnionVisibility
{
public:
  /** \brief Build over the balls (\a centers, \a radii), each radius r taken as
   * r · \a inflation + \a margin. */
  BallUnionVisibility(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii,
                      double inflation = 1.1, double margin = 0.0);

  /** \brief True when the segment [a, b] stays inside the (inflated) union of the balls. */
  bool
  operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

private:
  std::shared_ptr<const SphereTree> tree_; ///< shared: the functor is copied into std::function
  double min_step_ = 0.0;
};

} // namespace segmat
