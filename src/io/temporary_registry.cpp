/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "temporary_registry.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace segmat {
namespace io {
namespace detail {
namespace {
// Fixed storage: the handler may only touch memory that never moves and call unlink().
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
char g_paths[kSlots][kPathBytes];
std::atomic<bool> g_used[kSlots];
std::mutex g_mutex; // registration only; the handler does not lock

extern "C" void
onSignal(int signal_number)
{
  for (int k = 0; k < kSlots; ++k)
    if (g_used[k].load())
      ::unlink(g_paths[k]);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}
} // namespace

void
registerTemporary(const std::string& path)
{
  if (path.size() + 1 > kPathBytes)
    return;
  std::lock_guard<std::mutex> lock(g_mutex);
  for (int k = 0; k < kSlots; ++k)
    if (!g_used[k].load()) {
      std::memcpy(g_paths[k], path.c_str(), path.size() + 1);
      g_used[k].store(true);
      return;
    }
}

void
unregisterTemporary(const std::string& path)
{
  std::lock_guard<std::mutex> lock(g_mutex);
  for (int k = 0; k < kSlots; ++k)
    if (g_used[k].load() && path == g_paths[k]) {
      g_used[k].store(false);
      return;
    }
}

void
installTemporaryCleanup()
{
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (int s : {SIGINT, SIGTERM, SIGHUP})
      ::sigaction(s, &action, nullptr);
  });
}

} // namespace detail
} // namespace io
} // namespace segmat
