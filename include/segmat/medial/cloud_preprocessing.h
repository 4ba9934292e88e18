/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace segmat {

/** \brief Turns a raw cloud into the working cloud of the medial step: finite, resampled to a
 * working size, with unit normals oriented outward.
 *
 * The shrinking-ball step costs a nearest-neighbour query from a point deep inside the shape,
 * which visits every sample near-equidistant from it, so its cost grows faster than linearly
 * with density; the working cloud bounds it whatever the input size.
 *
 * Steps, in order:
 *  1. drop points with a non-finite coordinate (and, when input normals are used, points whose
 *     normal is non-finite or zero; if more than 1 % are bad the normals are estimated instead);
 *  2. keep one point per voxel (segmat::voxelRepresentatives, VoxelPick::Jittered: centre
 *     picks would leave a lattice of the grid's axes) when there are more than the working
 *     size, then drop exact duplicates (lowest index kept) and isolated points
 *     (scanner outliers: mean distance to the 8 nearest neighbours above 4 times the cloud's
 *     median and twice the median of those neighbours' own, so that a sparser region of a scan
 *     stays; each outlier would be a surface sample of its own inside or around the shape —
 *     their input points still get the label of the nearest working point); a warning when the
 *     cloud lies so far from the origin that float coordinates are a grid at its scale;
 *  3. smoothing: when the cloud is noisy (a point's median offset from the plane of its 8
 *     nearest neighbours, as a Gaussian σ, above 10 % of the spacing; clean samples show
 *     2–4 %), up to setSmoothingIterations() passes of *sided* quadratic smoothing — each point
 *     moves onto a height field fitted with weights on the residual (bandwidth 1.5 σ), so the
 *     two sides of a wall thinner than the neighbourhood stay apart instead of collapsing into
 *     one sheet; when step 2 thinned the cloud, to the input's points around it, several times
 *     as many over the same area. The test runs on every cloud, with or without normals;
 *  4. normals: the input's, normalised (default when it has them), unless the cloud was found
 *     noisy: then, as for a cloud without normals, pcl::NormalEstimationOMP over k neighbours
 *     of the smoothed points (the result does not depend on the thread count: every point's
 *     normal is computed alone), oriented by segmat::NormalOrientation. Smoothing carries
 *     points that the noise moved across a thin wall onto its other side, where their own
 *     normals point the wrong way.
 */
class CloudPreprocessing
{
public:
  using Ptr = std::shared_ptr<CloudPreprocessing>;
  using ConstPtr = std::shared_ptr<const CloudPreprocessing>;
  using PointCloudIn = pcl::PointCloud<pcl::PointNormal>;

  /** \brief Defaults: working size 20000, normals from 16 neighbours, up to 5 smoothing passes,
   * orientation over 10, input normals used, threads chosen by OpenMP.
   */
  CloudPreprocessing();

  /** \brief The raw cloud. Its normal fields are read only when setUseInputNormalsFlag(true). */
  void
  setInputCloud(const PointCloudIn::ConstPtr& cloud)
  {
    input_ = cloud;
  }

  /** \brief The raw cloud. */
  const PointCloudIn::ConstPtr&
  getInputCloud() const
  {
    return input_;
  }

  /** \brief Largest number of points kept for the medial step (> 0, default 20000). */
  void
  setWorkingSize(std::size_t size);

  /** \brief Largest number of points kept for the medial step. */
  std::size_t
  getWorkingSize() const
  {
    return working_size_;
  }

  /** \brief Neighbours of the PCA normal estimate (>= 3, default 16). */
  void
  setNormalKSearch(int k);

  /** \brief Neighbours of the PCA normal estimate. */
  int
  getNormalKSearch() const
  {
    return normal_k_;
  }

  /** \brief Neighbours of the orientation graph (> 0, default 10). */
  void
  setOrientationKSearch(int k);

  /** \brief Neighbours of the orientation graph. */
  int
  getOrientationKSearch() const
  {
    return orientation_k_;
  }

  /** \brief Largest number of smoothing passes before normals are estimated (>= 0, default 5).
   * Only noisy clouds whose normals are estimated are smoothed (see the class description; a
   * clean sample is left exactly as it is): each pass moves every point onto the sided
   * quadratic height field of its 2·normal_k nearest neighbours; passes stop once the median
   * move is below 5 % of the median spacing. Noise otherwise leaves Voronoi poles and shrinking
   * balls stuck on the bumps.
   */
  void
  setSmoothingIterations(int iterations);

  /** \brief Largest number of smoothing passes before normals are estimated. */
  int
  getSmoothingIterations() const
  {
    return smoothing_iterations_;
  }

  /** \brief Use the input's normals (true, default) or estimate them (false). Input normals
   * are trusted to be oriented outward. A cloud found noisy has its normals estimated either
   * way (step 4 above).
   */
  void
  setUseInputNormalsFlag(bool flag)
  {
    use_input_normals_ = flag;
  }

  /** \brief Whether the input's normals are used. */
  bool
  getUseInputNormalsFlag() const
  {
    return use_input_normals_;
  }

  /** \brief Threads of the normal estimation (0: OpenMP's choice, default). */
  void
  setNumberOfThreads(unsigned int threads)
  {
    threads_ = threads;
  }

  /** \brief Threads of the normal estimation. */
  unsigned int
  getNumberOfThreads() const
  {
    return threads_;
  }

  /** \brief Build the working cloud.
   * \param[out] working finite points with unit, outward normals (empty on failure)
   * \return false (PCL_ERROR) when there is no input, no finite point, or fewer than 3 points
   *         with a usable normal
   */
  bool
  compute(pcl::PointCloud<pcl::PointNormal>& working);

  /** \brief For each working point, its index in the input cloud (from the last compute()). */
  const std::vector<int>&
  getWorkingIndices() const
  {
    return working_indices_;
  }

  /** \brief For each input point, the working point that stands for it (from the last
   * compute()): its voxel's representative, or the nearest working point when that
   * representative was dropped (duplicate, unusable normal); -1 for non-finite points.
   * Labels of the working cloud reach every input point through this map.
   */
  const std::vector<int>&
  getInputToWorking() const
  {
    return input_to_working_;
  }

  /** \brief True when the last compute() estimated the normals: asked to, or the input's were
   * unusable, or the cloud was found noisy. */
  bool
  getNormalsEstimated() const
  {
    return normals_estimated_;
  }

  /** \brief Smoothing passes the last compute() applied: 0 for a clean cloud, 1 or more when
   * it found the cloud noisy. */
  int
  getSmoothingPassesApplied() const
  {
    return smoothing_passes_;
  }

  /** \brief The noise the last compute() estimated in the working cloud (Gaussian σ of the
   * points' offsets from their local surface, in the cloud's units), with or without input
   * normals. */
  double
  getEstimatedNoise() const
  {
    return noise_sigma_;
  }

  /** \brief The noise estimated again on the smoothed working cloud; 0 when nothing was
   * smoothed. */
  double
  getRemainingNoise() const
  {
    return remaining_sigma_;
  }

  /** \brief Median nearest-neighbour distance of the working cloud, from the same estimate. */
  double
  getEstimatedSpacing() const
  {
    return spacing_;
  }

private:
  PointCloudIn::ConstPtr input_;
  std::size_t working_size_;
  int normal_k_;
  int orientation_k_;
  int smoothing_iterations_;
  bool use_input_normals_;
  unsigned int threads_;
  std::vector<int> working_indices_;
  std::vector<int> input_to_working_;
  bool normals_estimated_ = false;
  int smoothing_passes_ = 0;
  double noise_sigma_ = 0.0;
  double remaining_sigma_ = 0.0;
  double spacing_ = 0.0;
};

} // namespace segmat
