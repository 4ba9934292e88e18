/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

/** \brief Wall-clock seconds of one named stage of a pipeline. */
struct StageTiming
{
  std::string name;     ///< stage name, e.g. "mat", "grow_merge"
  double seconds = 0.0; ///< wall-clock seconds (0 for a stage whose result was reused)
};

/** \brief Seconds per stage of one run of a pipeline, in pipeline order.
 *
 * A stage is listed once: adding to a name that is already present adds the seconds (so the
 * timings of repeated runs can be summed with add(const StageTimings&)).
 */
class StageTimings
{
public:
  using const_iterator = std::vector<StageTiming>::const_iterator;

  /** \brief Adds \a seconds to stage \a name, appending the stage when it is new. */
  void
  add(const std::string& name, double seconds);

  /** \brief Adds every stage of \a other, in its order (stages new here are appended). */
  void
  add(const StageTimings& other);

  /** \brief Seconds of stage \a name; 0 when it is absent. */
  double
  seconds(const std::string& name) const;

  /** \brief Whether stage \a name was recorded. */
  bool
  contains(const std::string& name) const;

  /** \brief Sum over all stages. */
  double
  total() const;

  /** \brief Forgets every stage. */
  void
  clear()
  {
    stages_.clear();
  }

  /** \brief Number of stages. */
  std::size_t
  size() const
  {
    return stages_.size();
  }

  /** \brief Whether no stage was recorded. */
  bool
  empty() const
  {
    return stages_.empty();
  }

  /** \brief The \a i-th stage, in pipeline order. */
  const StageTiming&
  operator[](std::size_t i) const
  {
    return stages_[i];
  }

  /** \brief First stage. */
  const_iterator
  begin() const
  {
    return stages_.begin();
  }

  /** \brief Past the last stage. */
  const_iterator
  end() const
  {
    return stages_.end();
  }

private:
  std::vector<StageTiming> stages_;
};

/** \brief Times a scope: on destruction adds the elapsed wall-clock seconds to one stage.
 *
 * \code
 * segmat::StageTimings timings;
 * {
 *   segmat::ScopedStageTimer timer(timings, "graph");
 *   buildGraph();
 * }
 * \endcode
 */
class ScopedStageTimer
{
public:
  /** \brief Starts timing stage \a name of \a timings. */
  ScopedStageTimer(StageTimings& timings, std::string name)
  : timings_(timings), name_(std::move(name)), start_(std::chrono::steady_clock::now())
  {}

  ScopedStageTimer(const ScopedStageTimer&) = delete;
  ScopedStageTimer&
  operator=(const ScopedStageTimer&) = delete;

  /** \brief Adds the seconds since construction to the stage. */
  ~ScopedStageTimer()
  {
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
    timings_.add(name_, elapsed.count());
  }

private:
  StageTimings& timings_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
};

} // namespace segmat
