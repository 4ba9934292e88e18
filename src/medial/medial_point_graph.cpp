/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/medial_point_graph.h>

#include "../common/point_kd_tree.h"

#include <pcl/console/print.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace segmat {

MedialPointGraph::MedialPointGraph() : k_(10), overlap_factor_(1.0), connect_components_(true) {}

void
MedialPointGraph::setKSearch(int k)
{
  if (k <= 0) {
    PCL_WARN("[segmat::MedialPointGraph::setKSearch] k must be positive; keeping %d.\n", k_);
    return;
  }
  k_ = k;
}

void
MedialPointGraph::setOverlapFactor(double rho)
{
  if (!(rho > 0.0) || !std::isfinite(rho)) {
    PCL_WARN("[segmat::MedialPointGraph::setOverlapFactor] rho must be positive and finite; "
             "keeping %g.\n", overlap_factor_);
    return;
  }
  overlap_factor_ = rho;
}

bool
MedialPointGraph::compute(MatGraph& graph)
{
  graph = MatGraph();
  components_ = 0;
  bridges_ = 0;
  if (!input_ || input_->empty()) {
    PCL_ERROR("[segmat::MedialPointGraph::compute] No input cloud, or it is empty.\n");
    return false;
  }
  const MedialCloud& medial = *input_;
  const int n = static_cast<int>(medial.size());
  for (const MedialPoint& p : medial)
    if (!p.getVector3fMap().allFinite() || !std::isfinite(p.radius) || p.radius < 0.0f) {
      PCL_ERROR("[segmat::MedialPointGraph::compute] Every centre and radius must be finite, "
                "every radius >= 0.\n");
      return false;
    }

  std::vector<Eigen::Vector3d> centres(n);
  std::vector<double> radii(n);
  std::vector<MatNode> nodes(n);
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  xyz->resize(n);
  for (int i = 0; i < n; ++i) {
    centres[i] = medial[i].getVector3fMap().cast<double>();
    radii[i] = medial[i].radius;
    (*xyz)[i].getVector3fMap() = medial[i].getVector3fMap();
    MatNode& node = nodes[i];
    node.kind = MatNodeKind::Point;
    node.v = Eigen::Vector3i(i, -1, -1);
    node.mean_radius = radii[i];
    node.centroid = centres[i];
    const Eigen::Vector3d normal = medial[i].getNormalVector3fMap().cast<double>();
    const double len = normal.norm();
    node.normal = std::isfinite(len) && len > 0.0 ? Eigen::Vector3d(normal / len)
                                                  : Eigen::Vector3d::Zero();
  }
  auto overlap = [&](int i, int j) {
    return (centres[i] - centres[j]).norm() < overlap_factor_ * (radii[i] + radii[j]);
  };

  std::vector<std::vector<int>> adjacency(n);
  boost::disjoint_sets_with_storage<> sets(n);
  for (int i = 0; i < n; ++i)
    sets.make_set(i);
  if (n > 1) {
    detail::PointKdTree tree;
    tree.setInputCloud(xyz);
    pcl::Indices nn;
    std::vector<float> d2;
    const int k = std::min(k_, n - 1) + 1; // the query point comes back too
    for (int i = 0; i < n; ++i) {
      tree.nearestKSearch((*xyz)[i], k, nn, d2);
      for (int j : nn)
        if (j != i && overlap(i, j)) {
          adjacency[i].push_back(j); // MatGraph symmetrises and removes duplicates
          sets.union_set(i, j);
        }
    }

    if (connect_components_) {
      struct Bridge
      {
        float distance;
        int a, b;
      };
      std::vector<Bridge> bridges;
      const int wide = std::min(4 * k_, n - 1) + 1;
      for (int i = 0; i < n; ++i) {
        tree.nearestKSearch((*xyz)[i], wide, nn, d2);
        for (std::size_t a = 0; a < nn.size(); ++a) {
          const int j = nn[a];
          if (j != i && sets.find_set(i) != sets.find_set(j) && overlap(i, j))
            bridges.push_back({d2[a], std::min(i, j), std::max(i, j)});
        }
      }
      std::sort(bridges.begin(), bridges.end(), [](const Bridge& x, const Bridge& y) {
        return std::tie(x.distance, x.a, x.b) < std::tie(y.distance, y.a, y.b);
      });
      for (const Bridge& bridge : bridges)
        if (sets.find_set(bridge.a) != sets.find_set(bridge.b)) {
          sets.union_set(bridge.a, bridge.b);
          adjacency[bridge.a].push_back(bridge.b);
          ++bridges_;
        }
    }
  }
  for (int i = 0; i < n; ++i)
    if (static_cast<int>(sets.find_set(i)) == i)
      ++components_;
  graph = MatGraph(std::move(centres), std::move(radii), std::move(nodes), adjacency);
  return true;
}

} // namespace segmat
