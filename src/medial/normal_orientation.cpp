/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/normal_orientation.h>

#include "../common/point_kd_tree.h"

#include <pcl/console/print.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <vector>

namespace segmat {

NormalOrientation::NormalOrientation() : k_(10), tangent_plane_term_(true), outward_check_(true) {}

void
NormalOrientation::setKSearch(int k)
{
  if (k <= 0) {
    PCL_WARN("[segmat::NormalOrientation::setKSearch] k must be positive; keeping %d.\n", k_);
    return;
  }
  k_ = k;
}

bool
NormalOrientation::orient(pcl::PointCloud<pcl::PointNormal>& cloud)
{
  components_ = 0;
  reversed_ = 0;
  const int n = static_cast<int>(cloud.size());
  if (n == 0) {
    PCL_ERROR("[segmat::NormalOrientation::orient] The cloud is empty.\n");
    return false;
  }
  for (const pcl::PointNormal& p : cloud) {
    const Eigen::Vector3f nv = p.getNormalVector3fMap();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !nv.allFinite() ||
        nv.squaredNorm() == 0.0f) {
      PCL_ERROR("[segmat::NormalOrientation::orient] Every point and normal must be finite and "
                "every normal non-zero.\n");
      return false;
    }
  }

  // n_j reflected in the plane halfway between p_i and p_j (the mirror relation).
  auto mirrored = [&cloud](int i, int j, const Eigen::Vector3f& nj) -> Eigen::Vector3f {
    const Eigen::Vector3f d = cloud[j].getVector3fMap() - cloud[i].getVector3fMap();
    const float len = d.norm();
    if (!(len > 0.0f))
      return nj;
    const Eigen::Vector3f u = d / len;
    return nj - 2.0f * u.dot(nj) * u;
  };

  // Symmetric k-NN graph, each undirected edge once, weighted.
  struct Edge
  {
    float weight;
    int a, b;
  };
  std::vector<Edge> edges;
  if (n > 1) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    xyz->resize(n);
    for (int i = 0; i < n; ++i)
      (*xyz)[i].getVector3fMap() = cloud[i].getVector3fMap();
    detail::PointKdTree tree;
    tree.setInputCloud(xyz);
    const int k = std::min(k_, n - 1) + 1; // +1: the query point itself comes back
    pcl::Indices nn;
    std::vector<float> d2;
    edges.reserve(std::size_t(n) * k);
    for (int i = 0; i < n; ++i) {
      tree.nearestKSearch((*xyz)[i], k, nn, d2);
      const Eigen::Vector3f ni = cloud[i].getNormalVector3fMap().normalized();
      for (int j : nn) {
        if (j == i)
          continue;
        const Eigen::Vector3f nj = cloud[j].getNormalVector3fMap().normalized();
        float w;
        if (mirror_relation_)
          w = 1.0f - std::abs(ni.dot(mirrored(i, j, nj)));
        else {
          w = 1.0f - std::abs(ni.dot(nj));
          if (tangent_plane_term_) {
            const Eigen::Vector3f d = cloud[j].getVector3fMap() - cloud[i].getVector3fMap();
            const float len = d.norm();
            if (len > 0.0f)
              w += std::abs(ni.dot(d)) * std::abs(nj.dot(d)) / (len * len);
          }
        }
        edges.push_back({w, std::min(i, j), std::max(i, j)});
      }
    }
    // Both directions of a mutual pair give the same weight up to rounding: keep one per pair.
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
      return std::tie(x.a, x.b, x.weight) < std::tie(y.a, y.b, y.weight);
    });
    edges.erase(std::unique(edges.begin(), edges.end(),
                            [](const Edge& x, const Edge& y) { return x.a == y.a && x.b == y.b; }),
                edges.end());
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
      return std::tie(x.weight, x.a, x.b) < std::tie(y.weight, y.a, y.b);
    });
  }

  // Kruskal: minimum spanning forest.
  boost::disjoint_sets_with_storage<> sets(n);
  for (int i = 0; i < n; ++i)
    sets.make_set(i);
  std::vector<std::vector<int>> tree_adjacency(n);
  for (const Edge& e : edges) {
    const int ra = static_cast<int>(sets.find_set(e.a));
    const int rb = static_cast<int>(sets.find_set(e.b));
    if (ra == rb)
      continue;
    sets.link(ra, rb);
    tree_adjacency[e.a].push_back(e.b);
    tree_adjacency[e.b].push_back(e.a);
  }
  for (auto& list : tree_adjacency)
    std::sort(list.begin(), list.end());

  // Components in order of their lowest index; seed = largest x.
  std::vector<int> component(n, -1);
  std::vector<std::vector<int>> members;
  for (int i = 0; i < n; ++i) {
    if (component[i] >= 0)
      continue;
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    std::vector<int> stack{i};
    component[i] = id;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      members[id].push_back(v);
      for (int w : tree_adjacency[v])
        if (component[w] < 0) {
          component[w] = id;
          stack.push_back(w);
        }
    }
  }
  components_ = members.size();

  std::vector<char> flip(n, 0), reached(n, 0);
  auto normal = [&](int i) -> Eigen::Vector3f {
    const Eigen::Vector3f v = cloud[i].getNormalVector3fMap();
    return flip[i] ? Eigen::Vector3f(-v) : v;
  };
  for (const std::vector<int>& comp : members) {
    int seed = comp.front();
    for (int v : comp)
      if (cloud[v].x > cloud[seed].x || (cloud[v].x == cloud[seed].x && v < seed))
        seed = v;
    flip[seed] = cloud[seed].normal_x < 0.0f;
    // Breadth-first over the tree: a child takes the side of its parent.
    std::queue<int> queue;
    queue.push(seed);
    reached[seed] = 1;
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      const Eigen::Vector3f nv = normal(v);
      for (int w : tree_adjacency[v]) {
        if (reached[w])
          continue;
        reached[w] = 1;
        const Eigen::Vector3f nw = cloud[w].getNormalVector3fMap();
        flip[w] = nv.dot(mirror_relation_ ? mirrored(v, w, nw) : nw) < 0.0f;
        queue.push(w);
      }
    }
    if (outward_check_) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int v : comp)
        centroid += cloud[v].getVector3fMap().cast<double>();
      centroid /= double(comp.size());
      double signed_sum = 0.0, absolute_sum = 0.0;
      for (int v : comp) {
        const double s =
            (cloud[v].getVector3fMap().cast<double>() - centroid).dot(normal(v).cast<double>());
        signed_sum += s;
        absolute_sum += std::abs(s);
      }
      if (absolute_sum > 0.0 && signed_sum < -0.1 * absolute_sum)
        for (int v : comp)
          flip[v] = !flip[v];
    }
  }
  for (int i = 0; i < n; ++i)
    if (flip[i]) {
      cloud[i].getNormalVector3fMap() *= -1.0f;
      ++reversed_;
    }
  return true;
}

} // namespace segmat
