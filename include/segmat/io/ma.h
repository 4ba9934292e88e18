/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <segmat/geometry/medial_mesh.h>

#include <string>

namespace segmat {
namespace io {

/** \brief Reads a Q-MAT `.ma` medial mesh (format: docs/file-formats.md).
 *
 * Parsed by tag (`v x y z r`, `e i j`, `f i j k`, optional `n nx ny nz`) until the end of file;
 * the header counts are checked and a mismatch only warns (real files have wrong headers).
 * Indices are 0-based and checked against the vertex count; CRLF is accepted.
 * \throws segmat::Error with path and line on a bad index, a negative or NaN radius, a
 *         malformed line, a missing file or binary junk.
 */
MedialMesh
loadMa(const std::string& path);

/** \brief Writes a `.ma` file at full precision (round-trips exactly; whole or not at all). */
void
saveMa(const std::string& path, const MedialMesh& mat);

} // namespace io
} // namespace segmat
