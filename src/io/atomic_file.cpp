/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>

namespace segmat {
namespace io {
namespace {
std::string
temporaryFor(const std::string& path)
{
  return path + ".tmp" + std::to_string(::getpid());
}

void
commit(const std::string& tmp, const std::string& path)
{
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(path, 0, "cannot write the file (rename of the temporary failed)");
  }
}
} // namespace

void
writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                    bool binary)
{
  const std::string tmp = temporaryFor(path);
  {
    std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary : std::ios::out);
    if (!out)
      throw Error(path, 0, "cannot open the file for writing");
    try {
      write(out);
    } catch (...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw Error(path, 0, "write failed (disk full or I/O error)");
    }
  }
  commit(tmp, path);
}

void
writeFileAtomicallyByName(const std::string& path,
                          const std::function<bool(const std::string&)>& write)
{
  const std::string tmp = temporaryFor(path);
  bool ok = false;
  try {
    ok = write(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    throw Error(path, 0, "write failed");
  }
  commit(tmp, path);
}

std::string
extensionOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

} // namespace io
} // namespace segmat
