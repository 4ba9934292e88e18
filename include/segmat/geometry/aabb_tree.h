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

/** \brief A static bounding-volume hierarchy of axis-aligned boxes over a triangle mesh, for
 * segment–surface intersection tests (the visibility test of SEG-MAT's merging, which used
 * CGAL's AABB tree in the authors' code).
 *
 * Built once (median split on the longest axis, small leaves); queries are const and may run
 * from several threads. Degenerate (zero-area) faces are left out.
 */
class AabbTree
{
public:
  using Ptr = std::shared_ptr<AabbTree>;
  using ConstPtr = std::shared_ptr<const AabbTree>;

  AabbTree() = default;
  /** \brief Build over the faces of \a mesh (the mesh is copied; it need not outlive the tree). */
  explicit AabbTree(const TriangleMesh& mesh) { build(mesh); }

  /** \brief (Re)build over the faces of \a mesh. */
  void
  build(const TriangleMesh& mesh);

  /** \brief True when the closed segment [a, b] meets some triangle (Möller–Trumbore, edges and
   * end points included). A degenerate segment (a == b) meets nothing; a segment lying in a
   * triangle's plane is not counted as meeting it.
   */
  bool
  segmentIntersects(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

  /** \brief Number of triangles in the tree (non-degenerate faces). */
  std::size_t
  numTriangles() const
  {
    return triangles_.size();
  }

  /** \brief True when the tree holds no triangle. */
  bool
  empty() const
  {
    return triangles_.empty();
  }

private:
  struct Triangle
  {
    Eigen::Vector3d v0, e1, e2; // corner and the two edges from it
  };
  struct Node
  {
    Eigen::Vector3d lo, hi;
    int first = 0; // leaf: first triangle; inner: index of the right child (left is next)
    int count = 0; // leaf: number of triangles; inner: 0
  };

  int
  buildNode(std::vector<int>& ids, std::vector<Eigen::Vector3d>& centroids, int begin, int end);

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
};

} // namespace segmat
