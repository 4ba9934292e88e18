/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/medial/normal_orientation.h>
#include <segmat/medial/voxel_sampling.h>

#include <pcl/console/print.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace segmat {
namespace {

bool
finitePoint(const pcl::PointNormal& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool
usableNormal(const pcl::PointNormal& p)
{
  const Eigen::Vector3f n = p.getNormalVector3fMap();
  return n.allFinite() && n.squaredNorm() > 0.0f;
}

/// Removes exact coordinate duplicates from \a indices (keeps the lowest index), keeps order.
void
dropExactDuplicates(const pcl::PointCloud<pcl::PointNormal>& cloud, std::vector<int>& indices)
{
  std::vector<int> order = indices;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::make_tuple(cloud[a].x, cloud[a].y, cloud[a].z, a) <
           std::make_tuple(cloud[b].x, cloud[b].y, cloud[b].z, b);
  });
  std::vector<char> drop(cloud.size(), 0);
  bool any = false;
  for (std::size_t i = 1; i < order.size(); ++i)
    if (cloud[order[i]].getVector3fMap() == cloud[order[i - 1]].getVector3fMap()) {
      drop[order[i]] = 1;
      any = true;
    }
  if (any)
    indices.erase(std::remove_if(indices.begin(), indices.end(), [&](int i) { return drop[i]; }),
                  indices.end());
}

} // namespace

CloudPreprocessing::CloudPreprocessing()
: working_size_(20000), normal_k_(16), orientation_k_(10), use_input_normals_(true), threads_(0)
{}

void
CloudPreprocessing::setWorkingSize(std::size_t size)
{
  if (size == 0) {
    PCL_WARN("[segmat::CloudPreprocessing::setWorkingSize] The size must be positive; keeping "
             "%zu.\n", working_size_);
    return;
  }
  working_size_ = size;
}

void
CloudPreprocessing::setNormalKSearch(int k)
{
  if (k < 3) {
    PCL_WARN("[segmat::CloudPreprocessing::setNormalKSearch] k must be at least 3; keeping "
             "%d.\n", normal_k_);
    return;
  }
  normal_k_ = k;
}

void
CloudPreprocessing::setOrientationKSearch(int k)
{
  if (k <= 0) {
    PCL_WARN("[segmat::CloudPreprocessing::setOrientationKSearch] k must be positive; keeping "
             "%d.\n", orientation_k_);
    return;
  }
  orientation_k_ = k;
}

bool
CloudPreprocessing::compute(pcl::PointCloud<pcl::PointNormal>& working)
{
  working.clear();
  working_indices_.clear();
  normals_estimated_ = false;
  if (!input_ || input_->empty()) {
    PCL_ERROR("[segmat::CloudPreprocessing::compute] No input cloud, or it is empty.\n");
    return false;
  }
  const PointCloudIn& in = *input_;

  // 1. Finite points; input normals when asked for and good enough.
  std::vector<int> candidates;
  candidates.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    if (finitePoint(in[i]))
      candidates.push_back(static_cast<int>(i));
  if (candidates.empty()) {
    PCL_ERROR("[segmat::CloudPreprocessing::compute] The cloud has no finite point.\n");
    return false;
  }
  bool estimate = !use_input_normals_;
  if (!estimate) {
    const auto bad = std::count_if(candidates.begin(), candidates.end(),
                                   [&](int i) { return !usableNormal(in[i]); });
    if (bad > 0 && std::size_t(bad) * 100 > candidates.size()) {
      PCL_WARN("[segmat::CloudPreprocessing::compute] %zu of %zu input normals are unusable; "
               "estimating normals instead.\n", std::size_t(bad), candidates.size());
      estimate = true;
    }
    else if (bad > 0)
      candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                      [&](int i) { return !usableNormal(in[i]); }),
                       candidates.end());
  }

  // 2. Resample to the working size, then drop exact duplicates.
  std::vector<Eigen::Vector3f> positions(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    positions[i] = in[candidates[i]].getVector3fMap();
  std::vector<int> kept = voxelRepresentativesNear(positions, working_size_);
  for (int& k : kept)
    k = candidates[k];
  dropExactDuplicates(in, kept);
  if (kept.size() < 3) {
    PCL_ERROR("[segmat::CloudPreprocessing::compute] %zu distinct finite point(s): at least 3 "
              "are needed.\n", kept.size());
    return false;
  }

  pcl::PointCloud<pcl::PointNormal> cloud;
  cloud.resize(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    cloud[i] = in[kept[i]];
    cloud[i].curvature = 0.0f;
    if (!estimate)
      cloud[i].getNormalVector3fMap().normalize();
  }

  // 3. Estimated normals: PCA, then MST orientation.
  if (estimate) {
    normals_estimated_ = true;
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    xyz->resize(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      (*xyz)[i].getVector3fMap() = cloud[i].getVector3fMap();
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation(threads_);
    estimation.setInputCloud(xyz);
    estimation.setSearchMethod(pcl::search::KdTree<pcl::PointXYZ>::Ptr(
        new pcl::search::KdTree<pcl::PointXYZ>));
    estimation.setKSearch(std::min<int>(normal_k_, static_cast<int>(cloud.size())));
    pcl::PointCloud<pcl::Normal> normals;
    estimation.compute(normals);
    std::vector<int> usable;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Eigen::Vector3f nv = normals[i].getNormalVector3fMap();
      if (nv.allFinite() && nv.squaredNorm() > 0.0f) {
        cloud[i].getNormalVector3fMap() = nv.normalized();
        cloud[i].curvature = normals[i].curvature;
        usable.push_back(static_cast<int>(i));
      }
    }
    if (usable.size() < 3) {
      PCL_ERROR("[segmat::CloudPreprocessing::compute] No usable normal could be estimated "
                "(degenerate cloud).\n");
      return false;
    }
    if (usable.size() < cloud.size()) {
      pcl::PointCloud<pcl::PointNormal> subset;
      std::vector<int> subset_kept;
      for (int i : usable) {
        subset.push_back(cloud[i]);
        subset_kept.push_back(kept[i]);
      }
      cloud.swap(subset);
      kept.swap(subset_kept);
    }
    NormalOrientation orientation;
    orientation.setKSearch(orientation_k_);
    if (!orientation.orient(cloud))
      return false;
  }

  working.swap(cloud);
  working.width = static_cast<std::uint32_t>(working.size());
  working.height = 1;
  working.is_dense = true;
  working_indices_.swap(kept);
  return true;
}

} // namespace segmat
