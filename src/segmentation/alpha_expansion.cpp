/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/segmentation/alpha_expansion.h>

#include <pcl/console/print.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/range/iterator_range.hpp>

#include <cmath>
#include <utility>

namespace segmat {
namespace {

/** The s–t network of one expansion move. Its topology (terminal arcs for every node, a pair of
 * arcs per edge) is the same for every move, so it is built once per compute() as a CSR graph
 * and each move only rewrites capacities: much cheaper than a fresh adjacency_list per move.
 */
class ExpansionNetwork
{
public:
  using Graph = boost::compressed_sparse_row_graph<boost::directedS>;
  using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
  using Arc = boost::graph_traits<Graph>::edge_descriptor;

  ExpansionNetwork(int num_nodes, const std::vector<std::pair<int, int>>& pairs)
  : num_nodes_(num_nodes), pair_arc_(pairs.size())
  {
    // Arcs grouped by tail (what the sorted CSR constructor wants): node i owns i→t, i→s and one
    // arc per incident edge; then the source's s→i, then the sink's t→i.
    const int n = num_nodes;
    std::vector<int> offset(n + 1, 0);
    for (const auto& p : pairs) {
      ++offset[p.first + 1];
      ++offset[p.second + 1];
    }
    for (int i = 0; i < n; ++i)
      offset[i + 1] += offset[i] + 2;
    first_source_arc_ = offset[n];
    const int num_arcs = first_source_arc_ + 2 * n;
    const Vertex source = n, sink = n + 1;

    std::vector<std::pair<Vertex, Vertex>> ends(num_arcs);
    std::vector<int> reverse(num_arcs);
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (int i = 0; i < n; ++i) {
      const int to_sink = cursor[i]++, to_source = cursor[i]++;
      const int from_source = first_source_arc_ + i, from_sink = first_source_arc_ + n + i;
      ends[to_sink] = {Vertex(i), sink};
      ends[to_source] = {Vertex(i), source};
      ends[from_source] = {source, Vertex(i)};
      ends[from_sink] = {sink, Vertex(i)};
      reverse[to_sink] = from_sink;
      reverse[from_sink] = to_sink;
      reverse[to_source] = from_source;
      reverse[from_source] = to_source;
    }
    for (std::size_t e = 0; e < pairs.size(); ++e) {
      const int a = pairs[e].first, b = pairs[e].second;
      const int ab = cursor[a]++, ba = cursor[b]++;
      ends[ab] = {Vertex(a), Vertex(b)};
      ends[ba] = {Vertex(b), Vertex(a)};
      reverse[ab] = ba;
      reverse[ba] = ab;
      pair_arc_[e] = ab;
    }
    graph_ = Graph(boost::edges_are_sorted, ends.begin(), ends.end(), Vertex(n + 2));

    // The sorted constructor keeps the given order, so an arc's CSR edge index is its position.
    arcs_.resize(num_arcs);
    const auto index = get(boost::edge_index, graph_);
    for (const Arc& arc : boost::make_iterator_range(edges(graph_)))
      arcs_[get(index, arc)] = arc;
    reverse_arcs_.resize(num_arcs);
    for (int k = 0; k < num_arcs; ++k)
      reverse_arcs_[k] = arcs_[reverse[k]];
    capacity_.assign(num_arcs, 0.0);
    residual_.assign(num_arcs, 0.0);
    predecessor_.resize(n + 2);
    colour_.resize(n + 2);
    distance_.resize(n + 2);
    to_sink_arc_.resize(n);
    for (int i = 0; i < n; ++i)
      to_sink_arc_[i] = offset[i];
  }

  /** Terminal capacities of node i: paid when i ends on the sink side (takes α) and when it
   * ends on the source side (keeps its label).
   */
  void
  setTerminals(int i, double cost_alpha, double cost_keep)
  {
    capacity_[first_source_arc_ + i] = cost_alpha;
    capacity_[to_sink_arc_[i]] = cost_keep;
  }

  /** Capacity of edge e's arc a→b, paid when a keeps and b takes α. The arc b→a stays 0. */
  void
  setPair(std::size_t e, double cost)
  {
    capacity_[pair_arc_[e]] = cost;
  }

  void
  solve()
  {
    const auto edge_index = get(boost::edge_index, graph_);
    const auto vertex_index = get(boost::vertex_index, graph_);
    boost::boykov_kolmogorov_max_flow(
        graph_, boost::make_iterator_property_map(capacity_.begin(), edge_index),
        boost::make_iterator_property_map(residual_.begin(), edge_index),
        boost::make_iterator_property_map(reverse_arcs_.begin(), edge_index),
        boost::make_iterator_property_map(predecessor_.begin(), vertex_index),
        boost::make_iterator_property_map(colour_.begin(), vertex_index),
        boost::make_iterator_property_map(distance_.begin(), vertex_index), vertex_index,
        Vertex(num_nodes_), Vertex(num_nodes_ + 1));
  }

  /** After solve(): node i is in the source tree, i.e. reachable from s in the residual graph
   * (keeps its label). Nodes of the sink tree and free nodes take α; both sides are minimum cuts.
   */
  bool
  keeps(int i) const
  {
    return colour_[i] == boost::black_color;
  }

private:
  int num_nodes_;
  int first_source_arc_ = 0;
  Graph graph_;
  std::vector<Arc> arcs_;
  std::vector<Arc> reverse_arcs_;
  std::vector<int> pair_arc_;
  std::vector<int> to_sink_arc_;
  std::vector<double> capacity_;
  std::vector<double> residual_;
  std::vector<Arc> predecessor_;
  std::vector<boost::default_color_type> colour_;
  std::vector<long> distance_;
};

} // namespace

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

  // Start from the per-node best label: with weak smoothing this is already near the optimum.
  labels.resize(n);
  for (int i = 0; i < n; ++i) {
    Eigen::Index best = 0;
    unary_.row(i).minCoeff(&best); // first minimum: ties go to the smaller label
    labels[i] = static_cast<int>(best);
  }
  energy_ = energy(labels);

  // Only edges that can cost something enter the network.
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> weights;
  for (const PottsEdge& e : edges_)
    if (e.a != e.b && e.weight > 0.0) {
      pairs.emplace_back(e.a, e.b);
      weights.push_back(e.weight);
    }
  if (num_labels == 1 || pairs.empty())
    return true; // argmin of the unary terms is the exact optimum

  ExpansionNetwork network(n, pairs);
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
        proposal[i] = network.keeps(i) ? labels[i] : alpha;
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
