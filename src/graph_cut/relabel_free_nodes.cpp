/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "relabel_free_nodes.h"

namespace segmat {
namespace detail {

bool
relabelFreeNodes(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                 const std::vector<char>& is_free, int max_cycles, std::vector<int>& labels,
                 bool from_labels)
{
  std::vector<int> index(labels.size(), -1), nodes; // node → its row among the free nodes
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (is_free[i]) {
      index[i] = static_cast<int>(nodes.size());
      nodes.push_back(static_cast<int>(i));
    }
  if (nodes.empty())
    return true;
  Eigen::MatrixXd costs(static_cast<Eigen::Index>(nodes.size()), unary.cols());
  for (std::size_t f = 0; f < nodes.size(); ++f)
    costs.row(static_cast<Eigen::Index>(f)) = unary.row(nodes[f]);
  std::vector<PottsEdge> free_edges;
  for (const PottsEdge& e : edges) {
    const int fa = index[e.a], fb = index[e.b];
    if (fa >= 0 && fb >= 0) {
      free_edges.push_back({fa, fb, e.weight});
    } else if (fa >= 0 || fb >= 0) { // cut unless the free end takes the held end's label
      const Eigen::Index row = fa >= 0 ? fa : fb;
      costs.row(row).array() += e.weight;
      costs(row, labels[fa >= 0 ? e.b : e.a]) -= e.weight;
    }
  }
  AlphaExpansion solver;
  solver.setMaxCycles(max_cycles);
  solver.setUnaryCosts(costs);
  solver.setEdges(std::move(free_edges));
  std::vector<int> initial, free_labels;
  if (from_labels)
    for (const int i : nodes)
      initial.push_back(labels[i]);
  if (!solver.compute(std::move(initial), free_labels))
    return false;
  for (std::size_t f = 0; f < nodes.size(); ++f)
    labels[nodes[f]] = free_labels[f];
  return true;
}

} // namespace detail
} // namespace segmat
