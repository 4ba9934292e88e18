/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace segmat {
namespace io {

/** \brief Writes a file whole or not at all.
 *
 * \a write fills a stream on a temporary file beside \a path (`path.tmpPID`); only when it
 * returns and the stream is good is the temporary renamed over \a path (atomic on POSIX). On any
 * failure the temporary is removed, \a path is left as it was, and segmat::Error names the path.
 * While it exists the temporary is registered for removal on SIGINT / SIGTERM (see
 * removeTemporariesOnSignal).
 */
void
writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                    bool binary = false);

/** \brief Same, for writers that only take a file name (PCL's savers): \a write gets the
 * temporary's path and returns true on success.
 */
void
writeFileAtomicallyByName(const std::string& path,
                          const std::function<bool(const std::string& tmp_path)>& write);

/** \brief Lower-case extension without the dot ("off" for "a/b.OFF"); "" when none. */
std::string
extensionOf(const std::string& path);

/** \brief Checks that \a path can be written as an output, before any work is done.
 *
 * Throws segmat::Error naming \a path when it is (after following links, or as a hard link)
 * one of \a inputs, when it names a directory or ends in '/', when it exists and is not a
 * regular file (a device such as /dev/full, a pipe), when it exists and is not writable, or when
 * its directory does not exist or is not writable.
 */
void
checkOutputPath(const std::string& path, const std::vector<std::string>& inputs);

/** \brief Removes `path.tmpPID` (and `path.tmpPID.tmpPID`) left by processes that no longer run
 * (a killed run); temporaries of live processes are left alone.
 * \return the number of files removed */
int
removeStaleTemporaries(const std::string& path);

/** \brief Installs SIGINT / SIGTERM / SIGHUP handlers that remove every registered temporary
 * and then end the process with the signal's usual status. Idempotent. */
void
removeTemporariesOnSignal();

/** \brief The outputs of one run, written together: all or none.
 *
 * add() checks each output location up front (checkOutputPath against the run's inputs) and
 * clears stale temporaries of killed runs; temporary() gives the path a writer should write
 * to; commit() renames every temporary onto its output with SIGINT / SIGTERM blocked, so an
 * interrupted run leaves all outputs or none (SIGKILL or a power cut between two renames can
 * still leave some). Uncommitted temporaries are removed by the destructor and on signals.
 */
class OutputSet
{
public:
  /** \param[in] inputs files the run reads: no output may replace one */
  explicit OutputSet(std::vector<std::string> inputs = {});
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet&
  operator=(const OutputSet&) = delete;

  /** \brief Declares an output file; throws segmat::Error when it cannot be written. */
  void
  add(const std::string& path);

  /** \brief Where to write output \a path (declared by add) before commit(). */
  std::string
  temporary(const std::string& path) const;

  /** \brief Moves every temporary onto its output; throws segmat::Error naming a file that is
   * missing or cannot be renamed (the temporaries are then removed). */
  void
  commit();

  /** \brief The declared outputs, in the order of add(). */
  const std::vector<std::string>&
  paths() const
  {
    return paths_;
  }

private:
  std::vector<std::string> inputs_, paths_;
  bool committed_ = false;
};

} // namespace io
} // namespace segmat
