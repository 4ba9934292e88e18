/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>

#include "temporary_registry.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace segmat {
namespace io {
namespace {
namespace fs = std::filesystem;

std::string
temporaryFor(const std::string& path)
{
  return path + ".tmp" + std::to_string(::getpid());
}

void
commitOne(const std::string& tmp, const std::string& path)
{
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    detail::unregisterTemporary(tmp);
    throw Error(path, 0, "cannot write the file (rename of the temporary failed)");
  }
  detail::unregisterTemporary(tmp);
}

void
discard(const std::string& tmp)
{
  std::remove(tmp.c_str());
  detail::unregisterTemporary(tmp);
}

// The directory a path's file lives in ("." for a bare name).
std::string
directoryOf(const std::string& path)
{
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// True when a and b name the same file: same path after resolving links, or same inode.
bool
sameFile(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  std::error_code ea, eb;
  const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  return !ea && !eb && ca == cb;
}

// SIGINT/SIGTERM/SIGHUP blocked while alive: a run's renames are not interrupted half-way.
class SignalsBlocked
{
public:
  SignalsBlocked()
  {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

private:
  sigset_t old_;
};
} // namespace

void
writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                    bool binary)
{
  const std::string tmp = temporaryFor(path);
  detail::registerTemporary(tmp);
  {
    std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary : std::ios::out);
    if (!out) {
      detail::unregisterTemporary(tmp);
      throw Error(path, 0, "cannot open the file for writing");
    }
    try {
      write(out);
    } catch (...) {
      out.close();
      discard(tmp);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      discard(tmp);
      throw Error(path, 0, "write failed (disk full or I/O error)");
    }
  }
  commitOne(tmp, path);
}

void
writeFileAtomicallyByName(const std::string& path,
                          const std::function<bool(const std::string&)>& write)
{
  const std::string tmp = temporaryFor(path);
  detail::registerTemporary(tmp);
  bool ok = false;
  try {
    ok = write(tmp);
  } catch (...) {
    discard(tmp);
    throw;
  }
  if (!ok) {
    discard(tmp);
    throw Error(path, 0, "write failed");
  }
  commitOne(tmp, path);
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

void
checkOutputPath(const std::string& path, const std::vector<std::string>& inputs)
{
  if (path.empty())
    throw Error("an output path is empty");
  if (path.back() == '/' || fs::is_directory(path))
    throw Error(path, 0,
                "is a directory; give a file name or a prefix inside it (such as dir/name)");
  for (const std::string& input : inputs)
    if (sameFile(path, input))
      throw Error(path, 0,
                  "is the input file '" + input + "'; refusing to overwrite an input");
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw Error(path, 0, "exists and is not a regular file (a device or a pipe?)");
    if (::access(path.c_str(), W_OK) != 0)
      throw Error(path, 0, "exists and is not writable");
  }
  const std::string dir = directoryOf(path);
  if (!fs::is_directory(dir))
    throw Error(path, 0, "the directory '" + dir + "' does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw Error(path, 0, "the directory '" + dir + "' is not writable");
}

int
removeStaleTemporaries(const std::string& path)
{
  const fs::path target(path);
  const std::string dir = directoryOf(path), stem = target.filename().string() + ".tmp";
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, stem.size(), stem) != 0)
      continue;
    // name = stem + PID [+ ".tmp" + PID]: the first PID made it.
    const std::string rest = name.substr(stem.size());
    const std::size_t digits = rest.find_first_not_of("0123456789");
    if (digits == 0 || (digits != std::string::npos && rest.compare(digits, 4, ".tmp") != 0))
      continue;
    const long pid = std::strtol(rest.c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid())
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue; // the process still runs (perhaps under another user)
    if (std::remove(it->path().c_str()) == 0)
      ++removed;
  }
  return removed;
}

void
removeTemporariesOnSignal()
{
  detail::installTemporaryCleanup();
}

OutputSet::OutputSet(std::vector<std::string> inputs) : inputs_(std::move(inputs)) {}

OutputSet::~OutputSet()
{
  if (!committed_)
    for (const std::string& path : paths_)
      discard(temporary(path));
}

void
OutputSet::add(const std::string& path)
{
  checkOutputPath(path, inputs_);
  for (const std::string& other : paths_)
    if (sameFile(other, path))
      throw Error(path, 0, "is given twice as an output");
  removeStaleTemporaries(path);
  paths_.push_back(path);
  detail::registerTemporary(temporary(path));
}

std::string
OutputSet::temporary(const std::string& path) const
{
  return temporaryFor(path);
}

void
OutputSet::commit()
{
  for (const std::string& path : paths_)
    if (::access(temporary(path).c_str(), F_OK) != 0)
      throw Error(path, 0, "was not written");
  const SignalsBlocked blocked;
  for (const std::string& path : paths_)
    commitOne(temporary(path), path);
  committed_ = true;
}

} // namespace io
} // namespace segmat
