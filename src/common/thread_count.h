/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: OpenMP is optional, so its API is touched only here.

#ifdef _OPENMP
#include <omp.h>
#endif

namespace segmat {
namespace detail {

/** \brief Threads for a parallel loop: \a requested, or OpenMP's choice when 0 (1 without
 * OpenMP).
 */
inline int
threadCount(unsigned int requested)
{
#ifdef _OPENMP
  return requested > 0 ? static_cast<int>(requested) : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

} // namespace detail
} // namespace segmat
