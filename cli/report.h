/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// What the segmenting programs print on stdout: text or JSON pieces (not installed).

#include <segmat/common/stage_timing.h>
#include <segmat/io/atomic_file.h>

#include <pcl/PointIndices.h>

#include <string>
#include <utility>
#include <vector>

namespace segmat {
namespace cli {



/** \brief `[n0, n1, ...]`: the parts' sizes. */
std::string
jsonSizes(const std::vector<pcl::PointIndices>& parts);

/** \brief `{"stage": seconds, ...}`. */
std::string
jsonSeconds(const StageTimings& seconds);

/** \brief "parts: N", "ELEMENT counts: ...", "seconds: ..." lines, without the last newline. */
void
printPartsText(const char* element, const std::vector<pcl::PointIndices>& parts,
               const StageTimings& seconds);

/** \brief "wrote A, B, ..." and a newline. */
void
printWrote(const io::OutputSet& outputs);

} // namespace cli
} // namespace segmat
