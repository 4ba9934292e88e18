/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h>

#include <string>
#include <vector>

namespace segmat {

/** \brief A granularity of SEG-MAT: the growing threshold δ and the minimal region η, the two
 * parameters the paper (Lin et al. 2022, §8) varies for coarser or finer parts while all others
 * stay fixed. A smaller δ stops the region growing earlier (more parts); a larger η absorbs more
 * small regions (fewer tiny parts).
 */
struct DetailLevel
{
  std::string name;                   ///< "coarse", "default", "fine" or the number given
  double growing_threshold = 0.015;   ///< δ (MatRegionGrowing::setGrowingThreshold)
  double min_region_fraction = 0.002; ///< η (MatRegionGrowing::setMinRegionFraction)
};

/** \brief The named levels, coarse to fine: "coarse", "default" (the library's defaults) and
 * "fine". Their δ and η were chosen from the part counts and PSB 1 − RI measured on psb-dev
 * (docs/levels.md, bench/results/sensitivity.txt).
 */
const std::vector<DetailLevel>&
detailLevels();

/** \brief Parses a level: a name of detailLevels(), or a number t in [−1, 1] that moves δ and η
 * geometrically from coarse (−1) through default (0) to fine (1).
 * \throws segmat::Error naming \a text when it is neither.
 */
DetailLevel
parseDetailLevel(const std::string& text);

} // namespace segmat
