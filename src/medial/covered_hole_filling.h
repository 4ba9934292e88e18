/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/medial: closes the holes of a medial mesh that its own balls cover.

#include <segmat/geometry/medial_mesh.h>

namespace segmat {
namespace detail {

/** \brief Fills every hole of a medial sheet that the balls on its rim cover, and returns how
 * many it filled.
 *
 * A hole in a medial sheet stands for a hole through the shape's wall: the sheet of a plate
 * with a hole of diameter d ends where its balls (radius t/2, the half-thickness) touch the
 * hole's side, so the rim balls leave a disc of diameter d uncovered. A hole that the rim balls
 * cover therefore has no hole of the shape behind it. Noise makes such holes: a Voronoi vertex
 * that the inside test rejects takes the sheet's triangles around it along, and Q-MAT keeps
 * every hole (it preserves topology), so a noisy wall's structured MAT comes out as a net of
 * lines around holes instead of a sheet.
 *
 * A hole is a loop of boundary edges (edges of exactly one triangle) through vertices that have
 * exactly two boundary edges, at most \a max_loop edges long, whose triangles lie outside the
 * loop (the loop of a small island has its triangles inside). It is filled with a fan from
 * its first vertex when every point of the fan (sampled on a barycentric grid) lies in a ball of
 * the rim and no fan diagonal is already an edge.
 */
int
fillCoveredHoles(MedialMesh& mat, int max_loop = 128);

} // namespace detail
} // namespace segmat
