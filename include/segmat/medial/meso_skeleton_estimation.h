/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/point_types.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace segmat {

/** \brief Every parameter of the meso-skeleton pipeline, with its default. */
struct MesoSkeletonParameters
{
  // Pre-processing (segmat::CloudPreprocessing).
  std::size_t working_size = 20000; ///< points kept for the medial step
  int normal_k = 16;                ///< neighbours of the PCA normal estimate
  int orientation_k = 10;           ///< neighbours of the MST orientation graph
  int smoothing_iterations = 5;     ///< most surface smoothing passes when normals are estimated
  bool use_input_normals = true;    ///< keep the cloud's own normals when it has them
  // Shrinking balls (segmat::ShrinkingBallEstimation).
  std::size_t ball_count = 5000;     ///< surface points that get a ball (0: every working point)
  float initial_radius = 0.0f;       ///< 0: automatic
  float preserve_angle = 0.349066f;  ///< 20°, radians
  float planar_angle = 0.558505f;    ///< 32°, radians
  int max_iterations = 30;           ///< per ball
  // Filtering.
  float min_separation_angle = 0.0f; ///< radians; 0: off (see the class comment)
  int outlier_k = 10;                ///< neighbours of the radius-outlier test
  float outlier_ratio = 2.0f;        ///< r / median(r of neighbours) outside [1/x, x]: drop
  float contact_tolerance = 0.1f;    ///< contact samples: within (1 + x)·r of the final centre
  float min_contact_spread = 1.047198f; ///< 60°: the contacts' smallest angular spread
  // Contraction (neighbour averaging across sheets and curves).
  int contraction_iterations = 3;
  float contraction_radius = 1.0f; ///< neighbourhood radius, × the point's ball radius
  // Reduction and medial normals.
  std::size_t target_size = 2000; ///< about the size of SEG-MAT's base MAT
  float min_spacing = 0.002f;     ///< smallest reduction voxel, × working-cloud diagonal
  int medial_normal_k = 10;       ///< neighbours of the PCA normal of a medial point
  unsigned int threads = 0;       ///< 0: OpenMP's choice; results do not depend on it
};

/** \brief Sizes and timings of the last meso-skeleton computation. */
struct MesoSkeletonStatistics
{
  std::size_t input_points = 0;     ///< points handed in (after indices)
  std::size_t working_points = 0;   ///< after resampling and normal checks
  std::size_t balls = 0;            ///< shrinking balls computed
  std::size_t valid_balls = 0;      ///< balls that converged to an interior ball
  std::size_t filtered_balls = 0;   ///< left after the angle and radius filters
  std::size_t medial_points = 0;    ///< output size
  bool normals_estimated = false;   ///< normals were estimated (not read from the cloud)
  int smoothing_passes = 0;         ///< smoothing passes applied (> 0: the cloud was noisy)
  double noise_sigma = 0;           ///< estimated noise σ (CloudPreprocessing::getEstimatedNoise)
  double spacing = 0;               ///< estimated spacing (CloudPreprocessing::getEstimatedSpacing)
  double remaining_sigma = 0;       ///< noise left after smoothing (CloudPreprocessing::getRemainingNoise)
  double seconds_preprocessing = 0; ///< resampling, normals, orientation
  double seconds_balls = 0;         ///< shrinking balls
  double seconds_medial = 0;        ///< filters, contraction, reduction, radii, normals
};

/** \brief Medial points with radii of a point cloud: its meso-skeleton (SEG-MAT, Lin et al.
 * 2022, §6: the MAT of a cloud is a set of medial points with radii and normals, no faces).
 *
 * Pipeline:
 *  1. pre-processing (segmat::CloudPreprocessing): finite points, resampled to the working size,
 *     unit normals — the cloud's own when PointT has them (and setUseInputNormalsFlag(true)),
 *     otherwise PCA-estimated and MST-oriented outward;
 *  2. shrinking balls (Ma, Bae, Choi 2012; segmat::ShrinkingBallEstimation) for a voxel subset
 *     of setBallCount() working points (default 5000; the balls still see every working point:
 *     the output is reduced to ~2000 points anyway, and a ball's cost grows with the samples
 *     near-equidistant from its centre);
 *  3. filters: invalid balls; optionally a minimum separation angle (off by default: with
 *     estimated normals a slightly tilted ball stops on a sample close to p through the 20°
 *     denoise rule, so most good balls have small separation angles); radius outside
 *     [m/x, x·m], m the median radius of the k nearest balls;
 *  4. reduction by voxel centroids to about twice the target (voxel side at least
 *     min_spacing × the working cloud's diagonal, so the blob of balls at a sphere's centre
 *     stays a few points); contraction passes: each centre moves onto a robust (Cauchy-weighted)
 *     local fit of the centres within contraction_radius × its ball radius — a quadratic
 *     across-offset along a curve (along the robust line through the point, so that at the
 *     bend of a tube the other branch does not pull), a quadratic height field across a sheet,
 *     the mean of a blob (a medial set has no volume) — so sheets and curves thin out without
 *     shrinking or bending; then voxel centroids again, at a size fitted on the contracted
 *     points, to about the target;
 *  5. radius = distance from the centre to the nearest working point; medialness test: the
 *     working points within (1 + contact_tolerance)·r must spread over at least
 *     min_contact_spread (60°) as seen from the centre — a centre left off its sheet touches
 *     one side only and has too small a ball;
 *  6. normal = smallest PCA direction of the k nearest medial points; for curve-like
 *     neighbourhoods (middle eigenvalue < 0.1 × largest, or a planar L whose robust line
 *     through the point holds 45 % of the neighbours), whose smallest direction is arbitrary,
 *     the curve direction instead: what C_θ should compare there (a bend of a tube then shows
 *     as one sharp change of direction, like the cones of a medial mesh).
 * Output fields: xyz = centre, normal, radius, surface_index = the nearest input point,
 * contact_index = the sample that stopped the ball (both index the input cloud).
 * Deterministic; the thread count does not change the result.
 *
 * PointT: any PCL type with xyz (instantiated for pcl::PointXYZ, pcl::PointNormal,
 * pcl::PointXYZRGBNormal); normals are read when it has normal fields.
 */
template <typename PointT>
class MesoSkeletonEstimation : public pcl::PCLBase<PointT>
{
public:
  using Ptr = std::shared_ptr<MesoSkeletonEstimation<PointT>>;
  using ConstPtr = std::shared_ptr<const MesoSkeletonEstimation<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using PointCloudConstPtr = typename PointCloud::ConstPtr;

  /** \brief Defaults: see segmat::MesoSkeletonParameters. */
  MesoSkeletonEstimation() = default;

  /** \brief All parameters at once (no validation beyond the setters'). */
  void
  setParameters(const MesoSkeletonParameters& params)
  {
    params_ = params;
  }

  /** \brief All parameters. */
  const MesoSkeletonParameters&
  getParameters() const
  {
    return params_;
  }

  /** \brief Points kept for the medial step (> 0, default 20000). */
  void
  setWorkingSize(std::size_t size);

  /** \brief Use the cloud's normals when PointT has them (default true). */
  void
  setUseInputNormalsFlag(bool flag)
  {
    params_.use_input_normals = flag;
  }

  /** \brief Neighbours of the PCA normal estimate on the working cloud (>= 3, default 16). */
  void
  setNormalKSearch(int k);

  /** \brief Surface points that get a shrinking ball (0: all working points, default). */
  void
  setBallCount(std::size_t count)
  {
    params_.ball_count = count;
  }

  /** \brief Minimum separation angle of a kept ball (radians in [0, pi], default 35°). */
  void
  setMinSeparationAngle(float angle);

  /** \brief Contraction passes (>= 0, default 3). */
  void
  setContractionIterations(int iterations);

  /** \brief About how many medial points to keep (> 0, default 2000). */
  void
  setTargetSize(std::size_t size);

  /** \brief Threads (0: OpenMP's choice, default). */
  void
  setNumberOfThreads(unsigned int threads)
  {
    params_.threads = threads;
  }

  /** \brief Compute the meso-skeleton of the input (through the indices, when set).
   * \param[out] skeleton medial points; surface_index / contact_index index the input cloud
   * \return false (PCL_ERROR, empty output) without input, with no finite point, with too few
   *         points for normals, or when no interior ball survives (e.g. a flat, open patch)
   */
  bool
  compute(pcl::PointCloud<MedialPoint>& skeleton);

  /** \brief The resampled, oriented cloud of the last compute(). */
  const pcl::PointCloud<pcl::PointNormal>&
  getWorkingCloud() const
  {
    return working_;
  }

  /** \brief For each working point, its index in the input cloud. */
  const std::vector<int>&
  getWorkingIndices() const
  {
    return working_indices_;
  }

  /** \brief For each point of the input cloud, the working point standing for it (its voxel's
   * representative, or the nearest working point); -1 for non-finite points and points outside
   * the indices. Labels computed on the working cloud reach every input point through it.
   */
  const std::vector<int>&
  getInputToWorking() const
  {
    return input_to_working_;
  }

  /** \brief Sizes and timings of the last compute(). */
  const MesoSkeletonStatistics&
  getStatistics() const
  {
    return stats_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

private:
  MesoSkeletonParameters params_;
  pcl::PointCloud<pcl::PointNormal> working_;
  std::vector<int> working_indices_;
  std::vector<int> input_to_working_;
  MesoSkeletonStatistics stats_;
};

} // namespace segmat
