/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "qmat_cycle_span.h"

#include <algorithm>

namespace segmat {
namespace qmat {

void
Gf2Span::reset(std::size_t bits)
{
  words_ = (bits + 63) / 64;
  rows_.clear();
  lead_row_.assign(bits, -1);
  scratch_.assign(words_, 0);
}

std::uint64_t*
Gf2Span::scratch()
{
  std::fill(scratch_.begin(), scratch_.end(), 0);
  return scratch_.data();
}

void
Gf2Span::insertScratch()
{
  const long h = reduce();
  if (h < 0)
    return;
  lead_row_[h] = static_cast<long>(rows_.size() / words_);
  rows_.insert(rows_.end(), scratch_.begin(), scratch_.end());
}

long
Gf2Span::reduce()
{
  for (;;) {
    long h = -1;
    for (std::size_t w = words_; w-- > 0;)
      if (scratch_[w]) {
        h = static_cast<long>(w * 64 + 63 - __builtin_clzll(scratch_[w]));
        break;
      }
    if (h < 0 || lead_row_[h] < 0)
      return h;
    const std::uint64_t* row = rows_.data() + lead_row_[h] * words_;
    for (std::size_t w = 0; w < words_; ++w)
      scratch_[w] ^= row[w];
  }
}

} // namespace qmat
} // namespace segmat
