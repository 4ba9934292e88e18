/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/graph_cut/alpha_expansion.h>
#include "bk_max_flow.h"

#include <pcl/console/print.h>


#include <cmath>
#include <utility>

namespace segmat {

AlphaExpansion::AlphaExpansion() : max_cycles_(100), energy_(0.0), cycles_(0), moves_(0) {}

void
AlphaExpansion::setUnaryCosts(const Eigen::MatrixXd& costs)
{
  unary_ = costs;
}

void
AlphaExpansion::setEdges(std::vector<PottsEdge> edges)
{
  edges_ = std::move(edges);
}

void
AlphaExpansion::setMaxCycles(int cycles)
{
  if (cycles < 1) {
    PCL_WARN("[segmat::AlphaExpansion::setMaxCycles] %d < 1 ignored, keeping %d.\n", cycles,
             max_cycles_);
    return;
  }
  max_cycles_ = cycles;
}

bool
AlphaExpansion::validate() const
{
  if (unary_.rows() > 0 && unary_.cols() == 0) {
    PCL_ERROR("[segmat::AlphaExpansion::compute] no labels (the unary cost matrix has 0 "
              "columns).\n");
    return false;
  }
  if (!unary_.allFinite()) {
    PCL_ERROR("[segmat::AlphaExpansion::compute] a unary cost is not finite.\n");
    return false;
  }
  const long n = unary_.rows();
  for (const PottsEdge& e : edges_) {
    if (e.a < 0 || e.b < 0 || e.a >= n || e.b >= n) {
      PCL_ERROR("[segmat::AlphaExpansion::compute] edge (%d, %d) out of range for %ld nodes.\n",
                e.a, e.b, n);
      return false;
    }
    if (!std::isfinite(e.weight) || e.weight < 0.0) {
      PCL_ERROR("[segmat::AlphaExpansion::compute] edge (%d, %d) has weight %g (must be finite "
                "and >= 0).\n",
                e.a, e.b, e.weight);
      return false;
    }
  }
  return true;
}

double
computePottsEnergy(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                   const std::vector<int>& labels)
{
  double sum = 0.0;
  for (long i = 0; i < unary.rows(); ++i)
    sum += unary(i, labels[i]);
  for (const PottsEdge& e : edges)
    if (labels[e.a] != labels[e.b])
      sum += e.weight;
  return sum;
}

bool
AlphaExpansion::compute(std::vector<int>& labels)
{
  return compute({}, labels);
}

bool
AlphaExpansion::compute(std::vector<int> initial, std::vector<int>& labels)
{
  labels.clear();
  energy_ = 0.0;
  cycles_ = 0;
  moves_ = 0;
  if (!validate())
    return false;
  const int n = static_cast<int>(unary_.rows());
  const int num_labels = static_cast<int>(unary_.cols());
  if (n == 0)
    return true;

  if (!initial.empty() && initial.size() != static_cast<std::size_t>(n)) {
    PCL_ERROR("[segmat::AlphaExpansion::compute] %zu initial labels for %d nodes.\n",
              initial.size(), n);
    return false;
  }
  for (int l : initial)
    if (l < 0 || l >= num_labels) {
      PCL_ERROR("[segmat::AlphaExpansion::compute] initial label %d out of range [0, %d).\n", l,
                num_labels);
      return false;
    }

  // Only edges that can cost something enter the network.
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> weights;
  for (const PottsEdge& e : edges_)
    if (e.a != e.b && e.weight > 0.0) {
      pairs.emplace_back(e.a, e.b);
      weights.push_back(e.weight);
    }
  if (!initial.empty() && num_labels > 1 && !pairs.empty())
    labels.swap(initial);
  else {
    // The per-node best label: with weak smoothing this is already near the optimum, and
    // without edges it is the exact optimum.
    labels.resize(n);
    for (int i = 0; i < n; ++i) {
      Eigen::Index best = 0;
      unary_.row(i).minCoeff(&best); // first minimum: ties go to the smaller label
      labels[i] = static_cast<int>(best);
    }
  }
  energy_ = energy(labels);
  if (num_labels == 1 || pairs.empty())
    return true;

  BkMaxFlow network(n, pairs);
  std::vector<double> alpha_minus_keep(n);
  std::vector<int> proposal(n);
  // A move for α is skipped when no label changed since α's last move: it would find nothing.
  long stamp = 0;
  std::vector<long> tried_at(num_labels, -1);
  for (int cycle = 1; cycle <= max_cycles_; ++cycle) {
    bool improved = false;
    for (int alpha = 0; alpha < num_labels; ++alpha) {
      if (tried_at[alpha] == stamp)
        continue;
      ++moves_;
      for (int i = 0; i < n; ++i)
        alpha_minus_keep[i] = unary_(i, alpha) - unary_(i, labels[i]);
      // Pairwise term of the binary move (x = 1: take α), for Potts with weight w:
      //   E00 = w[l_a≠l_b], E01 = w[l_a≠α], E10 = w[α≠l_b], E11 = 0, decomposed as
      //   E00 + (E10−E00)·x_a + (E11−E10)·x_b + (E01+E10−E00−E11)·(1−x_a)·x_b.
      for (std::size_t e = 0; e < pairs.size(); ++e) {
        const int la = labels[pairs[e].first], lb = labels[pairs[e].second];
        const double w = weights[e];
        const double e00 = la != lb ? w : 0.0, e01 = la != alpha ? w : 0.0,
                     e10 = alpha != lb ? w : 0.0;
        alpha_minus_keep[pairs[e].first] += e10 - e00;
        alpha_minus_keep[pairs[e].second] -= e10;
        network.setPair(e, e01 + e10 - e00); // >= 0: Potts is a metric
      }
      for (int i = 0; i < n; ++i) {
        const double d = alpha_minus_keep[i];
        network.setTerminals(i, d > 0.0 ? d : 0.0, d < 0.0 ? -d : 0.0);
      }
      network.solve();
      for (int i = 0; i < n; ++i)
        proposal[i] = network.inSourceSet(i) ? labels[i] : alpha;
      tried_at[alpha] = stamp;
      const double proposed = energy(proposal);
      if (proposed < energy_) {
        labels.swap(proposal);
        energy_ = proposed;
        tried_at[alpha] = ++stamp;
        improved = true;
      }
    }
    cycles_ = cycle;
    if (!improved)
      break;
  }
  return true;
}

} // namespace segmat
