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
 * OpenMP). Never more than the machine's processors: per-thread buffers of an absurd count
 * would exhaust memory, and results do not depend on the count.
 */
inline int
threadCount(unsigned int requested)
{
#ifdef _OPENMP
  const unsigned procs = static_cast<unsigned>(omp_get_num_procs());
  return requested > 0 ? static_cast<int>(requested < procs ? requested : procs)
                       : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

} // namespace detail
} // namespace segmat
