/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace segmat {

/** \brief Wall-clock seconds of one named stage of a pipeline. */
struct StageTiming
{
  StageTiming() = default;
  StageTiming(std::string stage_name, double stage_seconds)
  : name(std::move(stage_name))
  , seconds(stage_seconds)
  {}

  std::string name;     ///< the stage: "denoise", "mat", "grow_merge", ...
  double seconds = 0.0; ///< wall-clock seconds; 0 for a stage whose result was reused
};

/** \brief The stages of one run, in pipeline order (getStageSeconds() of the segmentations). */
using StageTimings = std::vector<StageTiming>;

} // namespace segmat
