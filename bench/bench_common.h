/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Small helpers shared by the benchmark programs (header only: bench/*.cpp are programs).
 */
#pragma once

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <unistd.h>

namespace segmat {
namespace bench {

/** \brief Run on one thread unless the caller set OMP_NUM_THREADS: OpenMP reads the variable
 * when the program is loaded, so set it and start the program again.
 */
inline void
restartSingleThreaded(char** argv)
{
  if (!std::getenv("OMP_NUM_THREADS")) {
    setenv("OMP_NUM_THREADS", "1", 1);
    execv("/proc/self/exe", argv);
  }
}

/** \brief Median of \a values (0 when empty; the mean of the middle two for an even count). */
inline double
median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

} // namespace bench
} // namespace segmat
