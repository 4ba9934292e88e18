/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/medial: the priority queue of Q-MAT's edge collapses.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace segmat {
namespace qmat {

/** A collapse candidate's place in the queue: tier, then cost, then the edge's endpoint indices
 * (deterministic ties). */
struct QueueKey
{
  double cost = 0.0;
  int lo = 0, hi = 0;
  std::uint8_t tier = 0; ///< 0: normal; 1: every candidate flips a triangle (deferred)

  bool
  operator<(const QueueKey& o) const
  {
    if (tier != o.tier)
      return tier < o.tier;
    if (cost != o.cost)
      return cost < o.cost;
    if (lo != o.lo)
      return lo < o.lo;
    return hi < o.hi;
  }
};

/** Indexed 4-ary min-heap of edges: one entry per edge, keys updated in place, so the heap never
 * holds stale entries and stays no larger than the number of live edges. */
class EdgeHeap
{
public:
  /** Builds the heap of edges 0..keys.size()−1 at once (Floyd: O(n), where inserting one by
   * one sifted each key up). Keys are distinct (they end in the edge's ends), so the order of
   * pops is that of the keys whatever the layout. */
  void
  build(const std::vector<QueueKey>& keys)
  {
    const int n = static_cast<int>(keys.size());
    pos_.assign(keys.size(), -1);
    nodes_.resize(keys.size());
    for (int e = 0; e < n; ++e) {
      nodes_[e] = {keys[e], e};
      pos_[e] = e;
    }
    for (int i = n / 4; i >= 0; --i)
      if (i < n)
        siftDown(i);
  }

  bool empty() const { return nodes_.empty(); }
  int topEdge() const { return nodes_.front().edge; }
  const QueueKey& topKey() const { return nodes_.front().key; }

  /** Inserts edge e or changes its key. */
  void
  set(int e, const QueueKey& key)
  {
    if (pos_[e] < 0) {
      pos_[e] = static_cast<int>(nodes_.size());
      nodes_.push_back({key, e});
      siftUp(pos_[e]);
      return;
    }
    const int i = pos_[e];
    const bool up = key < nodes_[i].key;
    nodes_[i].key = key;
    if (up)
      siftUp(i);
    else
      siftDown(i);
  }

  /** Removes edge e if present. */
  void
  erase(int e)
  {
    const int i = pos_[e];
    if (i < 0)
      return;
    pos_[e] = -1;
    const Node last = nodes_.back();
    nodes_.pop_back();
    if (i == static_cast<int>(nodes_.size()))
      return;
    nodes_[i] = last;
    pos_[last.edge] = i;
    if (i > 0 && last.key < nodes_[(i - 1) / 4].key)
      siftUp(i);
    else
      siftDown(i);
  }

private:
  struct Node
  {
    QueueKey key;
    int edge;
  };

  void
  siftUp(int i)
  {
    const Node n = nodes_[i];
    while (i > 0) {
      const int parent = (i - 1) / 4;
      if (!(n.key < nodes_[parent].key))
        break;
      nodes_[i] = nodes_[parent];
      pos_[nodes_[i].edge] = i;
      i = parent;
    }
    nodes_[i] = n;
    pos_[n.edge] = i;
  }

  void
  siftDown(int i)
  {
    const Node n = nodes_[i];
    const int size = static_cast<int>(nodes_.size());
    for (;;) {
      const int first = 4 * i + 1;
      if (first >= size)
        break;
      int best = first;
      const int last = std::min(first + 4, size);
      for (int c = first + 1; c < last; ++c)
        if (nodes_[c].key < nodes_[best].key)
          best = c;
      if (!(nodes_[best].key < n.key))
        break;
      nodes_[i] = nodes_[best];
      pos_[nodes_[i].edge] = i;
      i = best;
    }
    nodes_[i] = n;
    pos_[n.edge] = i;
  }

  std::vector<Node> nodes_;
  std::vector<int> pos_;
};

} // namespace qmat
} // namespace segmat
