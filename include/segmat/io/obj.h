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

/** \brief Reads the geometry of a Wavefront OBJ file: `v` and `f` lines.
 *
 * segmat's own reader: PCL's OBJ reader crashes on truncated or damaged files and rounds
 * coordinates to float. Accepts `f` corners written `i`, `i/t`, `i/t/n` or `i//n`, negative
 * (relative) indices, faces of any size (fan-triangulated (v0, v_{k-1}, v_k), in order), extra
 * values on `v` lines (w, vertex colours), `#` comments, CRLF; every other statement (vt, vn, g,
 * o, s, usemtl, mtllib, l, ...) is skipped.
 * \throws segmat::Error with path and line for a missing file, no `v` line at all, a non-numeric
 *         or non-finite coordinate, a face with fewer than 3 corners, an index 0 or out of range,
 *         or binary data.
 */
TriangleMesh
loadObj(const std::string& path);

/** \brief Writes `v` and `f` lines (1-based) at full precision (whole or not at all). */
void
saveObj(const std::string& path, const TriangleMesh& mesh);

} // namespace io
} // namespace segmat
