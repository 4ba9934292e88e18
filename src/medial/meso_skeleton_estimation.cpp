/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/medial/meso_skeleton_estimation.h>
#include <segmat/medial/shrinking_ball_estimation.h>
#include <segmat/medial/voxel_sampling.h>
#include <segmat/medial/impl/meso_skeleton_estimation.hpp>

#include "thread_count.h"

#include <pcl/console/print.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace segmat {
namespace detail {
namespace {

double
secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
toXYZ(const std::vector<Eigen::Vector3f>& points)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    (*cloud)[i].getVector3fMap() = points[i];
  return cloud;
}

/// Eigen-decomposition of the covariance of \a points[nn] (ascending eigenvalues).
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>
neighbourhoodPca(const std::vector<Eigen::Vector3f>& points, const pcl::Indices& nn)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j : nn)
    mean += points[j].cast<double>();
  mean /= double(nn.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int j : nn) {
    const Eigen::Vector3d d = points[j].cast<double>() - mean;
    cov += d * d.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov / double(nn.size()));
}

double
workingDiagonal(const pcl::PointCloud<pcl::PointNormal>& cloud)
{
  Eigen::Vector3f lo = cloud[0].getVector3fMap(), hi = lo;
  for (const pcl::PointNormal& p : cloud) {
    lo = lo.cwiseMin(p.getVector3fMap());
    hi = hi.cwiseMax(p.getVector3fMap());
  }
  return (hi - lo).cast<double>().norm();
}

/// A neighbourhood is curve-like when its middle spread is small next to its largest.
constexpr double kCurveRatio = 0.1;

bool
curveLike(const Eigen::Vector3d& eigenvalues)
{
  return eigenvalues[1] < kCurveRatio * eigenvalues[2];
}

/// Radius-outlier filter: keeps i when r_i / median(r of its k nearest) is in [1/ratio, ratio].
std::vector<int>
radiusInliers(const std::vector<Eigen::Vector3f>& centres, const std::vector<float>& radii,
              int k, float ratio, int threads)
{
  const int n = static_cast<int>(centres.size());
  if (n <= 2 || k <= 0) {
    std::vector<int> all(n);
    for (int i = 0; i < n; ++i)
      all[i] = i;
    return all;
  }
  const auto cloud = toXYZ(centres);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  const int kk = std::min(k, n - 1) + 1;
  std::vector<char> keep(n, 0);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2, r;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      tree.nearestKSearch((*cloud)[i], kk, nn, d2);
      r.clear();
      for (int j : nn)
        if (j != i)
          r.push_back(radii[j]);
      if (r.empty()) {
        keep[i] = 1;
        continue;
      }
      std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
      const float median = r[r.size() / 2];
      keep[i] = radii[i] <= ratio * median && radii[i] * ratio >= median;
    }
  }
  std::vector<int> kept;
  for (int i = 0; i < n; ++i)
    if (keep[i])
      kept.push_back(i);
  return kept;
}

/// One contraction pass: each centre moves towards the Gaussian-weighted mean of its k nearest,
/// only across the local structure (Jacobi update: all moves computed from the old positions).
void
contractOnce(std::vector<Eigen::Vector3f>& centres, int k, int threads)
{
  const int n = static_cast<int>(centres.size());
  if (n < 3)
    return;
  const auto cloud = toXYZ(centres);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  const int kk = std::min(k, n - 1) + 1;
  std::vector<Eigen::Vector3f> moved(centres);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      tree.nearestKSearch((*cloud)[i], kk, nn, d2);
      if (nn.size() < 3)
        continue;
      const double h2 = std::max(double(d2.back()), 1e-30);
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      double weight = 0.0;
      for (std::size_t a = 0; a < nn.size(); ++a) {
        const double w = std::exp(-double(d2[a]) / h2);
        mean += w * centres[nn[a]].cast<double>();
        weight += w;
      }
      mean /= weight;
      const auto pca = neighbourhoodPca(centres, nn);
      const Eigen::Vector3d step = mean - centres[i].cast<double>();
      Eigen::Vector3d across;
      if (curveLike(pca.eigenvalues())) {
        const Eigen::Vector3d t = pca.eigenvectors().col(2);
        across = step - t.dot(step) * t;
      }
      else {
        const Eigen::Vector3d nrm = pca.eigenvectors().col(0);
        across = nrm.dot(step) * nrm;
      }
      moved[i] = (centres[i].cast<double>() + across).cast<float>();
    }
  }
  centres.swap(moved);
}

} // namespace

bool
estimateMesoSkeleton(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud, bool has_normals,
                     const MesoSkeletonParameters& params, pcl::PointCloud<MedialPoint>& skeleton,
                     pcl::PointCloud<pcl::PointNormal>& working, std::vector<int>& working_indices,
                     MesoSkeletonStatistics& stats)
{
  skeleton.clear();
  working.clear();
  working_indices.clear();
  stats = MesoSkeletonStatistics();
  stats.input_points = cloud ? cloud->size() : 0;
  const int threads = threadCount(params.threads);

  // 1. Working cloud.
  auto start = std::chrono::steady_clock::now();
  CloudPreprocessing preprocessing;
  preprocessing.setInputCloud(cloud);
  preprocessing.setWorkingSize(params.working_size);
  preprocessing.setNormalKSearch(params.normal_k);
  preprocessing.setOrientationKSearch(params.orientation_k);
  preprocessing.setUseInputNormalsFlag(has_normals);
  preprocessing.setNumberOfThreads(static_cast<unsigned int>(threads));
  pcl::PointCloud<pcl::PointNormal>::Ptr surface(new pcl::PointCloud<pcl::PointNormal>);
  if (!preprocessing.compute(*surface))
    return false;
  working_indices = preprocessing.getWorkingIndices();
  working = *surface;
  stats.working_points = surface->size();
  stats.normals_estimated = preprocessing.getNormalsEstimated();
  stats.seconds_preprocessing = secondsSince(start);

  // 2. Shrinking balls.
  start = std::chrono::steady_clock::now();
  ShrinkingBallEstimation balls_estimation;
  balls_estimation.setInputCloud(surface);
  if (params.ball_count > 0 && params.ball_count < surface->size()) {
    std::vector<Eigen::Vector3f> positions(surface->size());
    for (std::size_t i = 0; i < surface->size(); ++i)
      positions[i] = (*surface)[i].getVector3fMap();
    balls_estimation.setIndices(std::make_shared<const std::vector<int>>(
        voxelRepresentativesNear(positions, params.ball_count)));
  }
  balls_estimation.setInitialRadius(params.initial_radius);
  balls_estimation.setDenoisePreserveAngle(params.preserve_angle);
  balls_estimation.setDenoisePlanarAngle(params.planar_angle);
  balls_estimation.setMaxIterations(params.max_iterations);
  balls_estimation.setNumberOfThreads(static_cast<unsigned int>(threads));
  pcl::PointCloud<MedialPoint> balls;
  if (!balls_estimation.compute(balls))
    return false;
  stats.balls = balls.size();
  stats.seconds_balls = secondsSince(start);
  start = std::chrono::steady_clock::now();

  // 3. Filters: valid, separation angle, radius outliers.
  const std::vector<float>& separation = balls_estimation.getSeparationAngles();
  std::vector<int> candidates;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!std::isfinite(balls[i].radius))
      continue;
    ++stats.valid_balls;
    if (separation[i] >= params.min_separation_angle)
      candidates.push_back(static_cast<int>(i));
  }
  std::vector<Eigen::Vector3f> centres;
  std::vector<float> radii;
  for (int i : candidates) {
    centres.push_back(balls[i].getVector3fMap());
    radii.push_back(balls[i].radius);
  }
  const std::vector<int> inliers =
      radiusInliers(centres, radii, params.outlier_k, params.outlier_ratio, threads);
  std::vector<int> ball_of(inliers.size());
  std::vector<Eigen::Vector3f> kept(inliers.size());
  for (std::size_t i = 0; i < inliers.size(); ++i) {
    ball_of[i] = candidates[inliers[i]];
    kept[i] = centres[inliers[i]];
  }
  stats.filtered_balls = kept.size();
  if (kept.empty()) {
    PCL_ERROR("[segmat::MesoSkeletonEstimation::compute] No interior ball survived (%zu of %zu "
              "valid): the cloud encloses no volume (flat, open or too noisy).\n",
              stats.valid_balls, stats.balls);
    stats.seconds_medial = secondsSince(start);
    return false;
  }

  // 4. Contraction.
  for (int it = 0; it < params.contraction_iterations; ++it)
    contractOnce(kept, params.contraction_k, threads);

  // 5. Reduction.
  // A sphere's balls all land near its centre: a minimum voxel keeps such a blob a few points.
  const std::vector<int> reduced = voxelRepresentativesNear(
      kept, params.target_size, nullptr, params.min_spacing * workingDiagonal(*surface));
  std::vector<Eigen::Vector3f> points(reduced.size());
  for (std::size_t i = 0; i < reduced.size(); ++i)
    points[i] = kept[reduced[i]];

  // 6. Radius from the working cloud, normal from the medial neighbourhood.
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface_xyz(new pcl::PointCloud<pcl::PointXYZ>);
  surface_xyz->resize(surface->size());
  for (std::size_t i = 0; i < surface->size(); ++i)
    (*surface_xyz)[i].getVector3fMap() = (*surface)[i].getVector3fMap();
  pcl::KdTreeFLANN<pcl::PointXYZ> surface_tree;
  surface_tree.setInputCloud(surface_xyz);
  const auto medial_xyz = toXYZ(points);
  pcl::KdTreeFLANN<pcl::PointXYZ> medial_tree;
  medial_tree.setInputCloud(medial_xyz);
  const int m = static_cast<int>(points.size());
  const int normal_k = std::min(std::max(params.medial_normal_k, 2), m - 1) + 1;
  skeleton.resize(m);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int i = 0; i < m; ++i) {
      MedialPoint& out = skeleton[i];
      out.getVector3fMap() = points[i];
      surface_tree.nearestKSearch((*medial_xyz)[i], 1, nn, d2);
      out.radius = std::sqrt(d2[0]);
      out.surface_index = working_indices[nn[0]];
      const int contact = balls[ball_of[reduced[i]]].contact_index;
      out.contact_index = contact >= 0 ? working_indices[contact] : -1;
      Eigen::Vector3f normal = Eigen::Vector3f::Zero();
      if (normal_k >= 3) {
        medial_tree.nearestKSearch((*medial_xyz)[i], normal_k, nn, d2);
        const auto pca = neighbourhoodPca(points, nn);
        if (pca.info() == Eigen::Success && pca.eigenvalues()[2] > 0.0)
          normal = pca.eigenvectors().col(curveLike(pca.eigenvalues()) ? 2 : 0).cast<float>();
      }
      out.getNormalVector3fMap() = normal;
    }
  }
  skeleton.width = static_cast<std::uint32_t>(m);
  skeleton.height = 1;
  skeleton.is_dense = true;
  stats.medial_points = skeleton.size();
  stats.seconds_medial = secondsSince(start);
  return true;
}

} // namespace detail

} // namespace segmat

SEGMAT_INSTANTIATE_MesoSkeletonEstimation(pcl::PointXYZ)
SEGMAT_INSTANTIATE_MesoSkeletonEstimation(pcl::PointNormal)
SEGMAT_INSTANTIATE_MesoSkeletonEstimation(pcl::PointXYZRGBNormal)
