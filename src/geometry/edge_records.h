/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Internal helper of src/geometry (not installed): grouping per-edge records.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace segmat {
namespace detail {

/** Sorts records whose first two entries are an edge (smaller vertex, larger vertex), with
 * 0 ≤ vertex < num_vertices, into lexicographic order — the same result as std::sort, in O(n):
 * a counting sort on the first vertex, then an insertion sort inside each (small) bucket.
 */
template <std::size_t N>
void
sortEdgeRecords(std::vector<std::array<int, N>>& records, int num_vertices)
{
  std::vector<int> start(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (const auto& r : records)
    ++start[r[0] + 1];
  for (int v = 0; v < num_vertices; ++v)
    start[v + 1] += start[v];
  std::vector<std::array<int, N>> sorted(records.size());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& r : records)
    sorted[fill[r[0]]++] = r;
  for (int v = 0; v < num_vertices; ++v) {
    auto first = sorted.begin() + start[v], last = sorted.begin() + start[v + 1];
    for (auto it = first; it != last; ++it)
      for (auto jt = it; jt != first && *jt < *(jt - 1); --jt)
        std::iter_swap(jt, jt - 1);
  }
  records.swap(sorted);
}

} // namespace detail
} // namespace segmat
