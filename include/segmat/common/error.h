/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <stdexcept>
#include <string>

namespace segmat {

/** \brief The one exception type segmat throws: bad files and bad command-line input.
 *
 * File readers throw it with the file's path and the 1-based line where the problem was found
 * (0 when no line applies: a missing file, binary junk, a count that does not match). Algorithm
 * classes never throw; they follow PCL: PCL_ERROR, an empty output and `false`.
 */
class Error : public std::runtime_error
{
public:
  /** \brief Error about a file.
   * \param[in] path the file
   * \param[in] line 1-based line number, 0 when none applies
   * \param[in] message what is wrong, in plain words
   */
  Error(const std::string& path, long line, const std::string& message);

  /** \brief Error not tied to a file. */
  explicit Error(const std::string& message);

  /** \brief The file the error is about ("" when none). */
  const std::string&
  path() const noexcept
  {
    return path_;
  }

  /** \brief 1-based line of the problem, 0 when none applies. */
  long
  line() const noexcept
  {
    return line_;
  }

  /** \brief The message without the "path:line: " prefix. */
  const std::string&
  message() const noexcept
  {
    return message_;
  }

private:
  std::string path_;
  long line_ = 0;
  std::string message_;
};

} // namespace segmat
