/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: the noise estimate and the surface smoothing shared by the mesh path and the
// cloud path (one noise design for both: estimate the noise from the samples, then smooth
// only as much as that noise asks for).

#include "../common/point_kd_tree.h"

#include <pcl/types.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {
namespace detail {

/** \brief Median of \a values (the upper one of an even count); 0 when empty. */
double
median(std::vector<float> values);

/// Calls visit(s, i, nn, d2) for i = s · stride (s = 0, 1, ...) with the \a k nearest neighbours
/// of point i of the tree's cloud (i itself first), on \a threads threads. Each s is visited
/// once, so what visit writes to slot s does not depend on the thread count.
template <typename Visit>
inline void
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

/** \brief The noise of surface samples and their spacing (both in the samples' units). */
struct SurfaceNoise
{
  double sigma = 0.0;   ///< Gaussian σ of the samples' offsets from their local surface
  double spacing = 0.0; ///< median distance of a sample to its nearest neighbour
};

/** \brief Where a surface sample's neighbours come from: the nearest samples in space for a
 * cloud, the rings around a vertex for a mesh (which never mix the two sides of a thin wall).
 * Each list starts with the sample itself, then its nearest neighbour, and ends with the
 * farthest; the squared distances come in the same order.
 */
class SampleNeighbourhoods
{
public:
  virtual ~SampleNeighbourhoods() = default;

  /** \brief Called with the current positions before they are read (they move between passes). */
  virtual void
  update(const std::vector<Eigen::Vector3f>& positions) = 0;

  /** \brief The few closest neighbours: they measure the noise without seeing the shape. */
  virtual void
  close(int i, pcl::Indices& nn, std::vector<float>& d2) const = 0;

  /** \brief The neighbours a smoothing fit uses. */
  virtual void
  wide(int i, pcl::Indices& nn, std::vector<float>& d2) const = 0;
};

/** \brief Noise and spacing from every \a stride-th sample: the median offset of a sample from
 * the PCA plane of its close neighbourhood (near enough to stay on its side of a thin wall; a
 * wider PCA would measure the wall's thickness), scaled to a Gaussian σ (÷ 0.6745), and the
 * median distance to the nearest neighbour.
 */
SurfaceNoise
estimateSurfaceNoise(const std::vector<Eigen::Vector3f>& positions,
                     const SampleNeighbourhoods& neighbourhoods, int stride, int threads);

/** \brief What denoiseSurface() found and did. */
struct SurfaceDenoising
{
  SurfaceNoise noise; ///< estimated before smoothing
  int passes = 0;     ///< smoothing passes that moved the samples
  double face_turn_degrees = 0.0; ///< meshes: median turn of a face to its flattest neighbour
  int normal_iterations = 0;      ///< meshes: bilateral normal filtering iterations
  /// σ̂ of the denoised surface (the same estimate), 0 when nothing was smoothed.
  double remaining_sigma = 0.0;
};

/** \brief Moves noisy surface samples back onto their surface; leaves clean ones alone.
 *
 * A sample set is noisy when its σ is at least a tenth of its spacing: the offsets of a clean
 * sample from its local planes are a few percent of the spacing (curvature), a noisy one's 30 %
 * and more. A noisy set gets sided quadratic smoothing passes (each sample onto the height field
 * of its own side of the surface, fitted to its \a k nearest neighbours with a residual band
 * of 1.5 σ) while a pass still moves the samples by 5 % of the spacing, at most \a max_passes.
 */
SurfaceDenoising
denoiseSurface(std::vector<Eigen::Vector3f>& positions, SampleNeighbourhoods& neighbourhoods,
               int max_passes, int threads, double min_noise_ratio = 0.1);

/** \brief denoiseSurface() of a point cloud: close = 8 nearest points, wide = \a k nearest.
 *
 * When \a dense holds more samples of the same surface (the input before it was thinned to
 * \a positions), every pass fits each sample to its dense neighbours instead: as many as its
 * k nearest samples span, at most 8 k, searched before the opening pass and again after it; the
 * band stays that of the input's noise.
 */
SurfaceDenoising
denoiseCloudSurface(std::vector<Eigen::Vector3f>& positions, int k, int max_passes, int threads,
                    const std::vector<Eigen::Vector3f>* dense = nullptr);

/** \brief Median over the faces of the angle (degrees) between a face's normal and that of its
 * flattest edge neighbour. A clean triangulation keeps it small whatever the shape: triangles
 * of a smooth surface turn little, and every triangle of a flat face (CAD meshes, whose vertices
 * all sit on creases) has a coplanar neighbour; vertex noise tilts every triangle against all
 * of its neighbours.
 */
double
medianFaceTurn(const std::vector<Eigen::Vector3d>& vertices,
               const std::vector<Eigen::Vector3i>& faces);

/** \brief denoiseSurface() of a mesh's vertices when medianFaceTurn() reaches \a noisy_degrees:
 * close = two rings around a vertex, wide = the rings until they hold \a k vertices (at most
 * three rings). Edges never join the two sides of a thin wall, so a wall thinner than the noise
 * keeps both of its sides. bilateralNormalFilter() runs before the passes, with σ_r from the
 * faces' normals (NormalFilterSettings::range_from_normals), and after them with the fixed σ_r,
 * which gives back the creases that the quadratic fits rounded; relaxTangentially() (at most
 * 2 σ per vertex) then evens out the spacing that the noise along the surface left. A mesh found
 * clean is left exactly as it is.
 */
SurfaceDenoising
denoiseMeshSurface(std::vector<Eigen::Vector3d>& vertices,
                   const std::vector<Eigen::Vector3i>& faces, int k, int max_passes, int threads,
                   double noisy_degrees);

} // namespace detail
} // namespace segmat
