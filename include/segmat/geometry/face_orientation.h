/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <vector>

namespace segmat {

/** \brief Per-face signs (+1 keep, −1 flip) that orient a triangle mesh consistently and outward.
 *
 * Real meshes are not always consistently wound, and the graph-cut smoothness of SEG-MAT tells
 * concave from convex edges with the face normals, assuming outward orientation
 * (the authors' `smoothFn`). Faces are propagated breadth-first over manifold edges (edges with
 * exactly two faces), in face order: a neighbour whose shared edge runs the same way as in the
 * current face is flipped. Each connected component is then turned so that its signed volume,
 * taken about the component's centroid, is >= 0 (faces with a non-finite corner left out).
 * Non-manifold edges do not propagate (their
 * sheets are oriented on their own); degenerate faces keep +1. A non-orientable component
 * (Möbius-like) keeps the first assignment reached.
 * \param[in] mesh the mesh
 * \param[in] adjacency mesh.faceAdjacency() (passed in because callers usually have it already)
 * \return one sign per face
 */
std::vector<int>
computeOutwardFaceSigns(const TriangleMesh& mesh, const std::vector<FaceAdjacency>& adjacency);

} // namespace segmat
