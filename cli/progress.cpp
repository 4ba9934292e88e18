/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "progress.h"

#include <cstdio>

namespace segmat {
namespace cli {

Progress::Progress(std::string program, bool quiet)
: program_(std::move(program)), quiet_(quiet), start_(std::chrono::steady_clock::now())
{
  if (!quiet_)
    watcher_ = std::thread([this] { watch(); });
}

Progress::~Progress()
{
  // No "done" line here: an exception may be unwinding the stage.
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (watcher_.joinable())
    watcher_.join();
}

double
Progress::stage(const std::string& name)
{
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (announced_)
    std::fprintf(stderr, "%s: %s done (%.1f s)\n", program_.c_str(), name_.c_str(), seconds);
  name_ = name;
  start_ = now;
  announced_ = false;
  return seconds;
}

double
Progress::done()
{
  return stage("");
}

void
Progress::watch()
{
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    wake_.wait_for(lock, std::chrono::milliseconds(200));
    if (stop_ || announced_ || name_.empty())
      continue;
    if (std::chrono::steady_clock::now() - start_ >= std::chrono::seconds(1)) {
      std::fprintf(stderr, "%s: %s ...\n", program_.c_str(), name_.c_str());
      announced_ = true;
    }
  }
}

} // namespace cli
} // namespace segmat
