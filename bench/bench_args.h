/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Command-line arguments of the MAT benchmark programs (header only: bench/*.cpp are programs).
 */
#pragma once

#include <segmat/common/error.h>
#include <segmat/io/mesh.h>

#include "option_parser.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace segmat {
namespace bench {

/** \brief Appends \a path to \a files, or, for a folder, every regular file in it (sorted). */
inline void
appendPaths(const std::string& path, std::vector<std::string>& files)
{
  if (!std::filesystem::is_directory(path)) {
    files.push_back(path);
    return;
  }
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(path))
    if (entry.is_regular_file())
      found.push_back(entry.path().string());
  std::sort(found.begin(), found.end());
  files.insert(files.end(), found.begin(), found.end());
}

/** \brief The integer after option argv[i] (advancing i), read by the programs' shared parser;
 * exits with status 2 (cli::kExitBadInput) when missing or not a whole number. */
inline int
intArgument(int argc, char** argv, int& i)
{
  const std::string option = argv[i];
  try {
    if (i + 1 >= argc)
      throw Error("needs a value");
    return static_cast<int>(cli::parseInteger(argv[++i], -1000000000L));
  }
  catch (const Error& e) {
    std::fprintf(stderr, "option %s: %s\n", option.c_str(), e.what());
    std::exit(cli::kExitBadInput);
  }
}

/** \brief The mesh at \a path, or null (with a "skipped" line on stderr) when it cannot be read. */
inline TriangleMesh::Ptr
loadMeshOrSkip(const std::string& path)
{
  try {
    return std::make_shared<TriangleMesh>(io::loadMesh(path));
  }
  catch (const Error& e) {
    std::fprintf(stderr, "skipped: %s\n", e.what());
    return nullptr;
  }
}

} // namespace bench
} // namespace segmat
