/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>

#include <string>

namespace segmat {

/** \brief Whether a given medial mesh plausibly belongs to a surface mesh.
 *
 * SEG-MAT reads the base and structured MATs from files; a file made for another mesh, or one
 * absurd sphere, silently gives wrong parts. A medial sphere of a closed surface is centred
 * inside it and touches it, so its radius is at most the surface's size. The checks, in units of
 * the mesh's bounding-box diagonal D:
 *  - every centre and radius finite, every radius >= 0;
 *  - every radius <= D;
 *  - every centre inside the mesh's bounding box grown by `box_margin` x D on each side;
 *  - at most `outside_fraction` of the centres outside the surface (winding number <= 0.5) and
 *    farther than `surface_margin` x D from it (simplified MATs put a few centres just outside).
 */
struct MedialMeshFit
{
  double box_margin = 0.1;        ///< growth of the bounding box, fraction of D
  double surface_margin = 0.02;   ///< "near the surface", fraction of D
  double outside_fraction = 0.05; ///< centres allowed away from the surface's inside

  /** \brief Checks \a mat against \a mesh.
   * \param[in] mat the medial mesh (spheres) to check
   * \param[in] mesh the surface it should belong to
   * \param[out] reason when false is returned: what does not fit, naming a sphere (0-based
   *             index) where one is at fault
   * \return true when \a mat passes every check (an empty mat passes) */
  bool
  check(const MedialMesh& mat, const TriangleMesh& mesh, std::string& reason) const;
};

} // namespace segmat
