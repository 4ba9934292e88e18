/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/medial/normal_orientation.h>
#include <segmat/medial/voxel_sampling.h>

#include "../common/point_kd_tree.h"
#include "../common/thread_count.h"
#include "local_fit.h"
#include "surface_denoising.h"

#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace segmat {
namespace {

using detail::forEachNeighbourhood;
using detail::median;

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

/// Float coordinates resolve ~1.2e-7 of their magnitude: a cloud far from 0 for its size
/// (georeferenced scans) is a grid before any step here sees it, and nothing downstream can
/// tell its cuts from the grid's. Said once, where the cause is still visible.
void
warnIfFarFromOrigin(const pcl::PointCloud<pcl::PointNormal>& cloud, const std::vector<int>& indices)
{
  Eigen::AlignedBox3f box;
  for (int i : indices)
    box.extend(cloud[i].getVector3fMap());
  const double magnitude = box.center().cwiseAbs().maxCoeff();
  const double diagonal = box.diagonal().norm();
  const double resolution = magnitude * std::numeric_limits<float>::epsilon();
  if (diagonal > 0.0 && resolution > 1e-4 * diagonal)
    PCL_WARN("[segmat::CloudPreprocessing::compute] The cloud lies %g from the origin, %g times "
             "its diagonal: float coordinates there resolve only %g (%.2g %% of the diagonal), "
             "so the points sit on a grid. Move the cloud next to the origin first "
             "(segmat::io::loadCloud does so for files).\n",
             magnitude, magnitude / diagonal, resolution, 100.0 * resolution / diagonal);
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


/// Removes from \a indices the points standing apart from the surface (scanner outliers: flying
/// pixels, dust): those whose mean distance to their 8 nearest neighbours exceeds 4 times the
/// cloud's median and twice the median of their neighbours' own. Each would be a surface
/// sample of its own, and the Voronoi balls between it and the surface are spurious medial
/// spheres. Runs on the resampled points: an outlier keeps its own voxel, so it is still there,
/// and the work stays at the working size. Not pcl::StatisticalOutlierRemoval: its limit (mean
/// plus a multiple of the standard deviation of the same distances, over the whole cloud) has
/// no neighbourhood test, and a global limit alone drops the sparse side of a scan with the
/// outliers (CloudPreprocessing.SetsIsolatedPointsAsideButKeepsSparseRegions).
void
dropIsolatedPoints(const pcl::PointCloud<pcl::PointNormal>& cloud, std::vector<int>& indices,
                   int threads)
{
  constexpr int kNeighbours = 8;
  constexpr float kFactor = 4.0f, kLocalFactor = 2.0f;
  const int n = static_cast<int>(indices.size());
  if (n <= 2 * kNeighbours)
    return;
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  xyz->resize(n);
  for (int i = 0; i < n; ++i)
    (*xyz)[i].getVector3fMap() = cloud[indices[i]].getVector3fMap();
  detail::PointKdTree tree;
  tree.setInputCloud(xyz);
  std::vector<float> mean_distance(n, 0.0f);
  forEachNeighbourhood(tree, kNeighbours + 1, 1, threads,
                       [&](int, int i, const pcl::Indices&, const std::vector<float>& d2) {
                         for (std::size_t k = 1; k < d2.size(); ++k) // [0]: the point itself
                           mean_distance[i] += std::sqrt(d2[k]) / float(d2.size() - 1);
                       });
  const float limit = kFactor * median(mean_distance);
  if (!(limit > 0.0f))
    return;
  std::vector<int> kept;
  kept.reserve(n);
  pcl::Indices nn;
  std::vector<float> d2, around;
  for (int i = 0; i < n; ++i) {
    bool isolated = mean_distance[i] > limit;
    if (isolated) {
      // A sparser region of the scan (range fall-off) is sparse all over: its points are as far
      // from their neighbours as those are from theirs, and it stays. Few points get here, so
      // their neighbours are searched again rather than stored for all.
      tree.nearestKSearch((*xyz)[i], kNeighbours + 1, nn, d2);
      around.clear();
      for (std::size_t k = 1; k < nn.size(); ++k)
        around.push_back(mean_distance[nn[k]]);
      isolated = around.empty() || mean_distance[i] > kLocalFactor * median(around);
    }
    if (!isolated)
      kept.push_back(indices[i]);
  }
  if (kept.size() != indices.size()) {
    PCL_DEBUG("[segmat::CloudPreprocessing::compute] %zu isolated point(s) set aside.\n",
              indices.size() - kept.size());
    indices.swap(kept);
  }
}

} // namespace

CloudPreprocessing::CloudPreprocessing()
: working_size_(20000)
, normal_k_(16)
, orientation_k_(10)
, smoothing_iterations_(5)
, use_input_normals_(true)
, threads_(0)
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

void
CloudPreprocessing::setSmoothingIterations(int iterations)
{
  if (iterations < 0) {
    PCL_WARN("[segmat::CloudPreprocessing::setSmoothingIterations] The count must be >= 0; "
             "keeping %d.\n", smoothing_iterations_);
    return;
  }
  smoothing_iterations_ = iterations;
}

bool
CloudPreprocessing::compute(pcl::PointCloud<pcl::PointNormal>& working)
{
  working.clear();
  working_indices_.clear();
  input_to_working_.clear();
  normals_estimated_ = false;
  smoothing_passes_ = 0;
  remaining_sigma_ = 0.0;
  noise_sigma_ = spacing_ = 0.0;
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
  warnIfFarFromOrigin(in, candidates);
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
  std::vector<Eigen::Vector3f> input_positions(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    input_positions[i] = in[candidates[i]].getVector3fMap();
  // representative[c]: the candidate (position in candidates) standing for candidate c.
  std::vector<int> representative(candidates.size());
  const double voxel = voxelSizeForCount(input_positions, working_size_);
  std::vector<int> kept;
  // Jittered picks: centre picks sit on a lattice of the grid's axes, which costs the clean
  // dense clouds of axis-aligned shapes their parts (docs/noise.md, "Dense clouds").
  if (voxel > 0.0)
    kept = voxelRepresentatives(input_positions, voxel, &representative, VoxelPick::Jittered);
  else {
    kept.resize(candidates.size());
    std::iota(kept.begin(), kept.end(), 0);
    representative = kept;
  }
  // The points that thinning set aside still measure the surface: the smoothing fits to them.
  const bool thinned = kept.size() < candidates.size();
  for (int& k : kept)
    k = candidates[k];
  dropExactDuplicates(in, kept);
  dropIsolatedPoints(in, kept, detail::threadCount(threads_));
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
  }

  // 3. Every cloud is tested for noise and, when noisy, smoothed. A clean cloud keeps the
  //    normals it came with (when they are used); a noisy one has them set aside and estimated
  //    from the smoothed points, as a cloud without normals: smoothing carries points that the
  //    noise moved across a thin wall onto its other side, where their own normals point the
  //    wrong way, and normals computed from noisy points are noisy themselves.
  const int threads = detail::threadCount(threads_);
  std::vector<Eigen::Vector3f> positions(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    positions[i] = cloud[i].getVector3fMap();
  const detail::SurfaceDenoising denoising =
      detail::denoiseCloudSurface(positions, 2 * normal_k_, smoothing_iterations_, threads,
                                  thinned ? &input_positions : nullptr);
  smoothing_passes_ = denoising.passes;
  remaining_sigma_ = denoising.remaining_sigma;
  noise_sigma_ = denoising.noise.sigma;
  spacing_ = denoising.noise.spacing;
  estimate = estimate || smoothing_passes_ > 0;
  normals_estimated_ = estimate;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    cloud[i].getVector3fMap() = positions[i];
    if (!estimate)
      cloud[i].getNormalVector3fMap().normalize();
  }
  if (estimate) {
    // PCL's PCA normal and viewpoint flip (as NormalEstimationOMP computes them, same answers),
    // with the neighbours from PointKdTree: pcl::search::KdTree's per-query set-up was most of
    // this step's time.
    const pcl::PointCloud<pcl::PointXYZ>::Ptr xyz = detail::toXYZ(positions);
    detail::PointKdTree tree;
    tree.setInputCloud(xyz);
    pcl::PointCloud<pcl::Normal> normals;
    normals.resize(cloud.size());
    for (auto& nrm : normals)
      nrm.normal_x = nrm.normal_y = nrm.normal_z = nrm.curvature =
          std::numeric_limits<float>::quiet_NaN();
    forEachNeighbourhood(
        tree, std::min<int>(normal_k_, static_cast<int>(cloud.size())), 1, threads,
        [&](int, int i, const pcl::Indices& near, const std::vector<float>&) {
          Eigen::Vector4f plane;
          float curvature;
          if (!pcl::computePointNormal(*xyz, near, plane, curvature))
            return;
          pcl::Normal& nrm = normals[i];
          nrm.normal_x = plane[0];
          nrm.normal_y = plane[1];
          nrm.normal_z = plane[2];
          nrm.curvature = curvature;
          pcl::flipNormalTowardsViewpoint((*xyz)[i], 0.0f, 0.0f, 0.0f, nrm.normal_x,
                                          nrm.normal_y, nrm.normal_z);
        });
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

  // Every finite input point's stand-in: its voxel representative when that survived, else
  // the nearest working point (dropped duplicates, dropped normals).
  std::vector<int> working_of_input(in.size(), -1);
  for (std::size_t w = 0; w < kept.size(); ++w)
    working_of_input[kept[w]] = static_cast<int>(w);
  input_to_working_.assign(in.size(), -1);
  std::vector<int> unresolved;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const int w = working_of_input[candidates[representative[c]]];
    if (w >= 0)
      input_to_working_[candidates[c]] = w;
  }
  for (std::size_t i = 0; i < in.size(); ++i)
    if (input_to_working_[i] < 0 && finitePoint(in[i]))
      unresolved.push_back(static_cast<int>(i));
  if (!unresolved.empty()) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    xyz->resize(cloud.size());
    for (std::size_t w = 0; w < cloud.size(); ++w)
      (*xyz)[w].getVector3fMap() = cloud[w].getVector3fMap();
    detail::PointKdTree tree;
    tree.setInputCloud(xyz);
    pcl::Indices nn;
    std::vector<float> d2;
    pcl::PointXYZ query;
    for (int i : unresolved) {
      query.getVector3fMap() = in[i].getVector3fMap();
      if (tree.nearestKSearch(query, 1, nn, d2) > 0)
        input_to_working_[i] = nn[0];
    }
  }

  working.swap(cloud);
  working.width = static_cast<std::uint32_t>(working.size());
  working.height = 1;
  working.is_dense = true;
  working_indices_.swap(kept);
  return true;
}

} // namespace segmat
