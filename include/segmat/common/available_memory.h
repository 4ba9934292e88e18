/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <cstddef>

namespace segmat {

/** \brief Memory this process may still take without swapping, in bytes: MemAvailable of
 * /proc/meminfo, else the free physical pages (sysconf); 0 when neither can be read. The size
 * ceilings of the medial-axis computation (VoronoiMat::getSampleCeiling) derive from it.
 */
std::size_t
availableMemoryBytes();

} // namespace segmat
