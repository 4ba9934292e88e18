/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error

#include <string>
#include <vector>

namespace segmat {
namespace io {

/** \brief Reads a PSB `.seg` file: one integer label per line, in face order.
 *
 * Strict, unlike the benchmark's own reader: exactly one integer per non-empty line and, when
 * \a expected_count >= 0, exactly that many lines.
 * \throws segmat::Error naming the file and line for a non-integer line or a wrong count.
 */
std::vector<int>
loadSeg(const std::string& path, long expected_count = -1);

/** \brief Writes labels one per line (whole or not at all). */
void
saveSeg(const std::string& path, const std::vector<int>& labels);

} // namespace io
} // namespace segmat
