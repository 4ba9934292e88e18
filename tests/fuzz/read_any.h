/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Shared by the fuzz targets and the test that replays tests/fuzz/regressions/.

#include <segmat/common/error.h>
#include <segmat/io/cloud.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>
#include <segmat/io/atomic_file.h>

#include <string>

namespace segmat {
namespace test {

/** \brief Reads \a path with the reader its extension selects (.pcd: clouds; .ma; .seg; else
 * meshes). Returns true when it was read, false when the reader threw segmat::Error; any other
 * exception propagates. */
inline bool
readAny(const std::string& path)
{
  try {
    const std::string ext = io::extensionOf(path);
    if (ext == "pcd")
      io::loadCloud(path);
    else if (ext == "ma")
      io::loadMa(path);
    else if (ext == "seg")
      io::loadSeg(path);
    else
      io::loadMesh(path);
    return true;
  }
  catch (const Error&) {
    return false;
  }
}

} // namespace test
} // namespace segmat
