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

#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
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

/// Where point \a self lies on its own side of the surface: a quadratic height field over the
/// neighbourhood's PCA tangent plane, fitted with spatial weights exp(−d²/support²) times
/// Gaussian weights (bandwidth \a band) on each neighbour's residual, refitted a few times
/// from the plane through the point itself. The residual weights are what keep the two sides of
/// a thin wall apart: a plain fit over neighbours from both sides lands in the middle of the
/// wall and flattens the wall into one sheet (the winding number then sees no volume there).
Eigen::Vector3f
sidedHeightFit(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn,
               const std::vector<float>& d2, double support, double band)
{
  const auto pca = detail::neighbourhoodPca(points, nn);
  const Eigen::Vector3d n = pca.eigenvectors().col(0), e1 = pca.eigenvectors().col(1),
                        e2 = pca.eigenvectors().col(2);
  const Eigen::Vector3d origin = points[self].cast<double>();
  const std::size_t m = nn.size();
  std::vector<Eigen::Matrix<double, 6, 1>> basis(m);
  std::vector<double> height(m), spatial(m);
  for (std::size_t a = 0; a < m; ++a) {
    const Eigen::Vector3d d = points[nn[a]].cast<double>() - origin;
    const double u = d.dot(e1) / support, v = d.dot(e2) / support; // unit-free: well posed
    basis[a] << 1.0, u, v, u * u, u * v, v * v;
    height[a] = d.dot(n);
    spatial[a] = std::exp(-double(d2[a]) / (support * support));
  }
  // From the plane through the point, with a wide residual band that narrows: a narrow band at
  // once would leave too few neighbours on a curved surface to fix six coefficients. A small
  // ridge on the curvature terms keeps the fit posed where few neighbours remain.
  Eigen::Matrix<double, 6, 1> coef = Eigen::Matrix<double, 6, 1>::Zero();
  const double bands[] = {4.0 * band, 2.0 * band, band, band};
  for (const double b : bands) {
    const double inv_band2 = 1.0 / (2.0 * b * b);
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    double total = 0.0;
    for (std::size_t a = 0; a < m; ++a) {
      const double r = height[a] - basis[a].dot(coef);
      const double w = spatial[a] * std::exp(-r * r * inv_band2);
      normal += w * basis[a] * basis[a].transpose();
      rhs += w * height[a] * basis[a];
      total += w;
    }
    if (!(total > 1e-6))
      break;
    for (int c = 3; c < 6; ++c)
      normal(c, c) += 1e-3 * total;
    const Eigen::Matrix<double, 6, 1> next = normal.ldlt().solve(rhs);
    if (!next.allFinite())
      break;
    coef = next;
  }
  return (origin + coef[0] * n).cast<float>();
}

double
median(std::vector<float> values)
{
  if (values.empty())
    return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return double(values[values.size() / 2]);
}

/// Calls visit(s, i, nn, d2) for i = s · stride (s = 0, 1, ...) with the \a k nearest neighbours
/// of point i of the tree's cloud (i itself first), on \a threads threads. Each s is visited
/// once, so what visit writes to slot s does not depend on the thread count.
template <typename Visit>
void
forEachNeighbourhood(const detail::PointKdTree& tree, int k, int stride, int threads,
                     Visit visit)
{
  const auto& cloud = *tree.getInputCloud();
  const int count = (static_cast<int>(cloud.size()) + stride - 1) / stride;
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int s = 0; s < count; ++s)
      if (tree.nearestKSearch(cloud[s * stride], k, nn, d2) > 0)
        visit(s, s * stride, nn, d2);
  }
}

/// The cloud's noise and spacing, from every \a stride-th point: the median offset of a point
/// from the PCA plane of its 8 nearest neighbours (near enough to stay on its side of a thin
/// wall; a wider PCA would measure the wall's thickness), scaled to a Gaussian σ (÷ 0.6745),
/// and the median distance to the nearest neighbour.
std::pair<double, double>
noiseAndSpacing(const std::vector<Eigen::Vector3f>& positions,
                const detail::PointKdTree& tree, int stride, int threads)
{
  const int n = static_cast<int>(positions.size());
  const int count = (n + stride - 1) / stride;
  std::vector<float> noise(count, 0.0f), spacing(count, 0.0f);
  forEachNeighbourhood(tree, std::min(8, n), stride, threads,
                       [&](int s, int i, const pcl::Indices& near, const std::vector<float>& d2) {
                         if (near.size() < 4)
                           return;
                         const auto pca = detail::neighbourhoodPca(positions, near);
                         Eigen::Vector3d mean = Eigen::Vector3d::Zero();
                         for (int j : near)
                           mean += positions[j].cast<double>();
                         mean /= double(near.size());
                         noise[s] = float(std::abs((positions[i].cast<double>() - mean)
                                                       .dot(pca.eigenvectors().col(0))));
                         spacing[s] = std::sqrt(d2[1]); // [0] is the point itself
                       });
  return {median(noise) / 0.6745, median(spacing)};
}

/// One pass of sided quadratic (MLS-like) smoothing: every point moves onto the height field
/// of its own side fitted to its k nearest neighbours (sidedHeightFit). A plane fit would
/// pull thin tubes inwards by about a²/(4R) (a the neighbourhood's size); a quadratic does not.
/// The residual bandwidth is 1.5 × the cloud's noise (noiseAndSpacing, floored at a tenth of the
/// spacing). Nothing moves when that noise is below \a min_noise_ratio × the spacing.
/// Returns the median move divided by the median spacing (0 when nothing moved).
double
smoothSurface(std::vector<Eigen::Vector3f>& positions, int k, int threads, double min_noise_ratio)
{
  const int n = static_cast<int>(positions.size());
  if (n < 6)
    return 0.0;
  const auto cloud = detail::toXYZ(positions);
  detail::PointKdTree tree;
  tree.setInputCloud(cloud);
  // A quarter of the points tells the noise as well as all of them, at a quarter of the cost
  // that a clean cloud pays for finding out it is clean.
  const auto [noise, spacing] = noiseAndSpacing(positions, tree, 4, threads);
  const double band = std::max(1.5 * noise, 0.1 * spacing);
  if (!(spacing > 0.0) || noise < min_noise_ratio * spacing)
    return 0.0;
  const int kk = std::min(k, n);
  std::vector<Eigen::Vector3f> moved(positions);
  std::vector<float> moves(n, 0.0f);
  forEachNeighbourhood(tree, kk, 1, threads,
                       [&](int, int i, const pcl::Indices& nn, const std::vector<float>& d2) {
                         if (nn.size() < 6 || !(d2.back() > 0.0f))
                           return;
                         moved[i] = sidedHeightFit(positions, i, nn, d2,
                                                   std::sqrt(double(d2.back())), band);
                         moves[i] = (moved[i] - positions[i]).norm();
                       });
  positions.swap(moved);
  return median(moves) / spacing;
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
  std::vector<Eigen::Vector3f> positions(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    positions[i] = in[candidates[i]].getVector3fMap();
  // representative[c]: the candidate (position in candidates) standing for candidate c.
  std::vector<int> representative(candidates.size());
  const double voxel = voxelSizeForCount(positions, working_size_);
  std::vector<int> kept;
  if (voxel > 0.0)
    kept = voxelRepresentatives(positions, voxel, &representative);
  else {
    kept.resize(candidates.size());
    std::iota(kept.begin(), kept.end(), 0);
    representative = kept;
  }
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
    if (!estimate)
      cloud[i].getNormalVector3fMap().normalize();
  }

  // 3. Estimated normals: smoothing, PCA, then MST orientation.
  if (estimate) {
    normals_estimated_ = true;
    const int threads = detail::threadCount(threads_);
    std::vector<Eigen::Vector3f> positions(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      positions[i] = cloud[i].getVector3fMap();
    // A clean sample is left as it is (its offsets from the local planes are 2–4 % of the
    // spacing; a scan with noise shows 30 % and more); a noisy one gets passes while they
    // still move points by a noticeable part of the spacing.
    constexpr double kNoisyRatio = 0.1, kStillRatio = 0.05;
    for (int it = 0; it < smoothing_iterations_; ++it) {
      const double moved =
          smoothSurface(positions, 2 * normal_k_, threads, it == 0 ? kNoisyRatio : 0.0);
      if (moved > 0.0)
        ++smoothing_passes_;
      if (moved < kStillRatio)
        break;
    }
    for (std::size_t i = 0; i < cloud.size(); ++i)
      cloud[i].getVector3fMap() = positions[i];
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
