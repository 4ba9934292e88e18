/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/segmentation/detail_level.h>

#include <cmath>
#include <cstdlib>

namespace segmat {

const std::vector<DetailLevel>&
detailLevels()
{
  // δ and η were swept on psb-dev (bench_sensitivity, docs/levels.md): coarse and fine are the
  // ends of the swept range that still move the part count the expected way.
  static const std::vector<DetailLevel> levels{
      {"coarse", 0.03, 0.004}, {"default", 0.015, 0.002}, {"fine", 0.0075, 0.001}};
  return levels;
}

DetailLevel
parseDetailLevel(const std::string& text)
{
  const std::vector<DetailLevel>& levels = detailLevels();
  for (const DetailLevel& level : levels)
    if (level.name == text)
      return level;
  char* end = nullptr;
  const double t = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(t >= -1.0 && t <= 1.0))
    throw Error("level '" + text + "': give coarse, default, fine or a number in [-1, 1]");
  // Geometric interpolation between the neighbouring named levels.
  const DetailLevel& from = levels[1];
  const DetailLevel& to = t < 0.0 ? levels[0] : levels[2];
  const double s = std::abs(t);
  DetailLevel level;
  level.name = text;
  level.growing_threshold =
      from.growing_threshold * std::pow(to.growing_threshold / from.growing_threshold, s);
  level.min_region_fraction =
      from.min_region_fraction * std::pow(to.min_region_fraction / from.min_region_fraction, s);
  return level;
}

} // namespace segmat
