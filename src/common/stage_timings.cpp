/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/stage_timings.h>

#include <algorithm>

namespace segmat {

void
StageTimings::add(const std::string& name, double seconds)
{
  const auto it = std::find_if(stages_.begin(), stages_.end(),
                               [&](const StageTiming& s) { return s.name == name; });
  if (it == stages_.end())
    stages_.push_back({name, seconds});
  else
    it->seconds += seconds;
}

void
StageTimings::add(const StageTimings& other)
{
  for (const StageTiming& s : other)
    add(s.name, s.seconds);
}

double
StageTimings::seconds(const std::string& name) const
{
  for (const StageTiming& s : stages_)
    if (s.name == name)
      return s.seconds;
  return 0.0;
}

bool
StageTimings::contains(const std::string& name) const
{
  return std::any_of(stages_.begin(), stages_.end(),
                     [&](const StageTiming& s) { return s.name == name; });
}

double
StageTimings::total() const
{
  double sum = 0.0;
  for (const StageTiming& s : stages_)
    sum += s.seconds;
  return sum;
}

} // namespace segmat
