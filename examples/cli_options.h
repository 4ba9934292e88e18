/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Option parsing and stage timing shared by the command-line programs (not installed).

#include <segmat/common/error.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>

namespace segmat {
namespace cli {

/** A finite number, or segmat::Error naming the option. */
inline double
parseNumber(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    throw Error("option " + option + ": '" + text + "' is not a number");
  return value;
}

/** A finite number >= 0. */
inline double
parseNonNegative(const std::string& option, const std::string& text)
{
  const double value = parseNumber(option, text);
  if (value < 0.0)
    throw Error("option " + option + ": '" + text + "' is not a number >= 0");
  return value;
}

/** --max-bend: an angle in degrees in (0, 90] (MatRegionGrowing::setMaxBendAngle). */
inline double
parseBendAngle(const std::string& option, const std::string& text)
{
  const double value = parseNumber(option, text);
  if (!(value > 0.0) || value > 90.0)
    throw Error("option " + option + ": '" + text + "' is not an angle in (0, 90] degrees");
  return value;
}

/** A whole number >= lowest (and <= 1e9). */
inline long
parseInteger(const std::string& option, const std::string& text, long lowest)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || value < lowest || value > 1000000000L)
    throw Error("option " + option + ": '" + text + "' is not an integer >= " +
                std::to_string(lowest));
  return value;
}

/** Seconds since \a start; restarts the clock. */
inline double
secondsSince(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - start).count();
  start = now;
  return s;
}

} // namespace cli
} // namespace segmat
