/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/segmentation/mat_region_growing.h>

#include <pcl/console/print.h>

#include <cmath>

namespace segmat {

MatRegionGrowing::MatRegionGrowing()
: delta0_(0.015)
, eta_(0.002)
, alpha_(0.05)
, lambda_(1.5)
, use_primitive_term_(true)
, merge_rounds_(3)
, seed_(0x5e6a7u)
{}

void
MatRegionGrowing::setInputGraph(const MatGraph::ConstPtr& graph)
{
  graph_ = graph;
}

void
MatRegionGrowing::setStructureTags(const StructureTags& tags)
{
  tags_ = tags;
}

void
MatRegionGrowing::setGrowingThreshold(double delta0)
{
  if (!(delta0 > 0.0) || !std::isfinite(delta0)) {
    PCL_WARN("[segmat::MatRegionGrowing::setGrowingThreshold] %g is not > 0; keeping %g.\n",
             delta0, delta0_);
    return;
  }
  delta0_ = delta0;
}

void
MatRegionGrowing::setMinRegionFraction(double eta)
{
  if (!(eta >= 0.0 && eta <= 1.0)) {
    PCL_WARN("[segmat::MatRegionGrowing::setMinRegionFraction] %g is not in [0, 1]; keeping %g.\n",
             eta, eta_);
    return;
  }
  eta_ = eta;
}

void
MatRegionGrowing::setAngleWeight(double alpha)
{
  if (!(alpha >= 0.0) || !std::isfinite(alpha)) {
    PCL_WARN("[segmat::MatRegionGrowing::setAngleWeight] %g is not >= 0; keeping %g.\n", alpha,
             alpha_);
    return;
  }
  alpha_ = alpha;
}

void
MatRegionGrowing::setPrimitiveWeight(double lambda)
{
  if (!(lambda >= 0.0) || !std::isfinite(lambda)) {
    PCL_WARN("[segmat::MatRegionGrowing::setPrimitiveWeight] %g is not >= 0; keeping %g.\n",
             lambda, lambda_);
    return;
  }
  lambda_ = lambda;
}

void
MatRegionGrowing::setMergeRounds(int rounds)
{
  if (rounds < 0 || rounds > 3) {
    PCL_WARN("[segmat::MatRegionGrowing::setMergeRounds] %d is not in [0, 3]; keeping %d.\n",
             rounds, merge_rounds_);
    return;
  }
  merge_rounds_ = rounds;
}

void
MatRegionGrowing::clearOutput()
{
  coarse_parts_.clear();
  node_labels_.clear();
  grown_region_sizes_.clear();
  tiny_patch_sizes_.clear();
}

bool
MatRegionGrowing::extract(std::vector<pcl::PointIndices>& parts)
{
  parts.clear();
  clearOutput();
  if (!graph_ || graph_->empty()) {
    PCL_ERROR("[segmat::MatRegionGrowing::extract] No input graph, or it is empty.\n");
    return false;
  }
  // STUB: one part holding every node (the real grower lands on branch `grower`).
  const int n = static_cast<int>(graph_->numNodes());
  parts.resize(1);
  coarse_parts_.resize(1);
  node_labels_.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    parts[0].indices.push_back(i);
    coarse_parts_[0].push_back(i);
  }
  return true;
}

} // namespace segmat
