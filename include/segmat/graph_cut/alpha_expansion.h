/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace segmat {

/** \brief An undirected edge of a labelling problem with a Potts cost: cutting it (giving its two
 * ends different labels) costs \a weight, whatever the two labels are.
 */
struct PottsEdge
{
  int a = -1;          ///< one end (node index)
  int b = -1;          ///< other end (node index)
  double weight = 0.0; ///< cost paid when label(a) != label(b); finite and >= 0
};

/** \brief The Potts energy Σ_i unary(i, l_i) + Σ_{(a,b,w)} w·[l_a ≠ l_b] of \a labels (one label
 * per row of \a unary; not validated).
 */
double
computePottsEnergy(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                   const std::vector<int>& labels);

/** \brief Multi-label energy minimisation by α-expansion (Boykov, Veksler, Zabih, "Fast
 * approximate energy minimization via graph cuts", IEEE TPAMI 23(11), 2001).
 *
 * Minimises E(l) = Σ_i D(i, l_i) + Σ_{(a,b,w)} w·[l_a ≠ l_b] over labellings l. This Potts model
 * with a weight per edge is exactly the energy of SEG-MAT's surface transfer (Lin et al. 2022,
 * §5), whose smoothness depends on the edge only. Each expansion move is
 * one s–t minimum cut solved with segmat::BkMaxFlow (Boykov–Kolmogorov); the result is a local
 * minimum for every expansion move and, with non-negative unary costs, within a factor 2 of the
 * global optimum (Potts).
 *
 * The class knows nothing of meshes: it takes nodes, labels, unary costs and weighted edges.
 * Differences from the reference (GCO v3, `expansion(2)`):
 *  - the initial labelling is the per-node argmin of the unary costs (ties: the smaller label),
 *    not "all 0" — it starts closer to the optimum, so fewer moves are needed — unless the
 *    caller gives one;
 *  - cycles over the labels 0..L−1 (fixed order, deterministic) repeat until a whole cycle
 *    lowers the energy no further, or until getMaxCycles() cycles have run;
 *  - a move is kept only when it lowers the energy strictly, which guarantees termination.
 * Capacities are doubles; integer-valued costs (as the transfer uses) are therefore exact.
 */
class AlphaExpansion
{
public:
  using Ptr = std::shared_ptr<AlphaExpansion>;
  using ConstPtr = std::shared_ptr<const AlphaExpansion>;

  /** \brief Empty problem; at most 100 cycles (convergence comes long before on real data). */
  AlphaExpansion();

  /** \brief Unary (data) costs: one row per node, one column per label. Finite values. */
  void
  setUnaryCosts(const Eigen::MatrixXd& costs);

  /** \brief The unary costs as given. */
  const Eigen::MatrixXd&
  getUnaryCosts() const
  {
    return unary_;
  }

  /** \brief Pairwise Potts edges. Self-loops are ignored; parallel edges add up. */
  void
  setEdges(std::vector<PottsEdge> edges);

  /** \brief The edges as given. */
  const std::vector<PottsEdge>&
  getEdges() const
  {
    return edges_;
  }

  /** \brief Largest number of expansion cycles (one move per label each); values < 1 are
   * ignored with a warning. The reference ran 2; the default 100 means "until converged".
   */
  void
  setMaxCycles(int cycles);

  /** \brief Largest number of expansion cycles. */
  int
  getMaxCycles() const
  {
    return max_cycles_;
  }

  /** \brief Minimise the energy.
   * \param[out] labels one label in [0, L) per node (empty on failure or with no nodes)
   * \return false (with PCL_ERROR) when there are no labels, a cost is not finite, an edge index
   *         is out of range or a weight is negative or not finite.
   */
  bool
  compute(std::vector<int>& labels);

  /** \brief Minimise the energy from \a initial instead of the unary argmin: a labelling close
   * to the optimum (the solution of a similar problem) needs fewer moves. Without edges, or
   * with one label, the unary argmin is the exact optimum and is returned whatever the start.
   * \param[in] initial one label in [0, L) per node; empty starts from the unary argmin
   * \param[out] labels as compute(labels); also false when \a initial has the wrong size or a
   *             label out of range
   */
  bool
  compute(std::vector<int> initial, std::vector<int>& labels);

  /** \brief Energy of \a labels under the current costs (computePottsEnergy). */
  double
  energy(const std::vector<int>& labels) const
  {
    return computePottsEnergy(unary_, edges_, labels);
  }

  /** \brief Energy reached by the last compute(). */
  double
  getEnergy() const
  {
    return energy_;
  }

  /** \brief Cycles run by the last compute() (0 when the initial labelling was already final
   * for every move, e.g. without edges).
   */
  int
  getCycles() const
  {
    return cycles_;
  }

  /** \brief Expansion moves (max-flow problems) solved by the last compute(). */
  int
  getMoves() const
  {
    return moves_;
  }

private:
  bool
  validate() const;

  Eigen::MatrixXd unary_;
  std::vector<PottsEdge> edges_;
  int max_cycles_;
  double energy_;
  int cycles_;
  int moves_;
};

} // namespace segmat
