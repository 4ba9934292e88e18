/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace segmat {

/** \brief Exact unsigned distance from points to a triangle mesh: a bounding-box hierarchy over
 * the faces, searched branch-and-bound with the exact point–triangle distance (Ericson,
 * "Real-Time Collision Detection", §5.1.5). Used to measure how far a medial envelope lies from
 * the surface it approximates. Degenerate faces count as segments or points.
 */
class MeshDistance
{
public:
  using Ptr = std::shared_ptr<MeshDistance>;
  using ConstPtr = std::shared_ptr<const MeshDistance>;

  /** \brief An empty hierarchy: every distance is +infinity. */
  MeshDistance() = default;

  /** \brief Builds the hierarchy over the faces of \a mesh (copied; faces with an index out of
   * range or a non-finite corner are skipped). O(F log F). */
  explicit MeshDistance(const TriangleMesh& mesh);

  /** \brief Distance from \a q to the nearest point of the mesh (+infinity when empty).
   * \param[in] q query point
   * \param[out] closest when not null, the nearest mesh point */
  double
  distance(const Eigen::Vector3d& q, Eigen::Vector3d* closest = nullptr) const;

  /** \brief Number of faces in the hierarchy. */
  std::size_t size() const { return triangles_.size(); }

private:
  struct Node
  {
    Eigen::Vector3d lo, hi;
    int first = 0, last = 0; ///< face range [first, last) when a leaf
    int left = -1, right = -1;
  };

  int
  build(int first, int last, std::vector<Eigen::Vector3d>& centroids);

  std::vector<Eigen::Matrix3d> triangles_; ///< corners as columns, in hierarchy order
  std::vector<Node> nodes_;
};

/** \brief The point of triangle (a, b, c) nearest to \a p (exact; works for degenerate
 * triangles too). */
Eigen::Vector3d
closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       const Eigen::Vector3d& c);

} // namespace segmat
