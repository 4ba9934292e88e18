/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: checks of PLY and PCD headers before PCL's readers see the files.
// PCL 1.13's readers trust the header: the PLY reader resizes its buffers to whatever element
// counts a corrupt header announces ("element vertex 400000000" in a 1 kB file allocates and
// zeroes gigabytes), aborts on a vertex list property of varying length, and the PCD reader
// crashes (segmentation fault) on an empty file or a header without fields. These checks refuse
// such files with the header line, so every damaged file becomes a segmat::Error. VTK's STL
// reader (behind PCL's) silently returns part of a truncated binary STL; checkStlSize refuses it.

#include <string>

namespace segmat {
namespace io {
namespace detail {

/** \brief Checks that \a path starts with a well-formed PLY header whose element counts fit in the
 * bytes after it.
 * \throws segmat::Error with path and header line (0 for a missing or empty file) otherwise.
 */
/** \brief Throws segmat::Error naming \a path when it is missing or a directory (stream readers
 * open a directory without complaint and then fail with a message that lacks the path). */
void
requireRegularFile(const std::string& path);

void
checkPlyHeader(const std::string& path);

/** \brief Checks that \a path starts with a well-formed, self-consistent PCD header (FIELDS,
 * SIZE, TYPE, COUNT agree; WIDTH x HEIGHT = POINTS; a DATA line) whose points fit in the bytes
 * after it.
 * \throws segmat::Error with path and header line (0 for a missing or empty file) otherwise.
 */
void
checkPcdHeader(const std::string& path);

/** \brief Checks that a binary STL's size matches its triangle count (VTK's reader silently
 * returns the triangles of a truncated file, and allocates whatever a wrong count announces);
 * ASCII STL (starting with `solid`, under 5 % non-text bytes in its first 256, as VTK tells
 * them apart) is left to the reader.
 * \throws segmat::Error with path (line 0) otherwise.
 */
void
checkStlSize(const std::string& path);

} // namespace detail
} // namespace io
} // namespace segmat
