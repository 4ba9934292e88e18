/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/medial_mesh.h>

namespace segmat {
namespace test {

/** \brief Medial meshes built in code, with a known topology, for simplification tests. */

/** \brief Flat sheet: an (n+1)×(n+1) grid over [0, size]² in z = 0, each cell split into two
 * triangles wound counter-clockwise seen from +z, every sphere of radius \a radius. Vertex
 * (i, j) has index j·(n+1) + i. */
MedialMesh
planarSheet(int n, double size, double radius);

/** \brief Flat annulus in z = 0 around the origin: \a rings + 1 circles of \a segments vertices
 * from radius \a inner to \a outer, triangulated, constant sphere radius. One hole (b1 = 1). */
MedialMesh
annulusSheet(int segments, int rings, double inner, double outer, double radius);

/** \brief A closed loop of \a n pure edges on a circle of radius \a loop_radius (the medial axis
 * of a solid torus), spheres of radius \a radius. One tunnel (b1 = 1), no triangle. */
MedialMesh
pureEdgeLoop(int n, double loop_radius, double radius);

/** \brief Mod-2 Betti numbers of a medial mesh seen as a simplicial 2-complex. */
struct Betti
{
  int b0 = 0; ///< connected components (isolated spheres included)
  int b1 = 0; ///< independent loops: tunnels and holes
  int b2 = 0; ///< enclosed cavities
};

/** \brief Betti numbers over GF(2) by Gaussian elimination of the boundary matrices. */
Betti
bettiNumbers(const MedialMesh& mat);

} // namespace test
} // namespace segmat
