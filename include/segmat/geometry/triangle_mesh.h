/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace segmat {

/** \brief Two faces that meet across the mesh edge (v0, v1). */
struct FaceAdjacency
{
  int face_a = -1; ///< first face (the smaller index)
  int face_b = -1; ///< second face
  int v0 = -1;     ///< shared edge, smaller vertex index
  int v1 = -1;     ///< shared edge, larger vertex index
};

/** \brief A triangle mesh as the segmentation kernels see it: plain vertex and face arrays.
 *
 * The input side of segmat (libigl-style V/F under the PCL façade). Faces keep the order of the
 * file they came from, so per-face labels line up with PSB `.seg` files. Nothing here assumes a
 * closed, manifold or consistently oriented mesh: degenerate faces have a zero normal and zero
 * area, border edges simply have no adjacency, and an edge shared by three or more faces links
 * every pair of them.
 */
class TriangleMesh
{
public:
  using Ptr = std::shared_ptr<TriangleMesh>;
  using ConstPtr = std::shared_ptr<const TriangleMesh>;

  TriangleMesh() = default;
  TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Eigen::Vector3i> faces)
  : vertices(std::move(vertices)), faces(std::move(faces))
  {}

  std::vector<Eigen::Vector3d> vertices; ///< vertex positions
  std::vector<Eigen::Vector3i> faces;    ///< vertex indices per triangle, counter-clockwise = outward

  /** \brief Number of faces. */
  std::size_t
  numFaces() const
  {
    return faces.size();
  }

  /** \brief Number of vertices. */
  std::size_t
  numVertices() const
  {
    return vertices.size();
  }

  /** \brief True when there are no faces. */
  bool
  empty() const
  {
    return faces.empty();
  }

  /** \brief Unit normal of face f by the right-hand rule; zero for a degenerate face. */
  Eigen::Vector3d
  faceNormal(int f) const;

  /** \brief Area of face f (half the cross product's length). */
  double
  faceArea(int f) const;

  /** \brief Centroid (mean of the three corners) of face f. */
  Eigen::Vector3d
  faceCentroid(int f) const;

  /** \brief Unit normals of all faces (zero for degenerate faces). */
  std::vector<Eigen::Vector3d>
  faceNormals() const;

  /** \brief Length of the diagonal of the vertices' axis-aligned bounding box (0 when empty). */
  double
  boundingBoxDiagonal() const;

  /** \brief Face pairs across every edge, sorted by (face_a, face_b).
   *
   * An edge with one face gives nothing (border); an edge with k >= 2 faces gives all k(k-1)/2
   * pairs. Faces with a repeated vertex index contribute no edges.
   */
  std::vector<FaceAdjacency>
  faceAdjacency() const;
};

} // namespace segmat
