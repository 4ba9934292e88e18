/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/medial: the mod-2 linear algebra of Q-MAT's topology test.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace segmat {
namespace qmat {

/** Incremental span of GF(2) vectors (echelon form keyed by leading bit), flat storage. Used to
 * decide whether a cycle is a sum of triangle boundaries (a mod-2 boundary). */
class Gf2Span
{
public:
  /** Empties the span; vectors have \a bits entries. */
  void reset(std::size_t bits);

  /** The zeroed working vector to fill with flip(). */
  std::uint64_t* scratch();

  static void
  flip(std::uint64_t* v, std::size_t bit)
  {
    v[bit / 64] ^= std::uint64_t(1) << (bit % 64);
  }

  /** Adds the working vector to the span. */
  void insertScratch();

  /** True when the working vector is in the span. */
  bool scratchInSpan() { return reduce() < 0; }

private:
  /** Reduces the working vector by the rows; returns its leading bit (-1: zero). */
  long reduce();

  std::size_t words_ = 0;
  std::vector<std::uint64_t> rows_;
  std::vector<long> lead_row_;
  std::vector<std::uint64_t> scratch_;
};

} // namespace qmat
} // namespace segmat
