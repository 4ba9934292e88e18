/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <segmat/geometry/triangle_mesh.h>

#include <string>

namespace segmat {
namespace io {

/** \brief Reads an OFF triangle mesh (PCL and VTK read no OFF).
 *
 * Accepts the `OFF` header (also glued to the counts, as in `OFF4 2 0`), `#` comments, blank
 * lines, CRLF, polygons of any size (fan-triangulated (v0, v_{k-1}, v_k), in order, so face i of a
 * triangle-only file is its i-th face line) and trailing per-face colours.
 * \throws segmat::Error with path and line for a missing file, a bad header, wrong counts,
 *         truncated data, an index out of range, a non-finite coordinate, or binary junk.
 */
TriangleMesh
loadOff(const std::string& path);

/** \brief Writes an OFF triangle mesh at full precision (whole or not at all). */
void
saveOff(const std::string& path, const TriangleMesh& mesh);

} // namespace io
} // namespace segmat
