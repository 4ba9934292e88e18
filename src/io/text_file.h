/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Private to src/io: the line reader, number parsing and number formatting that the OFF, SEG and
// MA readers and writers share. Whole-file read + std::from_chars: no iostream per token (a
// 30k-face OFF parses in a few milliseconds) and no dependence on the C locale's decimal point.

#include <segmat/geometry/triangle_mesh.h>

#include <string>
#include <string_view>

namespace segmat {
namespace io {
namespace detail {

/** \brief Splits one line into whitespace-separated tokens. */
class Tokens
{
public:
  explicit Tokens(std::string_view line) : rest_(line)
  {
  }

  /** \brief Next token; false when the line is used up. */
  bool
  next(std::string_view& token);

  /** \brief Number of tokens not yet taken. */
  std::size_t
  remaining() const;

private:
  std::string_view rest_;
};

/** \brief A whole text file held in memory and walked line by line, with 1-based line numbers
 * for every error. */
class TextFile
{
public:
  /** \brief Reads \a path.
   * \param[in] path the file
   * \param[in] format_name used in messages ("OFF", "SEG", "MA")
   * \param[in] hash_comments when true, everything from '#' to the end of a line is dropped
   * \throws segmat::Error for a missing or unreadable file and for binary data (NUL or other
   *         control bytes), naming the line where it starts.
   */
  TextFile(const std::string& path, const char* format_name, bool hash_comments);

  /** \brief Next line with content, trimmed of CR, comments and surrounding blanks; false at EOF.
   */
  bool
  nextLine(std::string_view& line);

  /** \brief 1-based number of the line last returned by nextLine (0 before the first). */
  long
  lineNumber() const
  {
    return line_number_;
  }

  /** \brief Size of the file in bytes. */
  std::size_t
  size() const
  {
    return text_.size();
  }

  const std::string&
  path() const
  {
    return path_;
  }

  /** \brief Throws segmat::Error(path, current line, message). */
  [[noreturn]] void
  fail(const std::string& message) const;

  /** \brief Throws segmat::Error(path, 0, message): problems of the file as a whole. */
  [[noreturn]] void
  failFile(const std::string& message) const;

  /** \brief Parses a whole token as a finite double; fails naming \a what otherwise. */
  double
  parseFinite(std::string_view token, const char* what) const;

  /** \brief Parses a whole token as an int; fails naming \a what otherwise. */
  int
  parseInt(std::string_view token, const char* what) const;

  /** \brief Parses a whole token as a long; fails naming \a what otherwise. */
  long
  parseLong(std::string_view token, const char* what) const;

  /** \brief Takes the next token of \a tokens, failing with "\a context: missing \a what". */
  std::string_view
  require(Tokens& tokens, const std::string& context, const char* what) const;

private:
  std::string path_;
  std::string format_name_;
  std::string text_;
  std::size_t pos_ = 0;
  long line_number_ = 0;
  bool hash_comments_;
};

/** \brief Shortest decimal text that reads back to exactly \a value (std::to_chars). */
void
appendDouble(std::string& out, double value);

/** \brief Decimal text of \a value. */
void
appendInt(std::string& out, long value);

/** \brief Appends a number: shortest round-trip text for doubles, decimal for integers. */
inline void
appendNumber(std::string& out, double value)
{
  appendDouble(out, value);
}
inline void
appendNumber(std::string& out, long value)
{
  appendInt(out, value);
}
inline void
appendNumber(std::string& out, int value)
{
  appendInt(out, value);
}

/** \brief Appends one line: \a first (a tag such as "v", or "" for none), then the values of
 * \a values (anything with size() and operator[]) separated by single spaces, then '\n'. */
template <typename Values>
void
appendLine(std::string& out, std::string_view first, const Values& values)
{
  out += first;
  for (int k = 0; k < static_cast<int>(values.size()); ++k) {
    if (k > 0 || !first.empty())
      out += ' ';
    appendNumber(out, values[k]);
  }
  out += '\n';
}

/** \brief Writes \a text to \a path whole or not at all (io::writeFileAtomically). */
void
writeTextAtomically(const std::string& path, const std::string& text);

/** \brief Refuses (segmat::Error naming \a path) a mesh no reader would take back: a non-finite
 * coordinate or a face index out of range. Writers call it before touching the file. */
void
checkMeshForWriting(const std::string& path, const TriangleMesh& mesh);

/** \brief True when the whole \a token is a number (std::from_chars; a leading '+' allowed;
 * "nan" and "inf" count). */
bool
isNumber(std::string_view token);

/** \brief Token quoted for a message, cut to a readable length. */
std::string
quoted(std::string_view token);

} // namespace detail
} // namespace io
} // namespace segmat
