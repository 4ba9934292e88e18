/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <cstdint>

namespace segmat {
namespace detail {

/// splitmix64's stream increment (2^64 / golden ratio): counter + a · kSplitmixIncrement gives
/// draw a of the stream that \a counter seeds.
constexpr std::uint64_t kSplitmixIncrement = 0x9E3779B97F4A7C15ull;

/** splitmix64 (Steele, Lea, Flood 2014): a well-mixed 64-bit value from a counter. Used where a
 * pseudo-random choice must be the same on every platform, library and thread count (the
 * standard distributions are implementation-defined). */
inline std::uint64_t
splitmix64(std::uint64_t counter)
{
  std::uint64_t z = counter + kSplitmixIncrement;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

} // namespace detail
} // namespace segmat
