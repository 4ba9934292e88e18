/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "report.h"

#include <cstdio>

namespace segmat {
namespace cli {

std::string
jsonSizes(const std::vector<pcl::PointIndices>& parts)
{
  std::string out = "[";
  for (std::size_t k = 0; k < parts.size(); ++k)
    out += (k ? ", " : "") + std::to_string(parts[k].indices.size());
  return out + "]";
}

std::string
jsonSeconds(const StageTimings& seconds)
{
  std::string out = "{";
  char number[32];
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    std::snprintf(number, sizeof number, "%.6f", seconds[k].seconds);
    out += (k ? ", \"" : "\"") + seconds[k].name + "\": " + number;
  }
  return out + "}";
}

void
printPartsText(const char* element, const std::vector<pcl::PointIndices>& parts,
               const StageTimings& seconds)
{
  std::printf("parts: %zu\n%s counts:", parts.size(), element);
  for (const auto& part : parts)
    std::printf(" %zu", part.indices.size());
  std::printf("\nseconds:");
  for (const auto& stage : seconds)
    std::printf(" %s %.4f", stage.name.c_str(), stage.seconds);
}

void
printWrote(const io::OutputSet& outputs)
{
  std::printf("wrote");
  for (std::size_t k = 0; k < outputs.paths().size(); ++k)
    std::printf("%s %s", k ? "," : "", outputs.paths()[k].c_str());
  std::printf("\n");
}

} // namespace cli
} // namespace segmat
