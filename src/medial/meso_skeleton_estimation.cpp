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

/// Angle between two vectors in radians (0 when either is zero), argument clamped.
double
angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double la = a.norm(), lb = b.norm();
  if (la == 0.0 || lb == 0.0)
    return 0.0;
  return std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
}

/// A neighbourhood is curve-like when its middle spread is small next to its largest.
constexpr double kCurveRatio = 0.1;

bool
curveLike(const Eigen::Vector3d& eigenvalues)
{
  return eigenvalues[1] < kCurveRatio * eigenvalues[2];
}

/// Sheet-like: thin in one direction only (checked after curveLike).
bool
sheetLike(const Eigen::Vector3d& eigenvalues)
{
  return eigenvalues[0] < kCurveRatio * eigenvalues[1];
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

/// Weighted least-squares fit of values_a ≈ c·basis_a, evaluated at basis_at_point. The basis
/// is ordered constant, linear, quadratic terms (1, t, t² or 1, u, v, u², uv, v²): the full
/// quadratic is tried first, then the linear and constant heads, as long as there are fewer
/// points than terms + 2 or the system is rank-deficient.
template <int Dim>
Eigen::Matrix<double, Dim, 1>
fitAndEvaluate(const std::vector<Eigen::VectorXd>& basis, const std::vector<double>& weights,
               const std::vector<Eigen::Matrix<double, Dim, 1>>& values,
               const Eigen::VectorXd& basis_at_point)
{
  const int terms = static_cast<int>(basis_at_point.size());
  const int linear = terms == 6 ? 3 : 2;
  for (int used : {terms, linear, 1}) {
    if (used > 1 && static_cast<int>(basis.size()) < used + 2)
      continue;
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(used, used);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(used, Dim);
    for (std::size_t a = 0; a < basis.size(); ++a) {
      const Eigen::VectorXd phi = basis[a].head(used);
      gram += weights[a] * phi * phi.transpose();
      rhs += weights[a] * phi * values[a].transpose();
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(gram);
    if (qr.rank() < used)
      continue;
    const Eigen::MatrixXd coefficients = qr.solve(rhs);
    return coefficients.transpose() * basis_at_point.head(used);
  }
  return Eigen::Matrix<double, Dim, 1>::Zero();
}

/// One contraction pass: each centre is replaced by a weighted least-squares fit of the centres
/// within rho·r of it (at most the 64 nearest, Gaussian weights), evaluated at its own place
/// along the structure: a quadratic curve for a curve-like neighbourhood (moved in the plane
/// normal to the curve), a quadratic height field for a sheet (moved along the normal), the
/// weighted mean for a blob. A quadratic fit, unlike the plain mean, does not pull points
/// towards the inside of a bent sheet or curve (a mean-based pass shrinks a circle of radius R
/// by about (rho·r)²/(6R) per pass). Jacobi update: every move uses the old positions.
void
contractOnce(std::vector<Eigen::Vector3f>& centres, const std::vector<float>& radii, float rho,
             int threads)
{
  const int n = static_cast<int>(centres.size());
  if (n < 3)
    return;
  const auto cloud = toXYZ(centres);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  std::vector<Eigen::Vector3f> moved(centres);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
    std::vector<double> weights;
    std::vector<Eigen::VectorXd> basis;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const double support = double(rho) * radii[i];
      if (!(support > 0.0) || tree.radiusSearch((*cloud)[i], support, nn, d2, 64) < 3)
        continue;
      weights.resize(nn.size());
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      double weight = 0.0;
      for (std::size_t a = 0; a < nn.size(); ++a) {
        weights[a] = std::exp(-double(d2[a]) / (support * support));
        mean += weights[a] * centres[nn[a]].cast<double>();
        weight += weights[a];
      }
      mean /= weight;
      const auto pca = neighbourhoodPca(centres, nn);
      const Eigen::Matrix3d& frame = pca.eigenvectors(); // columns: smallest .. largest
      const Eigen::Vector3d own = centres[i].cast<double>() - mean;
      Eigen::Vector3d result = mean; // blob
      basis.resize(nn.size());
      if (curveLike(pca.eigenvalues())) {
        // across(t) in the (e0, e1) plane, t along e2.
        std::vector<Eigen::Vector2d> across(nn.size());
        for (std::size_t a = 0; a < nn.size(); ++a) {
          const Eigen::Vector3d d = centres[nn[a]].cast<double>() - mean;
          const double t = d.dot(frame.col(2));
          basis[a] = Eigen::Vector3d(1.0, t, t * t);
          across[a] = Eigen::Vector2d(d.dot(frame.col(0)), d.dot(frame.col(1)));
        }
        const double t = own.dot(frame.col(2));
        const Eigen::Vector2d fit =
            fitAndEvaluate<2>(basis, weights, across, Eigen::Vector3d(1.0, t, t * t));
        result = mean + t * frame.col(2) + fit[0] * frame.col(0) + fit[1] * frame.col(1);
      }
      else if (sheetLike(pca.eigenvalues())) {
        // height(u, v) along e0 over the (e1, e2) plane.
        std::vector<Eigen::Matrix<double, 1, 1>> height(nn.size());
        auto phi = [](double u, double v) {
          Eigen::VectorXd b(6);
          b << 1.0, u, v, u * u, u * v, v * v;
          return b;
        };
        for (std::size_t a = 0; a < nn.size(); ++a) {
          const Eigen::Vector3d d = centres[nn[a]].cast<double>() - mean;
          basis[a] = phi(d.dot(frame.col(1)), d.dot(frame.col(2)));
          height[a](0) = d.dot(frame.col(0));
        }
        const double u = own.dot(frame.col(1)), v = own.dot(frame.col(2));
        const double h = fitAndEvaluate<1>(basis, weights, height, phi(u, v))(0);
        result = mean + u * frame.col(1) + v * frame.col(2) + h * frame.col(0);
      }
      moved[i] = result.cast<float>();
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

  // 4. Reduction, contraction, reduction. The first reduction (voxel centroids: averaging also
  // cancels part of the centres' scatter) makes the contraction cheap; the contraction pulls
  // the rest of the scatter onto sheets and curves, which can bring points of neighbouring
  // voxels together; the second reduction at the same voxel size merges those.
  // A minimum voxel keeps the blob of balls at a sphere's centre a few points.
  const double cell_size = voxelSizeForCount(kept, params.target_size,
                                             params.min_spacing * workingDiagonal(*surface));
  VoxelMerge merged = mergeByVoxel(kept, kept_radii, ball_of, cell_size);
  for (int it = 0; it < params.contraction_iterations; ++it)
    contractOnce(merged.centroids, merged.radii, params.contraction_radius, threads);
  if (params.contraction_iterations > 0)
    merged = mergeByVoxel(merged.centroids, merged.radii, merged.representative, cell_size);
  // 6. Radius = distance to the working cloud; the radius-outlier test again on these final
  // radii (a centre left off its sheet has too small a ball); normal from the medial
  // neighbourhood.
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface_xyz(new pcl::PointCloud<pcl::PointXYZ>);
  surface_xyz->resize(surface->size());
  for (std::size_t i = 0; i < surface->size(); ++i)
    (*surface_xyz)[i].getVector3fMap() = (*surface)[i].getVector3fMap();
  pcl::KdTreeFLANN<pcl::PointXYZ> surface_tree;
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
  pcl::KdTreeFLANN<pcl::PointXYZ> medial_tree;
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
