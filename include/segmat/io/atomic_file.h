/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace segmat {
namespace io {

/** \brief Writes a file whole or not at all.
 *
 * \a write fills a stream on a temporary file beside \a path; only when it returns and the stream
 * is good is the temporary renamed over \a path (atomic on POSIX). On any failure the temporary
 * is removed, \a path is left as it was, and segmat::Error names the path.
 */
void
writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                    bool binary = false);

/** \brief Same, for writers that only take a file name (PCL's savers): \a write gets the
 * temporary's path and returns true on success.
 */
void
writeFileAtomicallyByName(const std::string& path,
                          const std::function<bool(const std::string& tmp_path)>& write);

/** \brief Lower-case extension without the dot ("off" for "a/b.OFF"); "" when none. */
std::string
extensionOf(const std::string& path);

} // namespace io
} // namespace segmat
