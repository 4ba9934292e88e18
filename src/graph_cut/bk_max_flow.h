/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <utility>
#include <vector>

namespace segmat {

/** \brief s–t minimum cut of a fixed network whose capacities change between solves, by the
 * augmenting-path algorithm of Boykov and Kolmogorov ("An experimental comparison of
 * min-cut/max-flow algorithms for energy minimization in vision", IEEE TPAMI 26(9), 2004).
 *
 * Written for the expansion moves of segmat::AlphaExpansion: the topology (nodes and arc pairs)
 * is given once, each move sets the capacities and solves. Boost's generic
 * boykov_kolmogorov_max_flow took about three quarters of the cloud transfer; this one keeps
 * terminal arcs as one signed residual per node and arcs in flat arrays.
 *
 * The source side returned by inSourceSet() is the set of nodes reachable from the source in the
 * final residual graph — the smallest minimum-cut source side, the same for every maximum flow,
 * so the answer does not depend on the search order. Capacities are doubles: integer-valued
 * ones (as the transfer uses) are exact.
 */
class BkMaxFlow
{
public:
  /** \brief \a num_nodes nodes and one arc pair (a→b, b→a) per entry of \a pairs. */
  BkMaxFlow(int num_nodes, const std::vector<std::pair<int, int>>& pairs);

  /** \brief Terminal capacities of node \a i: source→i is \a from_source, i→sink \a to_sink
   * (both >= 0). Only their difference matters to the cut; the flow value counts both.
   */
  void
  setTerminals(int i, double from_source, double to_sink);

  /** \brief Capacities of pair \a e: a→b gets \a forward, b→a \a backward (both >= 0). */
  void
  setPair(std::size_t e, double forward, double backward = 0.0);

  /** \brief Maximum flow for the current capacities (capacities are kept: solve again freely). */
  double
  solve();

  /** \brief After solve(): node \a i is reachable from the source in the residual graph. */
  bool
  inSourceSet(int i) const
  {
    return parent_[i] != kFree && !sink_tree_[i];
  }

private:
  static constexpr int kFree = -1;     ///< in no tree
  static constexpr int kTerminal = -2; ///< child of its terminal
  static constexpr int kOrphan = -3;   ///< lost its parent arc in the last augmentation

  int
  tail(int arc) const
  {
    return head_[sister(arc)];
  }
  int
  sister(int arc) const
  {
    return sister_[arc];
  }
  void
  activate(int i);
  /** Saturates the path source ⇝ tail(arc) → head(arc) ⇝ sink; queues the new orphans. */
  double
  augment(int arc);
  /** Finds orphan \a i a new parent in its tree, or frees it. */
  void
  adopt(int i);

  int num_nodes_;
  // Arcs grouped by tail: node i's are out_begin_[i] .. out_begin_[i + 1] − 1.
  std::vector<int> head_, sister_;
  std::vector<double> capacity_, residual_;
  std::vector<int> pair_arc_; ///< arc a→b of each pair
  std::vector<int> out_begin_;
  std::vector<double> terminal_;          ///< source→i minus i→sink as set
  std::vector<double> terminal_residual_; ///< > 0: residual from the source; < 0: to the sink
  std::vector<double> terminal_shared_;   ///< min(source→i, i→sink): flow that bypasses the cut
  // Search trees.
  std::vector<int> parent_; ///< arc from the node to its parent, or kFree/kTerminal/kOrphan
  std::vector<char> sink_tree_;
  std::vector<long> stamp_; ///< when dist_ was last known to be exact
  std::vector<int> dist_;   ///< arcs to the terminal (heuristic; exact at stamp_)
  long time_ = 0;
  std::vector<int> active_; ///< ring buffer of active nodes
  std::vector<char> queued_;
  std::size_t active_head_ = 0, active_count_ = 0;
  std::vector<int> orphans_;
};

} // namespace segmat
