// α-expansion against brute-force enumeration and hand-solved problems.
#include <segmat/graph_cut/alpha_expansion.h>

#include "../src/graph_cut/coarse_expansion.h"
#include "../src/graph_cut/relabel_free_nodes.h"

#include <gtest/gtest.h>
#include <pcl/console/print.h>

#include <cmath>
#include <limits>
#include <random>

using namespace segmat;

namespace {

// Global minimum over all L^n labellings.
double
bruteForceMinimum(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                  std::vector<int>* best_labels = nullptr)
{
  const int n = static_cast<int>(unary.rows()), num_labels = static_cast<int>(unary.cols());
  std::vector<int> labels(n, 0);
  double best = std::numeric_limits<double>::infinity();
  while (true) {
    const double e = computePottsEnergy(unary, edges, labels);
    if (e < best) {
      best = e;
      if (best_labels)
        *best_labels = labels;
    }
    int k = 0;
    while (k < n && ++labels[k] == num_labels)
      labels[k++] = 0;
    if (k == n)
      break;
  }
  return best;
}

// Lowest energy reachable from `labels` by one α-expansion move, over all α and all 2^n subsets.
double
bestExpansionMove(const Eigen::MatrixXd& unary, const std::vector<PottsEdge>& edges,
                  const std::vector<int>& labels)
{
  const int n = static_cast<int>(unary.rows());
  double best = std::numeric_limits<double>::infinity();
  for (int alpha = 0; alpha < unary.cols(); ++alpha)
    for (int mask = 0; mask < (1 << n); ++mask) {
      std::vector<int> moved = labels;
      for (int i = 0; i < n; ++i)
        if (mask & (1 << i))
          moved[i] = alpha;
      best = std::min(best, computePottsEnergy(unary, edges, moved));
    }
  return best;
}

// Values from the raw engine output, so the instances are the same with every standard library.
double
draw(std::mt19937& rng, int range)
{
  return static_cast<double>(rng() % static_cast<unsigned>(range));
}

} // namespace

TEST(AlphaExpansion, RandomSmallProblemsAreExpansionOptimalAndWithinFactorTwo)
{
  std::mt19937 rng(20240607u);
  int exact = 0, total = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 4 + trial % 3, num_labels = 3;
    Eigen::MatrixXd unary(n, num_labels);
    for (int i = 0; i < n; ++i)
      for (int l = 0; l < num_labels; ++l)
        unary(i, l) = draw(rng, 20);
    std::vector<PottsEdge> edges;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (rng() % 2)
          edges.push_back({a, b, draw(rng, 3 + 5 * (trial % 4))});
    AlphaExpansion solver;
    solver.setUnaryCosts(unary);
    solver.setEdges(edges);
    std::vector<int> labels;
    ASSERT_TRUE(solver.compute(labels));
    ASSERT_EQ(labels.size(), static_cast<std::size_t>(n));
    const double e = computePottsEnergy(unary, edges, labels);
    EXPECT_DOUBLE_EQ(solver.getEnergy(), e);
    const double optimum = bruteForceMinimum(unary, edges);
    // A local minimum for every expansion move, and the Potts factor-2 guarantee.
    EXPECT_GE(bestExpansionMove(unary, edges, labels), e) << "trial " << trial;
    EXPECT_LE(e, 2.0 * optimum) << "trial " << trial;
    exact += e == optimum;
    ++total;
  }
  // α-expansion is nearly always exact on problems this small.
  EXPECT_GE(exact, total * 9 / 10);
}

TEST(AlphaExpansion, ChainCutsAtItsWeakestEdge)
{
  // Node 0 insists on label 0, node 5 on label 2, the middle weakly prefers label 1.
  // Best: one cut at the weight-1 edge (2,3) → 0 0 0 2 2 2, energy 4·2 + 1 = 9; keeping label 1
  // in the middle costs 4·1 + two cuts of 5 = 14.
  Eigen::MatrixXd unary(6, 3);
  unary << 0, 100, 100, 2, 1, 2, 2, 1, 2, 2, 1, 2, 2, 1, 2, 100, 100, 0;
  const std::vector<PottsEdge> edges{{0, 1, 5}, {1, 2, 5}, {2, 3, 1}, {3, 4, 5}, {4, 5, 5}};
  std::vector<int> brute;
  EXPECT_DOUBLE_EQ(bruteForceMinimum(unary, edges, &brute), 9.0);
  AlphaExpansion solver;
  solver.setUnaryCosts(unary);
  solver.setEdges(edges);
  std::vector<int> labels;
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 0, 2, 2, 2}));
  EXPECT_EQ(labels, brute);
  EXPECT_DOUBLE_EQ(solver.getEnergy(), 9.0);
}

TEST(AlphaExpansion, StartsFromAGivenLabelling)
{
  // The chain above, started from all 1: the moves to 0 and to 2 each take one end, and the
  // result is the optimum 0 0 0 2 2 2 again. Started from the optimum, one cycle of three moves
  // finds nothing to improve and returns it unchanged.
  Eigen::MatrixXd unary(6, 3);
  unary << 0, 100, 100, 2, 1, 2, 2, 1, 2, 2, 1, 2, 2, 1, 2, 100, 100, 0;
  const std::vector<PottsEdge> edges{{0, 1, 5}, {1, 2, 5}, {2, 3, 1}, {3, 4, 5}, {4, 5, 5}};
  AlphaExpansion solver;
  solver.setUnaryCosts(unary);
  solver.setEdges(edges);
  std::vector<int> labels;
  ASSERT_TRUE(solver.compute(std::vector<int>(6, 1), labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 0, 2, 2, 2}));
  EXPECT_DOUBLE_EQ(solver.getEnergy(), 9.0);
  ASSERT_TRUE(solver.compute({0, 0, 0, 2, 2, 2}, labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 0, 2, 2, 2}));
  EXPECT_EQ(solver.getCycles(), 1);
  EXPECT_EQ(solver.getMoves(), 3);

  pcl::console::VERBOSITY_LEVEL old = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  EXPECT_FALSE(solver.compute({0, 0, 0}, labels)); // wrong size
  EXPECT_TRUE(labels.empty());
  EXPECT_FALSE(solver.compute({0, 0, 0, 3, 2, 2}, labels)); // label out of range
  EXPECT_FALSE(solver.compute({0, 0, 0, -1, 2, 2}, labels));
  pcl::console::setVerbosityLevel(old);
}

TEST(AlphaExpansion, StrongSmoothingGivesOneLabel)
{
  // Sum of unaries per label: 9, 8, 10 → with edges too strong to cut, everything takes label 1.
  Eigen::MatrixXd unary(4, 3);
  unary << 0, 4, 4, 3, 0, 3, 3, 4, 0, 3, 0, 3;
  std::vector<PottsEdge> edges{{0, 1, 50}, {1, 2, 50}, {2, 3, 50}, {3, 0, 50}};
  AlphaExpansion solver;
  solver.setUnaryCosts(unary);
  solver.setEdges(edges);
  std::vector<int> labels;
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_EQ(labels, std::vector<int>(4, 1));
  EXPECT_DOUBLE_EQ(solver.getEnergy(), 8.0);
  EXPECT_DOUBLE_EQ(bruteForceMinimum(unary, edges), 8.0);
}

TEST(AlphaExpansion, NoEdgesGivesArgminOfUnary)
{
  Eigen::MatrixXd unary(3, 4);
  unary << 5, 1, 3, 1, // tie between 1 and 3: the smaller label wins
      0, 2, 2, 2,      //
      9, 8, 7, -1;     // negative costs are fine
  AlphaExpansion solver;
  solver.setUnaryCosts(unary);
  std::vector<int> labels;
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_EQ(labels, (std::vector<int>{1, 0, 3}));
  EXPECT_DOUBLE_EQ(solver.getEnergy(), 0.0);
  EXPECT_EQ(solver.getMoves(), 0);
  // Zero-weight edges and self-loops change nothing.
  solver.setEdges({{0, 1, 0.0}, {2, 2, 7.0}});
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_EQ(labels, (std::vector<int>{1, 0, 3}));
  // A given start changes nothing either: the argmin is the exact optimum.
  ASSERT_TRUE(solver.compute({0, 2, 2}, labels));
  EXPECT_EQ(labels, (std::vector<int>{1, 0, 3}));
}

TEST(AlphaExpansion, SingleLabelAndEmptyProblem)
{
  AlphaExpansion solver;
  solver.setUnaryCosts(Eigen::MatrixXd::Constant(3, 1, 2.0));
  solver.setEdges({{0, 1, 1.0}, {1, 2, 1.0}});
  std::vector<int> labels;
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_EQ(labels, std::vector<int>(3, 0));
  EXPECT_DOUBLE_EQ(solver.getEnergy(), 6.0);

  solver.setUnaryCosts(Eigen::MatrixXd(0, 2));
  solver.setEdges({});
  labels = {7};
  ASSERT_TRUE(solver.compute(labels));
  EXPECT_TRUE(labels.empty());
}

TEST(AlphaExpansion, RejectsBadInput)
{
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  AlphaExpansion solver;
  std::vector<int> labels{1, 2};
  solver.setUnaryCosts(Eigen::MatrixXd(2, 0));
  EXPECT_FALSE(solver.compute(labels));
  EXPECT_TRUE(labels.empty());

  Eigen::MatrixXd unary = Eigen::MatrixXd::Zero(2, 2);
  solver.setUnaryCosts(unary);
  solver.setEdges({{0, 2, 1.0}});
  EXPECT_FALSE(solver.compute(labels));
  solver.setEdges({{0, 1, -1.0}});
  EXPECT_FALSE(solver.compute(labels));
  solver.setEdges({{0, 1, std::nan("")}});
  EXPECT_FALSE(solver.compute(labels));
  unary(1, 1) = std::numeric_limits<double>::infinity();
  solver.setUnaryCosts(unary);
  solver.setEdges({});
  EXPECT_FALSE(solver.compute(labels));
  EXPECT_TRUE(labels.empty());

  solver.setMaxCycles(0); // ignored
  EXPECT_EQ(solver.getMaxCycles(), 100);
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
}

TEST(AlphaExpansion, CycleCapIsHonoured)
{
  // A 1-D "staircase" where each cycle can only move the front by one expansion: with one cycle
  // the result must still be a valid labelling whose energy does not exceed the start.
  std::mt19937 rng(7u);
  const int n = 40, num_labels = 5;
  Eigen::MatrixXd unary(n, num_labels);
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < num_labels; ++l)
      unary(i, l) = draw(rng, 10);
  std::vector<PottsEdge> edges;
  for (int i = 0; i + 1 < n; ++i)
    edges.push_back({i, i + 1, 4.0});
  std::vector<int> argmin(n);
  for (int i = 0; i < n; ++i)
    unary.row(i).minCoeff(&argmin[i]);

  AlphaExpansion one, full;
  one.setUnaryCosts(unary);
  one.setEdges(edges);
  one.setMaxCycles(1);
  full.setUnaryCosts(unary);
  full.setEdges(edges);
  std::vector<int> a, b;
  ASSERT_TRUE(one.compute(a));
  ASSERT_TRUE(full.compute(b));
  EXPECT_EQ(one.getCycles(), 1);
  EXPECT_LE(one.getEnergy(), one.energy(argmin));
  EXPECT_LE(full.getEnergy(), one.getEnergy());
  EXPECT_GE(full.getCycles(), 2); // the converged run needs a confirming cycle
  // Deterministic.
  std::vector<int> c;
  ASSERT_TRUE(full.compute(c));
  EXPECT_EQ(b, c);
}

// A chain 0 - 1 - 2 - 3 with nodes 0 and 3 held at labels 0 and 1 and nodes 1 and 2 free. Each
// free node prefers label 1 by 2, but the edges 0-1 and 1-2 weigh 10 and 2-3 only 1. By hand:
// (0, 0) costs 2 + 2 + 1 (the edge 2-3 cut) = 5; (1, 1) costs 10 (edge 0-1); (0, 1) costs 2 +
// 10; (1, 0) costs 2 + 10 + 10 + 1. So the free nodes take label 0 against their own costs.
TEST(RelabelFreeNodes, HeldNeighboursPriceTheCut)
{
  Eigen::MatrixXd unary(4, 2);
  unary << 7, 0, 2, 0, 2, 0, 0, 7; // nodes 0 and 3 would rather switch: they are held
  const std::vector<PottsEdge> edges{{0, 1, 10.0}, {1, 2, 10.0}, {2, 3, 1.0}};
  std::vector<int> labels{0, -1, -1, 1};
  ASSERT_TRUE(detail::relabelFreeNodes(unary, edges, {0, 1, 1, 0}, 100, labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 0, 1}));
  EXPECT_DOUBLE_EQ(computePottsEnergy(unary, edges, labels), 7.0 + 5.0 + 7.0);
  // With the edge 2-3 as heavy as the others, the cut moves to 0-1: (1, 1) costs 10, (0, 0) 14.
  const std::vector<PottsEdge> heavy{{0, 1, 10.0}, {1, 2, 10.0}, {2, 3, 10.0}};
  ASSERT_TRUE(detail::relabelFreeNodes(unary, heavy, {0, 1, 1, 0}, 100, labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 1, 1, 1}));
  // Nothing free: nothing changes.
  ASSERT_TRUE(detail::relabelFreeNodes(unary, heavy, {0, 0, 0, 0}, 100, labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 1, 1, 1}));
}

// With two labels an expansion move is an exact binary cut, so the free nodes reach the lowest
// energy over every labelling of theirs with the others held, found here by enumeration.
TEST(RelabelFreeNodes, TwoLabelsReachTheOptimumWithTheOthersHeld)
{
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 9;
    Eigen::MatrixXd unary(n, 2);
    for (int i = 0; i < n; ++i)
      for (int l = 0; l < 2; ++l)
        unary(i, l) = draw(rng, 12);
    std::vector<PottsEdge> edges;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (rng() % 3 == 0)
          edges.push_back({a, b, draw(rng, 8)});
    std::vector<char> is_free(n);
    std::vector<int> held(n), free_nodes;
    for (int i = 0; i < n; ++i) {
      is_free[i] = rng() % 2 == 0;
      held[i] = is_free[i] ? -1 : static_cast<int>(rng() % 2);
      if (is_free[i])
        free_nodes.push_back(i);
    }
    double best = std::numeric_limits<double>::infinity();
    for (int mask = 0; mask < (1 << free_nodes.size()); ++mask) {
      std::vector<int> labels = held;
      for (std::size_t k = 0; k < free_nodes.size(); ++k)
        labels[free_nodes[k]] = (mask >> k) & 1;
      best = std::min(best, computePottsEnergy(unary, edges, labels));
    }
    std::vector<int> labels = held;
    ASSERT_TRUE(detail::relabelFreeNodes(unary, edges, is_free, 100, labels)) << trial;
    EXPECT_DOUBLE_EQ(computePottsEnergy(unary, edges, labels), best) << trial;
    for (int i = 0; i < n; ++i)
      if (!is_free[i])
        EXPECT_EQ(labels[i], held[i]) << trial << " node " << i;
  }
}

namespace {

// A W × H grid, 4-neighbour edges of weight 1; each node prefers the label of its vertical
// band (x < 37: 0, x < 83: 1, else 2) by a cost of 3..7 for any other label (a fixed
// pseudo-random pattern). Moving one node off its band's label costs at least 3 in data and
// saves at most 2 in edges, so the bands are the unique optimum.
struct BandGrid
{
  static constexpr int W = 400, H = 100;
  Eigen::MatrixXd unary = Eigen::MatrixXd::Zero(W * H, 3);
  std::vector<PottsEdge> edges;
  std::vector<int> bands;

  BandGrid()
  {
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const int i = y * W + x;
        const int band = x < 37 ? 0 : x < 83 ? 1 : 2;
        bands.push_back(band);
        for (int l = 0; l < 3; ++l)
          unary(i, l) = l == band ? 0.0 : 3.0 + (i * 7 + l * 13) % 5;
        if (x + 1 < W)
          edges.push_back({i, i + 1, 1.0});
        if (y + 1 < H)
          edges.push_back({i, i + W, 1.0});
      }
  }
};

} // namespace

TEST(CoarseToFineExpansion, RecoversBoundariesThatNoClusterFollows)
{
  const BandGrid grid;
  std::vector<int> labels;
  detail::CoarseExpansion report;
  ASSERT_TRUE(detail::coarseToFineExpansion(grid.unary, grid.edges, 16, 100, labels, &report));
  EXPECT_EQ(labels, grid.bands);
  // The clusters hold about 16 nodes each; only those within three clusters of the two
  // boundaries were cut again.
  EXPECT_GE(report.clusters, BandGrid::W * BandGrid::H / 16);
  EXPECT_LT(report.clusters, BandGrid::W * BandGrid::H / 8);
  EXPECT_GT(report.free_nodes, 0);
  EXPECT_LT(report.free_nodes, BandGrid::W * BandGrid::H / 4);

  // The whole-grid expansion agrees (the optimum is unique).
  AlphaExpansion whole;
  whole.setUnaryCosts(grid.unary);
  whole.setEdges(grid.edges);
  std::vector<int> exact;
  ASSERT_TRUE(whole.compute(exact));
  EXPECT_EQ(exact, grid.bands);
}

TEST(CoarseToFineExpansion, ClustersOfTwoAndIsolatedNodes)
{
  // A chain 0–1–2–3 that prefers labels 0 0 1 1, and a node 4 with no edge: it takes its
  // cheapest label, 1.
  Eigen::MatrixXd unary(5, 2);
  unary << 0, 9, 0, 9, 9, 0, 9, 0, 5, 1;
  const std::vector<PottsEdge> edges{{0, 1, 1.0}, {1, 2, 1.0}, {2, 3, 1.0}};
  std::vector<int> labels;
  ASSERT_TRUE(detail::coarseToFineExpansion(unary, edges, 1, 100, labels));
  EXPECT_EQ(labels, (std::vector<int>{0, 0, 1, 1, 1}));
}
