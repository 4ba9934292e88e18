/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * libFuzzer target for one file reader, chosen at compile time by SEGMAT_FUZZ_EXT ("off", "ply",
 * "obj", "stl", "pcd", "ma", "seg"). The readers take paths, so each input is written to a file
 * with that extension first. A reader may accept the bytes or throw segmat::Error; anything else
 * (a crash, another exception, a sanitizer report, a hang) is a finding.
 */
#include "read_any.h"

#include <pcl/console/print.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace {
std::string g_path;
}

extern "C" int
LLVMFuzzerInitialize(int*, char***)
{
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); // PCL's per-file chatter off
  const char* dir = std::getenv("TMPDIR");
  g_path = std::string(dir ? dir : "/tmp") + "/segmat_fuzz_" + std::to_string(::getpid()) + "." +
           SEGMAT_FUZZ_EXT;
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::FILE* file = std::fopen(g_path.c_str(), "wb");
  if (!file)
    return 0;
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  segmat::test::readAny(g_path); // throws only what is not segmat::Error: a finding
  std::remove(g_path.c_str());
  return 0;
}
