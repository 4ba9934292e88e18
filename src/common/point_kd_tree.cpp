/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "point_kd_tree.h"

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>
#include <flann/util/result_set.h>

#include <algorithm>
#include <cmath>

namespace segmat {
namespace detail {
namespace {

/// FLANN's own switch from the insertion-sorted to the heap result set (KNN_HEAP_THRESHOLD);
/// the same switch keeps the answers, ties included, those of KdTreeFLANN.
constexpr int kHeapThreshold = 250;

/// Copies a FLANN result set into PCL-style outputs, mapping tree points to cloud indices.
template <typename ResultSet>
int
copyResults(ResultSet& results, std::size_t count, bool sorted, const std::vector<int>& to_cloud,
            pcl::Indices& indices, std::vector<float>& sq_distances)
{
  std::vector<std::size_t> found(count);
  sq_distances.resize(count);
  if (count > 0)
    results.copy(found.data(), sq_distances.data(), count, sorted);
  indices.resize(count);
  for (std::size_t i = 0; i < count; ++i)
    indices[i] = to_cloud[found[i]];
  return static_cast<int>(count);
}

} // namespace

PointKdTree::PointKdTree() = default;
PointKdTree::~PointKdTree() = default;

void
PointKdTree::setInputCloud(const Cloud::ConstPtr& cloud, const pcl::IndicesConstPtr& indices)
{
  cloud_ = cloud;
  index_.reset();
  data_.clear();
  to_cloud_.clear();
  if (!cloud)
    return;
  const std::size_t count = indices ? indices->size() : cloud->size();
  data_.reserve(3 * count);
  to_cloud_.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int c = indices ? (*indices)[i] : static_cast<int>(i);
    const pcl::PointXYZ& p = (*cloud)[c];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    data_.insert(data_.end(), {p.x, p.y, p.z});
    to_cloud_.push_back(c);
  }
  if (to_cloud_.empty())
    return;
  // 15 points per leaf, as KdTreeFLANN builds it.
  index_ = std::make_unique<Index>(flann::Matrix<float>(data_.data(), to_cloud_.size(), 3),
                                   flann::KDTreeSingleIndexParams(15));
  index_->buildIndex();
}

int
PointKdTree::nearestKSearch(const pcl::PointXYZ& query, int k, pcl::Indices& indices,
                            std::vector<float>& sq_distances) const
{
  k = std::min(k, static_cast<int>(to_cloud_.size()));
  if (!index_ || k <= 0) {
    indices.clear();
    sq_distances.clear();
    return 0;
  }
  const float q[3] = {query.x, query.y, query.z};
  const flann::SearchParams params(-1, 0.0f, true);
  if (k > kHeapThreshold) {
    flann::KNNResultSet2<float> results(k);
    index_->findNeighbors(results, q, params);
    return copyResults(results, std::min<std::size_t>(results.size(), k), true, to_cloud_, indices,
                       sq_distances);
  }
  flann::KNNSimpleResultSet<float> results(k);
  index_->findNeighbors(results, q, params);
  return copyResults(results, std::min<std::size_t>(results.size(), k), true, to_cloud_, indices,
                     sq_distances);
}

int
PointKdTree::radiusSearch(const pcl::PointXYZ& query, double radius, pcl::Indices& indices,
                          std::vector<float>& sq_distances, unsigned int max_nn) const
{
  if (!index_) {
    indices.clear();
    sq_distances.clear();
    return 0;
  }
  const float q[3] = {query.x, query.y, query.z};
  const float sq_radius = static_cast<float>(radius * radius);
  const flann::SearchParams params(-1, 0.0f, sorted_);
  if (max_nn == 0 || max_nn >= to_cloud_.size()) {
    flann::RadiusResultSet<float> results(sq_radius);
    index_->findNeighbors(results, q, params);
    return copyResults(results, results.size(), sorted_, to_cloud_, indices, sq_distances);
  }
  flann::KNNRadiusResultSet<float> results(sq_radius, max_nn);
  index_->findNeighbors(results, q, params);
  return copyResults(results, std::min<std::size_t>(results.size(), max_nn), sorted_, to_cloud_,
                     indices, sq_distances);
}

} // namespace detail
} // namespace segmat
