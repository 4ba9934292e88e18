/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "bk_max_flow.h"

#include <algorithm>
#include <limits>

namespace segmat {

BkMaxFlow::BkMaxFlow(int num_nodes, const std::vector<std::pair<int, int>>& pairs)
: num_nodes_(num_nodes)
, head_(2 * pairs.size())
, sister_(2 * pairs.size())
, capacity_(2 * pairs.size(), 0.0)
, pair_arc_(pairs.size())
, out_begin_(num_nodes + 1, 0)
, terminal_(num_nodes, 0.0)
, terminal_shared_(num_nodes, 0.0)
, parent_(num_nodes, kFree)
, sink_tree_(num_nodes, 0)
, stamp_(num_nodes, 0)
, dist_(num_nodes, 0)
, active_(num_nodes)
, queued_(num_nodes, 0)
{
  // Arcs grouped by tail (CSR): a node's arcs, their heads and residuals are contiguous.
  for (const auto& p : pairs) {
    ++out_begin_[p.first + 1];
    ++out_begin_[p.second + 1];
  }
  for (int i = 0; i < num_nodes; ++i)
    out_begin_[i + 1] += out_begin_[i];
  std::vector<int> cursor(out_begin_.begin(), out_begin_.end() - 1);
  for (std::size_t e = 0; e < pairs.size(); ++e) {
    const int ab = cursor[pairs[e].first]++, ba = cursor[pairs[e].second]++;
    head_[ab] = pairs[e].second;
    head_[ba] = pairs[e].first;
    sister_[ab] = ba;
    sister_[ba] = ab;
    pair_arc_[e] = ab;
  }
}

void
BkMaxFlow::setTerminals(int i, double from_source, double to_sink)
{
  terminal_[i] = from_source - to_sink;
  terminal_shared_[i] = std::min(from_source, to_sink);
}

void
BkMaxFlow::setPair(std::size_t e, double forward, double backward)
{
  capacity_[pair_arc_[e]] = forward;
  capacity_[sister_[pair_arc_[e]]] = backward;
}

void
BkMaxFlow::activate(int i)
{
  if (queued_[i])
    return;
  queued_[i] = 1;
  active_[(active_head_ + active_count_) % active_.size()] = i;
  ++active_count_;
}

double
BkMaxFlow::augment(int arc)
{
  const auto orphan = [this](int k) {
    parent_[k] = kOrphan;
    orphans_.push_back(k);
  };
  // Bottleneck: the bridge, the source side up to its root, the sink side down to its root.
  double b = residual_[arc];
  int k = tail(arc);
  for (; parent_[k] != kTerminal; k = head_[parent_[k]])
    b = std::min(b, residual_[sister(parent_[k])]);
  b = std::min(b, terminal_residual_[k]);
  for (k = head_[arc]; parent_[k] != kTerminal; k = head_[parent_[k]])
    b = std::min(b, residual_[parent_[k]]);
  b = std::min(b, -terminal_residual_[k]);

  // Push. x − b is exactly 0 where x was the bottleneck, and ≥ 0 elsewhere.
  residual_[arc] -= b;
  residual_[sister(arc)] += b;
  for (k = tail(arc);;) {
    const int a = parent_[k];
    if (a == kTerminal) {
      terminal_residual_[k] -= b;
      if (terminal_residual_[k] == 0.0)
        orphan(k);
      break;
    }
    residual_[sister(a)] -= b; // parent → k carries the flow
    residual_[a] += b;
    if (residual_[sister(a)] == 0.0)
      orphan(k);
    k = head_[a];
  }
  for (k = head_[arc];;) {
    const int a = parent_[k];
    if (a == kTerminal) {
      terminal_residual_[k] += b;
      if (terminal_residual_[k] == 0.0)
        orphan(k);
      break;
    }
    residual_[a] -= b; // k → parent carries the flow
    residual_[sister(a)] += b;
    if (residual_[a] == 0.0)
      orphan(k);
    k = head_[a];
  }
  return b;
}

void
BkMaxFlow::adopt(int i)
{
  constexpr int kInfinite = std::numeric_limits<int>::max();
  const bool sink = sink_tree_[i] != 0;
  // An arc i → j can be i's parent arc when j is in i's tree and flow can reach i from j
  // (source tree) or go from i to j (sink tree).
  const auto carries = [&](int a) { return sink ? residual_[a] > 0.0 : residual_[sister(a)] > 0.0; };
  int best_arc = -1, best_dist = kInfinite;
  for (int a = out_begin_[i]; a < out_begin_[i + 1]; ++a) {
    const int j = head_[a];
    if (parent_[j] == kFree || (sink_tree_[j] != 0) != sink || !carries(a))
      continue;
    // Does j still hang from a terminal? Walk up until a node checked during this
    // augmentation (stamp_ == time_) or the terminal; an orphan on the way means no.
    int d = 0, k = j;
    for (;;) {
      if (stamp_[k] == time_) {
        d += dist_[k];
        break;
      }
      const int pa = parent_[k];
      ++d;
      if (pa == kTerminal) {
        stamp_[k] = time_;
        dist_[k] = 1;
        break;
      }
      if (pa < 0) { // orphan
        d = kInfinite;
        break;
      }
      k = head_[pa];
    }
    if (d == kInfinite)
      continue;
    if (d < best_dist) {
      best_arc = a;
      best_dist = d;
    }
    for (k = j; stamp_[k] != time_; k = head_[parent_[k]]) { // remember the distances found
      stamp_[k] = time_;
      dist_[k] = d--;
    }
  }
  if (best_arc >= 0) {
    parent_[i] = best_arc;
    stamp_[i] = time_;
    dist_[i] = best_dist + 1;
    return;
  }
  // No parent: i leaves its tree. Neighbours that could reach it become active (they may grow
  // into it again), its children become orphans.
  for (int a = out_begin_[i]; a < out_begin_[i + 1]; ++a) {
    const int j = head_[a];
    if (parent_[j] == kFree || (sink_tree_[j] != 0) != sink)
      continue;
    if (carries(a))
      activate(j);
    if (parent_[j] >= 0 && head_[parent_[j]] == i) {
      parent_[j] = kOrphan;
      orphans_.push_back(j);
    }
  }
  parent_[i] = kFree;
}

double
BkMaxFlow::solve()
{
  residual_ = capacity_;
  terminal_residual_ = terminal_;
  double flow = 0.0;
  for (double shared : terminal_shared_)
    flow += shared;
  std::fill(parent_.begin(), parent_.end(), kFree);
  std::fill(sink_tree_.begin(), sink_tree_.end(), 0);
  std::fill(stamp_.begin(), stamp_.end(), 0);
  std::fill(queued_.begin(), queued_.end(), 0);
  time_ = 0;
  active_head_ = active_count_ = 0;
  orphans_.clear();
  // Paths s → i → j → t first, greedily: in expansion moves most of the flow takes them, and
  // each one found by the tree search would cost orphans. Any maximum flow leaves the same
  // reachable set, so this changes no answer.
  for (int i = 0; i < num_nodes_; ++i)
    for (int a = out_begin_[i]; a < out_begin_[i + 1] && terminal_residual_[i] > 0.0; ++a) {
      const int j = head_[a];
      if (terminal_residual_[j] >= 0.0 || residual_[a] <= 0.0)
        continue;
      const double b = std::min({terminal_residual_[i], residual_[a], -terminal_residual_[j]});
      terminal_residual_[i] -= b;
      terminal_residual_[j] += b;
      residual_[a] -= b;
      residual_[sister(a)] += b;
      flow += b;
    }
  for (int i = 0; i < num_nodes_; ++i)
    if (terminal_residual_[i] != 0.0) {
      parent_[i] = kTerminal;
      sink_tree_[i] = terminal_residual_[i] < 0.0;
      dist_[i] = 1;
      activate(i);
    }

  int current = -1; // a node that just led to a path is searched again at once
  while (current >= 0 || active_count_ > 0) {
    int i = current;
    current = -1;
    if (i < 0) {
      i = active_[active_head_];
      active_head_ = (active_head_ + 1) % active_.size();
      --active_count_;
      queued_[i] = 0;
    }
    if (parent_[i] == kFree)
      continue; // left its tree since it was queued
    const bool sink = sink_tree_[i] != 0;
    // Grow i's tree by one layer; stop at the first arc into the other tree.
    int bridge = -1; // arc from the source tree into the sink tree
    for (int a = out_begin_[i]; a < out_begin_[i + 1]; ++a) {
      if ((sink ? residual_[sister(a)] : residual_[a]) <= 0.0)
        continue;
      const int j = head_[a];
      if (parent_[j] == kFree) {
        parent_[j] = sister(a);
        sink_tree_[j] = sink;
        stamp_[j] = stamp_[i];
        dist_[j] = dist_[i] + 1;
        activate(j);
      } else if ((sink_tree_[j] != 0) != sink) {
        bridge = sink ? sister(a) : a;
        break;
      } else if (stamp_[j] <= stamp_[i] && dist_[j] > dist_[i]) {
        // j is known to be farther from the terminal than through i: hang it from i (shorter
        // trees make fewer, cheaper orphans).
        parent_[j] = sister(a);
        stamp_[j] = stamp_[i];
        dist_[j] = dist_[i] + 1;
      }
    }
    if (bridge < 0)
      continue; // i is passive now
    ++time_;
    flow += augment(bridge);
    for (std::size_t o = 0; o < orphans_.size(); ++o) // FIFO; adopt() may append
      adopt(orphans_[o]);
    orphans_.clear();
    current = i;
  }
  return flow;
}

} // namespace segmat
