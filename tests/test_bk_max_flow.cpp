// Boykov–Kolmogorov max-flow against a hand-solved network and brute-force minimum cuts.
#include "../src/graph_cut/bk_max_flow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <queue>
#include <random>

using namespace segmat;

namespace {

struct Network
{
  int n = 0;
  std::vector<double> from_source, to_sink;
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> forward, backward;

  double
  cut(unsigned source_set) const
  {
    double c = 0.0;
    for (int i = 0; i < n; ++i)
      c += (source_set >> i & 1u) ? to_sink[i] : from_source[i];
    for (std::size_t e = 0; e < pairs.size(); ++e) {
      const bool a = source_set >> pairs[e].first & 1u, b = source_set >> pairs[e].second & 1u;
      if (a && !b)
        c += forward[e];
      if (b && !a)
        c += backward[e];
    }
    return c;
  }

  void
  load(BkMaxFlow& flow) const
  {
    for (int i = 0; i < n; ++i)
      flow.setTerminals(i, from_source[i], to_sink[i]);
    for (std::size_t e = 0; e < pairs.size(); ++e)
      flow.setPair(e, forward[e], backward[e]);
  }
};

unsigned
sourceSet(const BkMaxFlow& flow, int n)
{
  unsigned set = 0;
  for (int i = 0; i < n; ++i)
    if (flow.inSourceSet(i))
      set |= 1u << i;
  return set;
}

} // namespace

TEST(BkMaxFlow, HandSolvedNetwork)
{
  // s→0: 4, s→1: 3, 0→1: 2, 0→2: 3, 1→3: 4, 2→3: 1, 2→t: 3, 3→t: 5. Paths s-0-2-t (3),
  // s-1-3-t (3), s-0-1-3-t (1): flow 7, and both source arcs are saturated, so the smallest
  // minimum-cut source side is {} (the cut {s, 0, 1}: 0→2 + 1→3 = 7 is minimal too).
  Network net;
  net.n = 4;
  net.from_source = {4, 3, 0, 0};
  net.to_sink = {0, 0, 3, 5};
  net.pairs = {{0, 1}, {0, 2}, {1, 3}, {2, 3}};
  net.forward = {2, 3, 4, 1};
  net.backward = {0, 0, 0, 0};
  BkMaxFlow flow(net.n, net.pairs);
  net.load(flow);
  EXPECT_DOUBLE_EQ(flow.solve(), 7.0);
  EXPECT_EQ(sourceSet(flow, net.n), 0u);
  // Capacities change, the network is solved again: with 0→2 at 1, paths s-0-2-t (1), s-1-3-t
  // (3), s-0-1-3-t (1) give 5; s→0 keeps 2 and 0→1 keeps 1, so 0 and 1 stay on the source side.
  net.forward[1] = 1;
  net.load(flow);
  EXPECT_DOUBLE_EQ(flow.solve(), 5.0);
  EXPECT_EQ(sourceSet(flow, net.n), 0b0011u);
  EXPECT_DOUBLE_EQ(net.cut(0b0011u), 5.0);
}

TEST(BkMaxFlow, RandomNetworksGiveTheSmallestMinimumCut)
{
  std::mt19937 rng(20261201u);
  for (int trial = 0; trial < 300; ++trial) {
    Network net;
    net.n = 3 + trial % 8;
    for (int i = 0; i < net.n; ++i) {
      // Often zero, as in expansion moves (one terminal per node) and on ties.
      net.from_source.push_back(rng() % 3 == 0 ? 0.0 : static_cast<double>(rng() % 10));
      net.to_sink.push_back(rng() % 3 == 0 ? 0.0 : static_cast<double>(rng() % 10));
    }
    for (int a = 0; a < net.n; ++a)
      for (int b = a + 1; b < net.n; ++b)
        if (rng() % 3 != 0) {
          net.pairs.emplace_back(a, b);
          net.forward.push_back(static_cast<double>(rng() % 8));
          net.backward.push_back(rng() % 2 ? 0.0 : static_cast<double>(rng() % 8));
        }
    // Brute force: the minimum cut and the intersection of all minimum-cut source sets (the
    // smallest one: minimum cuts are closed under intersection).
    double best = std::numeric_limits<double>::infinity();
    unsigned smallest = 0;
    for (unsigned set = 0; set < (1u << net.n); ++set) {
      const double c = net.cut(set);
      if (c < best) {
        best = c;
        smallest = set;
      }
      else if (c == best)
        smallest &= set;
    }
    BkMaxFlow flow(net.n, net.pairs);
    net.load(flow);
    ASSERT_DOUBLE_EQ(flow.solve(), best) << "trial " << trial;
    EXPECT_EQ(sourceSet(flow, net.n), smallest) << "trial " << trial;
    // A second solve from the same capacities gives the same answer.
    ASSERT_DOUBLE_EQ(flow.solve(), best) << "trial " << trial;
    EXPECT_EQ(sourceSet(flow, net.n), smallest) << "trial " << trial;
  }
}

namespace {

// Edmonds–Karp on a dense capacity matrix; node n is the source, n + 1 the sink.
double
edmondsKarp(const Network& net)
{
  const int n = net.n, s = n, t = n + 1, size = n + 2;
  std::vector<std::vector<double>> cap(size, std::vector<double>(size, 0.0));
  for (int i = 0; i < n; ++i) {
    cap[s][i] += net.from_source[i];
    cap[i][t] += net.to_sink[i];
  }
  for (std::size_t e = 0; e < net.pairs.size(); ++e) {
    cap[net.pairs[e].first][net.pairs[e].second] += net.forward[e];
    cap[net.pairs[e].second][net.pairs[e].first] += net.backward[e];
  }
  double flow = 0.0;
  for (;;) {
    std::vector<int> from(size, -1);
    from[s] = s;
    std::queue<int> queue;
    queue.push(s);
    while (!queue.empty() && from[t] < 0) {
      const int u = queue.front();
      queue.pop();
      for (int v = 0; v < size; ++v)
        if (from[v] < 0 && cap[u][v] > 0.0) {
          from[v] = u;
          queue.push(v);
        }
    }
    if (from[t] < 0)
      return flow;
    double b = std::numeric_limits<double>::infinity();
    for (int v = t; v != s; v = from[v])
      b = std::min(b, cap[from[v]][v]);
    for (int v = t; v != s; v = from[v]) {
      cap[from[v]][v] -= b;
      cap[v][from[v]] += b;
    }
    flow += b;
  }
}

} // namespace

TEST(BkMaxFlow, LargerGridNetworksMatchEdmondsKarp)
{
  // 12 × 12 grids with diagonals (k-NN-like degree) and both terminals, as in expansion moves
  // on a cloud: long augmenting paths, many orphans, and the tree-distance heuristics at work.
  std::mt19937 rng(7u);
  const int side = 12;
  for (int trial = 0; trial < 20; ++trial) {
    Network net;
    net.n = side * side;
    for (int i = 0; i < net.n; ++i) {
      const double d = static_cast<double>(static_cast<int>(rng() % 41) - 20);
      net.from_source.push_back(d > 0.0 ? d : 0.0);
      net.to_sink.push_back(d < 0.0 ? -d : 0.0);
    }
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        for (const auto& step : {std::pair<int, int>{1, 0}, {0, 1}, {1, 1}, {-1, 1}}) {
          const int xx = x + step.first, yy = y + step.second;
          if (xx < 0 || xx >= side || yy >= side)
            continue;
          net.pairs.emplace_back(y * side + x, yy * side + xx);
          net.forward.push_back(static_cast<double>(rng() % (5 + trial)));
          net.backward.push_back(static_cast<double>(rng() % (5 + trial)));
        }
    BkMaxFlow flow(net.n, net.pairs);
    net.load(flow);
    const double value = flow.solve();
    EXPECT_DOUBLE_EQ(value, edmondsKarp(net)) << "trial " << trial;
    // The reported side is a cut of exactly that value.
    double cut = 0.0;
    for (int i = 0; i < net.n; ++i)
      cut += flow.inSourceSet(i) ? net.to_sink[i] : net.from_source[i];
    for (std::size_t e = 0; e < net.pairs.size(); ++e) {
      const bool a = flow.inSourceSet(net.pairs[e].first), b = flow.inSourceSet(net.pairs[e].second);
      cut += (a && !b) ? net.forward[e] : 0.0;
      cut += (b && !a) ? net.backward[e] : 0.0;
    }
    EXPECT_DOUBLE_EQ(cut, value) << "trial " << trial;
  }
}

TEST(BkMaxFlow, NetworkWithoutArcsOrNodes)
{
  BkMaxFlow empty(0, {});
  EXPECT_DOUBLE_EQ(empty.solve(), 0.0);
  BkMaxFlow lonely(2, {});
  lonely.setTerminals(0, 5.0, 2.0); // keeps 2 as bypass flow, 3 residual from the source
  lonely.setTerminals(1, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(lonely.solve(), 2.0);
  EXPECT_TRUE(lonely.inSourceSet(0));
  EXPECT_FALSE(lonely.inSourceSet(1));
}
