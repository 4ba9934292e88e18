/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <memory>
#include <vector>

namespace flann {
template <class T> struct L2_Simple;
template <typename Distance> class KDTreeSingleIndex;
} // namespace flann

namespace segmat {
namespace detail {

/** Exact k-nearest and radius search on 3D points, with pcl::KdTreeFLANN<pcl::PointXYZ>'s
 * interface and answers: the same FLANN tree (single kd-tree, 15 points per leaf), the same
 * exact search and result sets, results sorted, non-finite points left out and indices mapped
 * back to the cloud (or to \a indices) as KdTreeFLANN does. What it saves is KdTreeFLANN's cost
 * per query — it goes through flann::Index, which opens an OpenMP region and allocates for every
 * single query: the 16 nearest of each of 100 000 teddy points take 0.75 s there and 0.28 s
 * here (`build/bin/bench_kd_tree`, one core). Queries are const and may run on several threads
 * at once. */
class PointKdTree
{
public:
  using Cloud = pcl::PointCloud<pcl::PointXYZ>;

  PointKdTree();
  ~PointKdTree();
  PointKdTree(const PointKdTree&) = delete;
  PointKdTree& operator=(const PointKdTree&) = delete;

  /** Builds the tree on the finite points of \a cloud (only those listed in \a indices, when
   * given); the cloud is kept for getInputCloud(). */
  void setInputCloud(const Cloud::ConstPtr& cloud, const pcl::IndicesConstPtr& indices = nullptr);
  const Cloud::ConstPtr& getInputCloud() const { return cloud_; }

  /** Whether radiusSearch() sorts its answers (default: yes); k-nearest answers are always
   * sorted. As KdTreeFLANN::setSortedResults. */
  void setSortedResults(bool sorted) { sorted_ = sorted; }

  /** The \a k nearest points (fewer when the tree holds fewer), nearest first; returns their
   * count. \a sq_distances are squared. */
  int nearestKSearch(const pcl::PointXYZ& query, int k, pcl::Indices& indices,
                     std::vector<float>& sq_distances) const;

  /** The points within \a radius (at most \a max_nn of them when it is > 0), nearest first;
   * returns their count. */
  int radiusSearch(const pcl::PointXYZ& query, double radius, pcl::Indices& indices,
                   std::vector<float>& sq_distances, unsigned int max_nn = 0) const;

private:
  using Index = flann::KDTreeSingleIndex<flann::L2_Simple<float>>;

  Cloud::ConstPtr cloud_;
  std::vector<float> data_;     ///< the indexed coordinates, 3 per point
  std::vector<int> to_cloud_;   ///< tree point → cloud index
  std::unique_ptr<Index> index_;
  bool sorted_ = true;
};

} // namespace detail
} // namespace segmat
