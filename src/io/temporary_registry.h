/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/io: temporaries that a signal handler removes before the process dies.

#include <string>

namespace segmat {
namespace io {
namespace detail {

/** \brief Remembers \a path for removal on a signal (a fixed number of slots; paths beyond it
 * or longer than a slot are not remembered, and only lose the cleanup). */
void
registerTemporary(const std::string& path);

/** \brief Forgets \a path (it was renamed or removed). */
void
unregisterTemporary(const std::string& path);

/** \brief SIGINT / SIGTERM / SIGHUP: unlink every registered path, then die of the signal. */
void
installTemporaryCleanup();

} // namespace detail
} // namespace io
} // namespace segmat
