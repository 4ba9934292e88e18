/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/medial/meso_skeleton_estimation.h>
#include <segmat/medial/shrinking_ball_estimation.h>
#include <segmat/medial/voxel_sampling.h>
#include "meso_skeleton_estimation_impl.hpp"

#include "../common/point_kd_tree.h"
#include "../common/thread_count.h"
#include "local_fit.h"
#include "preprocess_cloud.h"

#include <pcl/console/print.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

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
  detail::PointKdTree tree;
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

/// One contraction pass: each centre is replaced by fitLocalStructure() of the centres within
/// rho·r of it (at most the 64 nearest): moved across its sheet or curve, or to the mean of a
/// blob. The tight residual scale (0.1 × support) lets the fit follow one branch where two
/// meet (the corner of a bent tube). Jacobi update: every move uses the old positions.
void
contractOnce(std::vector<Eigen::Vector3f>& centres, const std::vector<float>& radii, float rho,
             int threads)
{
  const int n = static_cast<int>(centres.size());
  if (n < 3)
    return;
  const auto cloud = toXYZ(centres);
  detail::PointKdTree tree;
  tree.setInputCloud(cloud);
  std::vector<Eigen::Vector3f> moved(centres);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const double support = double(rho) * radii[i];
      if (support > 0.0 && tree.radiusSearch((*cloud)[i], support, nn, d2, 64) >= 3)
        moved[i] = fitLocalStructure(centres, i, nn, d2, support, LocalShape::Unknown,
                                     0.1 * support)
                       .cast<float>();
    }
  }
  centres.swap(moved);
}

/// Points merged per voxel: centroid, mean radius, and the tag of the member nearest the
/// centroid (lowest index on a tie).
struct VoxelMerge
{
  std::vector<Eigen::Vector3f> centroids;
  std::vector<float> radii;
  std::vector<int> representative;
};

VoxelMerge
mergeByVoxel(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& radii,
             const std::vector<int>& tags, double cell_size)
{
  std::size_t cells = points.size();
  std::vector<int> cell_of(points.size());
  if (cell_size > 0.0)
    cell_of = voxelCellIndices(points, cell_size, &cells);
  else
    for (std::size_t i = 0; i < points.size(); ++i)
      cell_of[i] = static_cast<int>(i);
  std::vector<Eigen::Vector3d> sums(cells, Eigen::Vector3d::Zero());
  std::vector<double> radius_sums(cells, 0.0);
  std::vector<int> members(cells, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    sums[cell_of[i]] += points[i].cast<double>();
    radius_sums[cell_of[i]] += radii[i];
    ++members[cell_of[i]];
  }
  VoxelMerge merged;
  merged.centroids.resize(cells);
  merged.radii.resize(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    merged.centroids[c] = (sums[c] / double(members[c])).cast<float>();
    merged.radii[c] = static_cast<float>(radius_sums[c] / members[c]);
  }
  std::vector<int> nearest(cells, -1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    int& best = nearest[cell_of[i]];
    const Eigen::Vector3f& centre = merged.centroids[cell_of[i]];
    if (best < 0 || (points[i] - centre).squaredNorm() < (points[best] - centre).squaredNorm())
      best = static_cast<int>(i);
  }
  merged.representative.resize(cells);
  for (std::size_t c = 0; c < cells; ++c)
    merged.representative[c] = tags[nearest[c]];
  return merged;
}

} // namespace

std::vector<int>
inputToWorking(std::size_t input_size, const pcl::Indices& indices,
               const std::vector<int>& copy_to_working)
{
  std::vector<int> map;
  if (copy_to_working.empty())
    return map;
  map.assign(input_size, -1);
  for (std::size_t i = 0; i < indices.size() && i < copy_to_working.size(); ++i)
    map[indices[i]] = copy_to_working[i];
  return map;
}

bool
preprocessCloud(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud, bool has_normals,
                const MesoSkeletonParameters& params, pcl::PointCloud<pcl::PointNormal>& working,
                std::vector<int>& working_indices, std::vector<int>& input_to_working,
                MesoSkeletonStatistics& stats)
{
  const auto start = std::chrono::steady_clock::now();
  CloudPreprocessing preprocessing;
  preprocessing.setInputCloud(cloud);
  preprocessing.setWorkingSize(params.working_size);
  preprocessing.setNormalKSearch(params.normal_k);
  preprocessing.setOrientationKSearch(params.orientation_k);
  preprocessing.setSmoothingIterations(params.smoothing_iterations);
  preprocessing.setUseInputNormalsFlag(has_normals);
  preprocessing.setNumberOfThreads(static_cast<unsigned int>(threadCount(params.threads)));
  if (!preprocessing.compute(working))
    return false;
  working_indices = preprocessing.getWorkingIndices();
  input_to_working = preprocessing.getInputToWorking();
  stats.working_points = working.size();
  stats.normals_estimated = preprocessing.getNormalsEstimated();
  stats.smoothing_passes = preprocessing.getSmoothingPassesApplied();
  stats.noise_sigma = preprocessing.getEstimatedNoise();
  stats.spacing = preprocessing.getEstimatedSpacing();
  stats.remaining_sigma = preprocessing.getRemainingNoise();
  stats.seconds_preprocessing = secondsSince(start);
  return true;
}

bool
estimateMesoSkeleton(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud, bool has_normals,
                     const MesoSkeletonParameters& params, pcl::PointCloud<MedialPoint>& skeleton,
                     pcl::PointCloud<pcl::PointNormal>& working, std::vector<int>& working_indices,
                     std::vector<int>& input_to_working, MesoSkeletonStatistics& stats)
{
  skeleton.clear();
  working.clear();
  working_indices.clear();
  input_to_working.clear();
  stats = MesoSkeletonStatistics();
  stats.input_points = cloud ? cloud->size() : 0;
  const int threads = threadCount(params.threads);

  // 1. Working cloud.
  if (!preprocessCloud(cloud, has_normals, params, working, working_indices, input_to_working,
                       stats))
    return false;
  pcl::PointCloud<pcl::PointNormal>::Ptr surface(new pcl::PointCloud<pcl::PointNormal>(working));
  auto start = std::chrono::steady_clock::now();

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
    if (separation[i] < params.min_separation_angle)
      continue;
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
  std::vector<float> kept_radii(inliers.size());
  for (std::size_t i = 0; i < inliers.size(); ++i) {
    ball_of[i] = candidates[inliers[i]];
    kept[i] = centres[inliers[i]];
    kept_radii[i] = radii[inliers[i]];
  }
  stats.filtered_balls = kept.size();
  if (kept.empty()) {
    PCL_ERROR("[segmat::MesoSkeletonEstimation::compute] No interior ball survived (%zu of %zu "
              "valid): the cloud encloses no volume (flat, open or too noisy).\n",
              stats.valid_balls, stats.balls);
    stats.seconds_medial = secondsSince(start);
    return false;
  }

  // 4. Reduction, contraction, reduction. The first reduction (voxel centroids, to about twice
  // the target: averaging also cancels part of the centres' scatter) makes the contraction
  // cheap; the contraction pulls the rest of the scatter onto sheets and curves; the second
  // reduction, with a voxel size fitted again on the contracted points (which now lie on
  // lower-dimensional sets), brings the count to about the target.
  // A minimum voxel keeps the blob of balls at a sphere's centre a few points.
  const double min_cell = params.min_spacing * workingDiagonal(*surface);
  VoxelMerge merged = mergeByVoxel(
      kept, kept_radii, ball_of, voxelSizeForCount(kept, 2 * params.target_size, min_cell));
  for (int it = 0; it < params.contraction_iterations; ++it)
    contractOnce(merged.centroids, merged.radii, params.contraction_radius, threads);
  merged = mergeByVoxel(merged.centroids, merged.radii, merged.representative,
                        voxelSizeForCount(merged.centroids, params.target_size, min_cell));

  // 6. Radius = distance to the working cloud; the radius-outlier test again on these final
  // radii (a centre left off its sheet has too small a ball); normal from the medial
  // neighbourhood.
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface_xyz(new pcl::PointCloud<pcl::PointXYZ>);
  surface_xyz->resize(surface->size());
  for (std::size_t i = 0; i < surface->size(); ++i)
    (*surface_xyz)[i].getVector3fMap() = (*surface)[i].getVector3fMap();
  detail::PointKdTree surface_tree;
  surface_tree.setInputCloud(surface_xyz);
  const int merged_count = static_cast<int>(merged.centroids.size());
  std::vector<float> final_radii(merged_count);
  std::vector<int> nearest_surface(merged_count);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
    pcl::PointXYZ query;
#pragma omp for schedule(static)
    for (int i = 0; i < merged_count; ++i) {
      query.getVector3fMap() = merged.centroids[i];
      surface_tree.nearestKSearch(query, 1, nn, d2);
      final_radii[i] = std::sqrt(d2[0]);
      nearest_surface[i] = nn[0];
    }
  }
  // Medialness: the samples within (1 + eps)·r of the centre must spread over at least the
  // given angle as seen from it (two-sided contact). A centre left off its sheet touches one
  // side only.
  std::vector<int> final_kept;
  {
    const double slack = 1.0 + double(params.contact_tolerance);
    const double min_spread = params.min_contact_spread;
    std::vector<char> keep(merged_count, 0);
#pragma omp parallel num_threads(threads)
    {
      pcl::Indices nn;
      std::vector<float> d2;
      pcl::PointXYZ query;
#pragma omp for schedule(dynamic, 16)
      for (int i = 0; i < merged_count; ++i) {
        query.getVector3fMap() = merged.centroids[i];
        const Eigen::Vector3d c = merged.centroids[i].cast<double>();
        surface_tree.radiusSearch(query, slack * final_radii[i], nn, d2);
        const Eigen::Vector3d u0 =
            (*surface_xyz)[nearest_surface[i]].getVector3fMap().cast<double>() - c;
        double widest = 0.0;
        for (int j : nn)
          widest = std::max(widest,
                            angleBetween(u0, (*surface_xyz)[j].getVector3fMap().cast<double>() - c));
        keep[i] = widest >= min_spread;
      }
    }
    for (int i = 0; i < merged_count; ++i)
      if (keep[i])
        final_kept.push_back(i);
  }
  const int m = static_cast<int>(final_kept.size());
  std::vector<Eigen::Vector3f> points(m);
  for (int i = 0; i < m; ++i)
    points[i] = merged.centroids[final_kept[i]];
  const auto medial_xyz = toXYZ(points);
  detail::PointKdTree medial_tree;
  medial_tree.setInputCloud(medial_xyz);
  const int normal_k = std::min(std::max(params.medial_normal_k, 2), m - 1) + 1;
  skeleton.resize(m);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int i = 0; i < m; ++i) {
      const int source = final_kept[i];
      MedialPoint& out = skeleton[i];
      out.getVector3fMap() = points[i];
      out.radius = final_radii[source];
      out.surface_index = working_indices[nearest_surface[source]];
      const int contact = balls[merged.representative[source]].contact_index;
      out.contact_index = contact >= 0 ? working_indices[contact] : -1;
      Eigen::Vector3f normal = Eigen::Vector3f::Zero();
      if (normal_k >= 3) {
        medial_tree.nearestKSearch((*medial_xyz)[i], normal_k, nn, d2);
        normal = medialDirection(points, i, nn).cast<float>();
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
