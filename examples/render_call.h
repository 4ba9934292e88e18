/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// --png of segmat_mesh and segmat_cloud (not installed): runs segmat_render, the one renderer,
// so these programs need no VTK. segmat_render is looked for beside the running program, then
// on PATH; it is built only when VTK is found.

#include <segmat/common/error.h>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <string>
#include <vector>

extern char** environ;

namespace segmat {
namespace cli {

/** Writes \a png, a picture of \a shape coloured by \a labels; segmat::Error naming \a png when
 * segmat_render cannot be run or fails (its own message is on stderr). */
inline void
renderPicture(const std::string& shape, const std::string& labels, const std::string& png)
{
  std::string program = "segmat_render";
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n > 0) {
    const std::string path(self, static_cast<std::size_t>(n));
    const std::string sibling = path.substr(0, path.rfind('/') + 1) + program;
    if (access(sibling.c_str(), X_OK) == 0)
      program = sibling;
  }
  std::vector<std::string> args{program, shape, labels, "-o", png};
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ);
  if (error != 0)
    throw Error(png, 0,
                std::string("not written: cannot run segmat_render (") + std::strerror(error) +
                    "; it is built when VTK is found)");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(png, 0, "not written: segmat_render failed (its message is above)");
}

} // namespace cli
} // namespace segmat
