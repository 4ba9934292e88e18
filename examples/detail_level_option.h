/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// --level of segmat_mesh and segmat_cloud (not installed).

#include <segmat/segmentation/detail_level.h>

#include <string>

namespace segmat {
namespace cli {

/** --level: sets δ and η together (coarse, default, fine or a number in [−1, 1]). */
template <typename Segmentation>
void
applyDetailLevel(Segmentation& segmentation, const std::string& text)
{
  const DetailLevel level = parseDetailLevel(text);
  segmentation.setGrowingThreshold(level.growing_threshold);
  segmentation.setMinRegionFraction(level.min_region_fraction);
}

} // namespace cli
} // namespace segmat
