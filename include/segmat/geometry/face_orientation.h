/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <cstddef>
#include <vector>

namespace segmat {

/** \brief Makes the faces of each connected component consistently oriented, and each
 * component outward-facing.
 *
 * Users' meshes often mix face orientations, and inside/outside tests built on the generalised
 * winding number (Jacobson et al. 2013) need one. Per connected component (faces joined across
 * edges that have exactly two faces; vertices closer than `weld_tolerance` count as one, so
 * unwelded "triangle soups" still connect), a breadth-first walk from the lowest-indexed face
 * flips neighbours so every shared edge is traversed in opposite directions. Then a component
 * whose signed volume (about its own centroid) is negative is flipped as a whole.
 *
 * Limits: a non-orientable component (Möbius-like) keeps the first orientation the walk gives;
 * edges with three or more faces do not propagate orientation; an inner shell that bounds a
 * cavity is turned outward too (so the cavity counts as inside); the orientation of an open
 * sheet with no volume is left as the walk gives it.
 * \param[in,out] mesh the mesh; faces are flipped by swapping their 2nd and 3rd corners
 * \param[in] weld_tolerance distance under which vertices are treated as one (absolute units)
 * \return the number of faces flipped
 */
std::size_t
orientFacesOutward(TriangleMesh& mesh, double weld_tolerance = 0.0);

/** \brief As above, with the vertex welding given: `representative[v]` is the vertex that v
 * counts as (weldPoints()); its size must equal the vertex count.
 */
std::size_t
orientFacesOutward(TriangleMesh& mesh, const std::vector<int>& representative);

} // namespace segmat
