/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "text_file.h"

#include "file_headers.h"

#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <ostream>

namespace segmat {
namespace io {
namespace detail {
namespace {
bool
isBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view
trim(std::string_view s)
{
  while (!s.empty() && isBlank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back()))
    s.remove_suffix(1);
  return s;
}

// Text files hold printable bytes, blanks and line breaks; anything else below 0x20 (NUL above
// all) means a binary file was passed. Bytes >= 0x80 are allowed (UTF-8 comments).
bool
isBinaryByte(unsigned char c)
{
  return (c < 0x20 && c != '\n' && !isBlank(static_cast<char>(c))) || c == 0x7f;
}
} // namespace

bool
Tokens::next(std::string_view& token)
{
  std::size_t i = 0;
  while (i < rest_.size() && isBlank(rest_[i]))
    ++i;
  if (i == rest_.size()) {
    rest_ = {};
    return false;
  }
  std::size_t j = i;
  while (j < rest_.size() && !isBlank(rest_[j]))
    ++j;
  token = rest_.substr(i, j - i);
  rest_.remove_prefix(j);
  return true;
}

std::size_t
Tokens::remaining() const
{
  Tokens copy = *this;
  std::size_t n = 0;
  std::string_view t;
  while (copy.next(t))
    ++n;
  return n;
}

TextFile::TextFile(const std::string& path, const char* format_name, bool hash_comments)
: path_(path), format_name_(format_name), hash_comments_(hash_comments)
{
  requireRegularFile(path);
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if (!in)
    throw Error(path, 0, "cannot open the file (missing or unreadable)");
  text_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad())
    throw Error(path, 0, "read error");
  // A UTF-8 byte-order mark is harmless text editors add; skip it.
  if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0)
    pos_ = 3;
  long line = 1;
  for (std::size_t i = pos_; i < text_.size(); ++i) {
    const auto c = static_cast<unsigned char>(text_[i]);
    if (c == '\n')
      ++line;
    else if (isBinaryByte(c)) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throw Error(path, line,
                  std::string("binary data (byte ") + hex + "): not a text " + format_name_ +
                      " file");
    }
  }
}

bool
TextFile::nextLine(std::string_view& line)
{
  const std::string_view all(text_);
  while (pos_ < all.size()) {
    const std::size_t end = all.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? all.size() : end;
    std::string_view raw = all.substr(pos_, stop - pos_);
    pos_ = end == std::string_view::npos ? all.size() : end + 1;
    ++line_number_;
    if (hash_comments_) {
      const std::size_t hash = raw.find('#');
      if (hash != std::string_view::npos)
        raw = raw.substr(0, hash);
    }
    raw = trim(raw);
    if (!raw.empty()) {
      line = raw;
      return true;
    }
  }
  return false;
}

void
TextFile::fail(const std::string& message) const
{
  throw Error(path_, line_number_, message);
}

void
TextFile::failFile(const std::string& message) const
{
  throw Error(path_, 0, message);
}

namespace {
// Parses the whole token with std::from_chars. Returns "" on success, else the complaint.
template <typename Number>
const char*
parseWhole(std::string_view token, Number& value, const char* not_a_number)
{
  // from_chars rejects a leading '+', which some writers emit.
  if (token.size() > 1 && token[0] == '+' && token[1] != '-')
    token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range)
    return "is out of range";
  if (ec != std::errc() || end != token.data() + token.size())
    return not_a_number;
  return "";
}
} // namespace

bool
isNumber(std::string_view token)
{
  double value = 0.0;
  return *parseWhole(token, value, "-") == '\0';
}

double
TextFile::parseFinite(std::string_view token, const char* what) const
{
  double value = 0.0;
  const char* complaint = parseWhole(token, value, "is not a number");
  if (*complaint == '\0' && !std::isfinite(value))
    complaint = "is not finite";
  if (*complaint != '\0')
    fail(std::string(what) + " " + quoted(token) + " " + complaint);
  return value;
}

long
TextFile::parseLong(std::string_view token, const char* what) const
{
  long value = 0;
  const char* complaint = parseWhole(token, value, "is not an integer");
  if (*complaint != '\0')
    fail(std::string(what) + " " + quoted(token) + " " + complaint);
  return value;
}

int
TextFile::parseInt(std::string_view token, const char* what) const
{
  const long value = parseLong(token, what);
  if (value < -2147483647L - 1 || value > 2147483647L)
    fail(std::string(what) + " " + quoted(token) + " is out of range");
  return static_cast<int>(value);
}

std::string_view
TextFile::require(Tokens& tokens, const std::string& context, const char* what) const
{
  std::string_view token;
  if (!tokens.next(token))
    fail(context + ": missing " + what);
  return token;
}

void
appendDouble(std::string& out, double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void
appendInt(std::string& out, long value)
{
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void
writeTextAtomically(const std::string& path, const std::string& text)
{
  writeFileAtomically(path, [&](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

void
checkMeshForWriting(const std::string& path, const TriangleMesh& mesh)
{
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite())
      throw Error(path, 0, "not written: vertex " + std::to_string(v) + " is not finite");
  const long n = static_cast<long>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces[f][k] < 0 || mesh.faces[f][k] >= n)
        throw Error(path, 0,
                    "not written: face " + std::to_string(f) + " refers to vertex " +
                        std::to_string(mesh.faces[f][k]) + " of " + std::to_string(n));
}

std::string
quoted(std::string_view token)
{
  constexpr std::size_t max_shown = 40;
  if (token.size() > max_shown)
    return "'" + std::string(token.substr(0, max_shown)) + "...'";
  return "'" + std::string(token) + "'";
}

} // namespace detail
} // namespace io
} // namespace segmat
