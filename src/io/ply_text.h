/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: the one PLY writer behind saveMesh and the coloured-PLY savers.

#include <segmat/io/colored_ply.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace segmat {
namespace io {
namespace detail {

/** \brief ASCII PLY text: vertices `double x y z` (+ `uchar red green blue` when \a vertex_colors),
 * then, when \a faces is given, faces `list uchar int vertex_indices` (+ colours when
 * \a face_colors). Numbers in shortest round-trip form, so equal inputs give equal bytes. */
std::string
plyText(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Rgb>* vertex_colors,
        const std::vector<Eigen::Vector3i>* faces, const std::vector<Rgb>* face_colors);

} // namespace detail
} // namespace io
} // namespace segmat
