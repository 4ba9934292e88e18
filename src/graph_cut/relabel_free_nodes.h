/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/graph_cut/alpha_expansion.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Minimises the Potts energy of \a unary and \a edges over the labels of the nodes
 * marked in \a is_free only, every other node held at its label in \a labels: a held neighbour
 * adds its edge's weight to each label of a free node but its own, and the free nodes are
 * labelled by α-expansion (at most \a max_cycles cycles), starting from the argmin of those
 * costs or, with \a from_labels, from their labels on entry. Relabelling a few nodes so costs
 * a cut of the few nodes, not of the whole graph.
 * \param[in,out] labels one per node: the held nodes' labels in [0, unary.cols()) on entry
 *                (the free nodes' are ignored unless \a from_labels); every node's label on
 *                return
 * \return false (with PCL_ERROR, \a labels unchanged) when the α-expansion fails
 */
bool
relabelFreeNodes(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                 const std::vector<char>& is_free, int max_cycles, std::vector<int>& labels,
                 bool from_labels = false);

} // namespace detail
} // namespace segmat
