/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace test {

/** \brief Closed triangle meshes built in code, all wound counter-clockwise seen from outside
 * (outward normals), for tests that need shapes with a known answer.
 */

/** \brief Tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1); volume 1/6. */
TriangleMesh
tetrahedron();

/** \brief Axis-aligned box [lo, hi], each side split into an n×n grid of quads (2 triangles each).
 * With n > 1 the vertices lie on a regular grid: a CAD-like, co-spherical input for Delaunay codes.
 */
TriangleMesh
box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int n = 1);

/** \brief Icosphere: an icosahedron subdivided `subdivisions` times, projected onto the sphere.
 * 12, 42, 162, 642, 2562, 10242 vertices for 0…5 subdivisions.
 */
TriangleMesh
icosphere(int subdivisions, double radius = 1.0,
          const Eigen::Vector3d& center = Eigen::Vector3d::Zero());

/** \brief Surface of revolution about the z axis.
 * \param[in] profile (r, z) points from top to bottom; an end with r == 0 becomes a pole vertex,
 *            an end with r > 0 is closed by a flat cap with a centre vertex.
 * \param[in] segments number of vertices around each ring (>= 3)
 */
TriangleMesh
revolve(const std::vector<Eigen::Vector2d>& profile, int segments);

/** \brief Closed cylinder of the given radius, axis z, from z = -length/2 to +length/2. */
TriangleMesh
cylinder(double radius, double length, int segments = 48, int stacks = 24);

/** \brief Capsule: cylinder of `length` along z capped by hemispheres of the same radius
 * (total extent length + 2·radius). Its medial axis is the segment z ∈ [-length/2, length/2].
 */
TriangleMesh
capsule(double radius, double length, int segments = 48, int stacks = 24, int cap_rings = 12);

/** \brief Torus about the z axis: tube radius `minor` around a circle of radius `major`. */
TriangleMesh
torus(double major, double minor, int major_segments = 64, int minor_segments = 24);

/** \brief Signed volume (divergence theorem); positive for a closed outward-wound mesh. */
double
signedVolume(const TriangleMesh& mesh);

/** \brief Concatenates meshes (vertex indices of later meshes are shifted). */
TriangleMesh
merge(const std::vector<TriangleMesh>& parts);

} // namespace test
} // namespace segmat
