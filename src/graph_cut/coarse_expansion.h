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

/** \brief What coarseToFineExpansion() did. */
struct CoarseExpansion
{
  int clusters = 0;   ///< nodes of the coarse problem
  int free_nodes = 0; ///< nodes of the fine problem that were free to change
  int cycles = 0;     ///< α-expansion cycles of the coarse problem
};

/** \brief A Potts labelling of a graph too large to expand whole (a scanned mesh's faces).
 *
 * The nodes are grouped into connected clusters of about \a cluster_size nodes (breadth-first,
 * in node order); the clusters are labelled by α-expansion of the summed problem (a cluster's
 * unary costs are its nodes' sums, an edge between two clusters weighs the sum of the edges
 * between them), which places every boundary to within a cluster. Then the nodes of the
 * clusters within three clusters of a boundary are labelled again at full resolution, from the
 * coarse labels and with every other node held (relabelFreeNodes()), so that the boundaries
 * follow the fine edges. The result is deterministic: no step depends on threads.
 * \param[in] cluster_size nodes per cluster (at least 2)
 * \param[out] labels one per node
 * \return false (with PCL_ERROR) when an α-expansion fails
 */
bool
coarseToFineExpansion(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                      int cluster_size, int max_cycles, std::vector<int>& labels,
                      CoarseExpansion* report = nullptr);

} // namespace detail
} // namespace segmat
