/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <cstddef>

namespace segmat {

/** \brief Edges of a triangle mesh by the number of faces they border, with vertices at equal
 * positions (within 1e-9 x the bounding-box diagonal) taken as one, as the inside test does.
 * A closed manifold surface has only two-face edges; SEG-MAT's medial axis assumes one.
 */
struct MeshEdgeCounts
{
  std::size_t edges = 0;        ///< distinct edges of non-degenerate faces
  std::size_t boundary = 0;     ///< edges of one face: the surface is open there
  std::size_t non_manifold = 0; ///< edges of three or more faces

  /** \brief True when every edge borders exactly two faces. */
  bool
  closedManifold() const
  {
    return boundary == 0 && non_manifold == 0;
  }
};

/** \brief Counts the edges of \a mesh by kind (faces with an index out of range or a repeated
 * vertex are skipped). */
MeshEdgeCounts
countMeshEdges(const TriangleMesh& mesh);

} // namespace segmat
