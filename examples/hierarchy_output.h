/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// --hierarchy of segmat_mesh (not installed).

#include <segmat/io/atomic_file.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>
#include <segmat/segmentation/segmentation_hierarchy.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace segmat {
namespace cli {

/** --hierarchy: segments at every named level, coarse to fine, reusing the medial meshes, and
 * writes PREFIX_levelK.seg per level and PREFIX_hierarchy.json:
 * {"levels": [{"level": K, "name": .., "growing_threshold": δ, "min_region": η,
 * "file": "PREFIX_levelK.seg", "parts": N, "parents": [parent of part 0, ...]}, ...]}
 * (file names relative to the JSON's folder; parents −1 on level 0). Returns the level count. */
inline std::vector<std::string>
hierarchySuffixes()
{
  std::vector<std::string> suffixes;
  for (std::size_t k = 0; k < detailLevels().size(); ++k)
    suffixes.push_back("_level" + std::to_string(k) + ".seg");
  suffixes.push_back("_hierarchy.json");
  return suffixes;
}

/** Writes into \a outputs' temporaries (declared with hierarchySuffixes()). */
inline std::size_t
writeHierarchy(const io::OutputSet& outputs, const std::string& prefix,
               MeshSegmentation& segmentation)
{
  std::vector<HierarchyLevel> hierarchy;
  if (!segmentHierarchy(segmentation, detailLevels(), hierarchy))
    throw Error("the hierarchy's segmentation failed");
  const std::string base = std::filesystem::path(prefix).filename().string();
  for (std::size_t k = 0; k < hierarchy.size(); ++k)
    io::saveSeg(outputs.temporary(prefix + "_level" + std::to_string(k) + ".seg"),
                hierarchy[k].labels);
  io::writeFileAtomically(outputs.temporary(prefix + "_hierarchy.json"), [&](std::ostream& out) {
    out.precision(15); // the levels' δ and η print as written (0.03, not 0.029999999999999999)
    out << "{\"levels\": [";
    for (std::size_t k = 0; k < hierarchy.size(); ++k) {
      const HierarchyLevel& h = hierarchy[k];
      out << (k ? ",\n  " : "\n  ") << "{\"level\": " << k << ", \"name\": \"" << h.level.name
          << "\", \"growing_threshold\": " << h.level.growing_threshold
          << ", \"min_region\": " << h.level.min_region_fraction << ", \"file\": \"" << base
          << "_level" << k << ".seg\", \"parts\": " << h.parents.size() << ", \"parents\": [";
      for (std::size_t p = 0; p < h.parents.size(); ++p)
        out << (p ? ", " : "") << h.parents[p];
      out << "]}";
    }
    out << "\n]}\n";
  });
  return hierarchy.size();
}

} // namespace cli
} // namespace segmat
