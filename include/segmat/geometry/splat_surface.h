/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {

/** \brief A triangle soup standing for the surface of an oriented point cloud: one small
 * equilateral triangle ("splat") per point, centred on it, in its tangent plane, of the area the
 * point stands for, wound so that its face normal is the point's normal.
 *
 * The generalised winding number of this soup is the cloud winding number of Barill, Dickson,
 * Schmidt, Levin, Jacobson ("Fast winding numbers for soups and clouds", ACM TOG 2018, §3.3:
 * each point a dipole a_i n_i): the far field depends only on the area vectors, and the near
 * field of a flat splat is finite where a bare dipole's is not. So WindingNumber (built without
 * orientation repair: the splats share no edge) answers inside/outside for a cloud.
 *
 * Points with a non-finite coordinate or normal, a zero normal or a non-positive area get no
 * splat.
 * \param[in] points the points
 * \param[in] normals one outward normal per point (normalised here)
 * \param[in] areas one surface area per point (e.g. π d_k² / (k + 1) from the k-th neighbour)
 * \return the soup: 3 vertices and 1 face per kept point, in point order
 */
TriangleMesh
makeSplatSurface(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& areas);

} // namespace segmat
