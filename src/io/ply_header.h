/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: a check of a PLY header before PCL's reader sees the file. PCL resizes its
// buffers to the element counts the header announces, so a corrupt count ("element vertex
// 400000000" in a 1 kB file) would allocate and zero gigabytes before failing; this check refuses
// such files with the header line, and gives clear messages for non-PLY files.

#include <string>

namespace segmat {
namespace io {
namespace detail {

/** \brief Checks that \a path starts with a well-formed PLY header whose element counts fit in the
 * bytes after it.
 * \throws segmat::Error with path and header line (0 for a missing file) otherwise.
 */
void
checkPlyHeader(const std::string& path);

} // namespace detail
} // namespace io
} // namespace segmat
