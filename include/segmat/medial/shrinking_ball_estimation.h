/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/point_types.h>

#include <pcl/point_cloud.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace segmat {

/** \brief Medial balls of an oriented point cloud by the shrinking-ball method.
 *
 * Ma, Bae and Choi, "3D medial axis point approximation using nearest neighbors and the normal
 * field", The Visual Computer 28(1):7–19, 2012. For a surface point p with outward unit normal
 * n, the ball tangent at p has centre c = p − r·n. Starting from r = r_init, the nearest sample
 * q to c other than p is found; while q lies strictly inside the ball, r shrinks to the radius
 * of the ball through q tangent at p, r = |p−q|² / (2 n·(p−q)). The ball is final when it holds
 * no sample, when q repeats or r changes by less than 1e-5 of the bounding-box diagonal, or
 * after the iteration cap.
 *
 * Denoising (the paper's two angle tests, on the separation angle ∠(p−c, q−c)):
 *  - first shrink below the planar angle (default 32°): p sits on a flat, open or noisy spot
 *    with no interior ball; the ball is invalid;
 *  - a later shrink below the preserve angle (default 20°): q is noise next to p; the previous
 *    ball is kept.
 * A ball of radius r_init holding no sample also makes the point invalid (open side, hole).
 *
 * Every ball is computed alone (nearest-neighbour queries on a precompiled
 * pcl::KdTreeFLANN<pcl::PointXYZ>), so the result does not depend on the thread count.
 */
class ShrinkingBallEstimation
{
public:
  using Ptr = std::shared_ptr<ShrinkingBallEstimation>;
  using ConstPtr = std::shared_ptr<const ShrinkingBallEstimation>;
  using SurfaceCloud = pcl::PointCloud<pcl::PointNormal>;

  /** \brief Defaults: r_init automatic, 20°/32° denoise angles, 30 iterations, OpenMP threads. */
  ShrinkingBallEstimation();

  /** \brief The sampled surface: finite points with unit, outward normals. */
  void
  setInputCloud(const SurfaceCloud::ConstPtr& cloud)
  {
    input_ = cloud;
  }

  /** \brief The sampled surface. */
  const SurfaceCloud::ConstPtr&
  getInputCloud() const
  {
    return input_;
  }

  /** \brief The surface points that get a ball (default: all). Every point stays searchable. */
  void
  setIndices(const std::shared_ptr<const std::vector<int>>& indices)
  {
    indices_ = indices;
  }

  /** \brief Starting radius; 0 (default) means 0.55 × the smallest extent of the bounding box
   * (no ball inside the shape is larger than half of it), at least 1e-3 of its diagonal.
   */
  void
  setInitialRadius(float radius);

  /** \brief Starting radius (0: automatic). */
  float
  getInitialRadius() const
  {
    return initial_radius_;
  }

  /** \brief Separation angle below which a later shrink is refused (radians, default 20°). */
  void
  setDenoisePreserveAngle(float angle);

  /** \brief Separation angle below which a later shrink is refused (radians). */
  float
  getDenoisePreserveAngle() const
  {
    return preserve_angle_;
  }

  /** \brief Separation angle below which the first shrink marks the point planar, invalid
   * (radians, default 32°).
   */
  void
  setDenoisePlanarAngle(float angle);

  /** \brief Separation angle below which the first shrink marks the point invalid (radians). */
  float
  getDenoisePlanarAngle() const
  {
    return planar_angle_;
  }

  /** \brief Iteration cap per ball (> 0, default 30). */
  void
  setMaxIterations(int iterations);

  /** \brief Iteration cap per ball. */
  int
  getMaxIterations() const
  {
    return max_iterations_;
  }

  /** \brief Threads (0: OpenMP's choice, default). */
  void
  setNumberOfThreads(unsigned int threads)
  {
    threads_ = threads;
  }

  /** \brief Threads (0: OpenMP's choice). */
  unsigned int
  getNumberOfThreads() const
  {
    return threads_;
  }

  /** \brief Compute one ball per selected surface point.
   * \param[out] balls one point per index, in index order: centre, radius, surface_index = the
   *             surface point, contact_index = the last touching sample, normal = the surface
   *             normal. Invalid balls have NaN coordinates and radius, and then
   *             is_dense = false.
   * \return false (PCL_ERROR, empty output) without input, with an index out of range or with
   *         fewer than 2 surface points
   */
  bool
  compute(pcl::PointCloud<MedialPoint>& balls);

  /** \brief Separation angle ∠(p−c, q−c) of each ball of the last compute() (radians; NaN for
   * invalid balls). Small angles mark balls spiking towards a convex edge or noise.
   */
  const std::vector<float>&
  getSeparationAngles() const
  {
    return separation_angles_;
  }

private:
  SurfaceCloud::ConstPtr input_;
  std::shared_ptr<const std::vector<int>> indices_;
  float initial_radius_;
  float preserve_angle_;
  float planar_angle_;
  int max_iterations_;
  unsigned int threads_;
  std::vector<float> separation_angles_;
};

} // namespace segmat
