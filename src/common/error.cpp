/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>

namespace segmat {
namespace {
std::string
format(const std::string& path, long line, const std::string& message)
{
  if (path.empty())
    return message;
  return line > 0 ? path + ":" + std::to_string(line) + ": " + message : path + ": " + message;
}
} // namespace

Error::Error(const std::string& path, long line, const std::string& message)
: std::runtime_error(format(path, line, message)), path_(path), line_(line), message_(message)
{}

Error::Error(const std::string& message) : std::runtime_error(message), message_(message) {}

} // namespace segmat
