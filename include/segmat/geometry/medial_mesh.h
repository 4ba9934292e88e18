/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace segmat {

/** \brief A medial mesh (Q-MAT, Li et al. 2015; SEG-MAT, Lin et al. 2022 §3): spheres joined by
 * edges (medial cones) and triangles (medial slabs).
 *
 * Identity is by index, never by coordinates (the reference code merged spheres with equal
 * centres). The constructor normalises the complex once and derives the
 * incidence every later stage needs:
 *  - triangles with a repeated index and edges with equal ends are dropped, duplicates removed;
 *  - every side of every triangle is an edge (added when the input lacked it);
 *  - edges are stored with the smaller index first, in first-seen order;
 *  - vertex → edges and vertex → triangles lists, edge → triangle counts.
 * An edge that is a side of no triangle is a "pure" edge: a cone of its own in the MAT graph.
 */
class MedialMesh
{
public:
  using Ptr = std::shared_ptr<MedialMesh>;
  using ConstPtr = std::shared_ptr<const MedialMesh>;

  MedialMesh() = default;

  /** \brief Build from raw arrays.
   * \throws segmat::Error when an index is out of range, a radius is negative or not finite, or
   *         the arrays' sizes disagree.
   */
  MedialMesh(std::vector<Eigen::Vector3d> centers, std::vector<double> radii,
             const std::vector<Eigen::Vector2i>& edges,
             const std::vector<Eigen::Vector3i>& triangles);

  std::size_t numVertices() const { return centers_.size(); }
  std::size_t numEdges() const { return edges_.size(); }
  std::size_t numTriangles() const { return triangles_.size(); }
  bool empty() const { return centers_.empty(); }

  /** \brief Sphere centres. */
  const std::vector<Eigen::Vector3d>& centers() const { return centers_; }
  /** \brief Sphere radii (finite, >= 0). */
  const std::vector<double>& radii() const { return radii_; }
  /** \brief Edges, smaller index first. */
  const std::vector<Eigen::Vector2i>& edges() const { return edges_; }
  /** \brief Triangles as given (winding carries no meaning: Q-MAT writes ascending indices). */
  const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }

  /** \brief Sphere v as (x, y, z, r). */
  Eigen::Vector4d
  sphere(int v) const
  {
    return {centers_[v].x(), centers_[v].y(), centers_[v].z(), radii_[v]};
  }

  /** \brief Edges incident to vertex v (ascending edge index). */
  const std::vector<int>& vertexEdges(int v) const { return vertex_edges_[v]; }
  /** \brief Triangles incident to vertex v (ascending triangle index). */
  const std::vector<int>& vertexTriangles(int v) const { return vertex_triangles_[v]; }
  /** \brief Number of triangles having edge e as a side (0 for a pure edge, >= 3: non-manifold). */
  int edgeTriangleCount(int e) const { return edge_triangle_count_[e]; }
  /** \brief True when edge e is a side of no triangle (a medial cone of its own). */
  bool isPureEdge(int e) const { return edge_triangle_count_[e] == 0; }
  /** \brief Index of edge (a, b) in either order, or -1. */
  int findEdge(int a, int b) const;

  /** \brief Diagonal of the bounding box of the sphere centres (SEG-MAT's normaliser). */
  double centerBoundingBoxDiagonal() const;
  /** \brief Largest radius (0 when empty). */
  double maxRadius() const;
  /** \brief Number of connected components (spheres joined by edges; an isolated sphere is one). */
  std::size_t numConnectedComponents() const;

private:
  std::vector<Eigen::Vector3d> centers_;
  std::vector<double> radii_;
  std::vector<Eigen::Vector2i> edges_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<std::vector<int>> vertex_edges_;
  std::vector<std::vector<int>> vertex_triangles_;
  std::vector<int> edge_triangle_count_;
};

} // namespace segmat
