/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Progress on stderr for the command-line programs (not installed).

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace segmat {
namespace cli {

/** \brief Names the stage a program is in, on stderr, once it has run for a second.
 *
 * Fast stages print nothing (a quick run stays silent); a stage still running after one second
 * prints "PROGRAM: STAGE ..." and, when stage() or done() ends it, "done (N s)". Silent when
 * quiet.
 */
class Progress
{
public:
  Progress(std::string program, bool quiet);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress&
  operator=(const Progress&) = delete;

  /** \brief Ends the current stage and starts \a name; returns the ended stage's seconds. */
  double
  stage(const std::string& name);

  /** \brief Ends the current stage; returns its seconds. */
  double
  done();

private:
  void
  watch();

  std::string program_;
  bool quiet_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
  bool announced_ = false, stop_ = false;
  std::thread watcher_;
};

} // namespace cli
} // namespace segmat
