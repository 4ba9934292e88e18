/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Test and benchmark clouds: area-uniform samples of triangle meshes and of analytic shapes,
// with true normals and the source element of every point (face index, or part id).

#include <segmat/geometry/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/type_traits.h>

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace segmat {
namespace test {

/** \brief Points with unit outward normals and, per point, where it came from. */
struct SampledCloud
{
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;
  std::vector<int> source; ///< mesh: face index; analytic shape: part id

  std::size_t size() const { return points.size(); }

  /** \brief Points and normals as a PCL cloud. */
  pcl::PointCloud<pcl::PointNormal>::Ptr
  toPointNormal() const;

  /** \brief Points only. */
  pcl::PointCloud<pcl::PointXYZ>::Ptr
  toPointXYZ() const;

  /** \brief As any PCL point type; the normals are copied when it has normal fields. */
  template <typename PointT>
  typename pcl::PointCloud<PointT>::Ptr
  toCloud() const
  {
    typename pcl::PointCloud<PointT>::Ptr cloud(new pcl::PointCloud<PointT>);
    cloud->resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      (*cloud)[i].getVector3fMap() = points[i];
      if constexpr (pcl::traits::has_normal_v<PointT>)
        (*cloud)[i].getNormalVector3fMap() = normals[i];
    }
    return cloud;
  }

  /** \brief Map per-source labels (e.g. a face labelling) to per-point labels. */
  std::vector<int>
  pointLabels(const std::vector<int>& source_labels) const;
};

/** \brief Uniform double in [0, 1) from the raw engine output (53 bits from two draws), so the
 * same seed gives the same numbers with every standard library.
 */
double
uniform01(std::mt19937& rng);

/** \brief Standard normal deviate (Box–Muller on uniform01). */
double
standardNormal(std::mt19937& rng);

/** \brief \a count points, area-uniform on \a mesh; normal = face normal, source = face index.
 * Degenerate faces get no point. Empty result for a mesh without area.
 */
SampledCloud
sampleMesh(const TriangleMesh& mesh, std::size_t count, std::uint32_t seed = 1);

/** \brief Gaussian displacement of every point, sigma = \a fraction × bounding-box diagonal
 * (normals unchanged).
 */
void
addGaussianNoise(SampledCloud& cloud, double fraction, std::uint32_t seed = 2);

/** \brief The same noise on a mesh's vertices (sigma from the vertices' bounding box). */
void
addGaussianNoise(TriangleMesh& mesh, double fraction, std::uint32_t seed = 2);

/** \brief 1 − Rand index of two labelings of the same points, over point pairs with the
 * textbook divisor n(n−1)/2 (bench::randDistance: points labelled < 0 in either are left
 * out); 0 for fewer than two points; throws std::invalid_argument when the sizes differ.
 */
double
randIndexError(const std::vector<int>& a, const std::vector<int>& b);

/** \brief Two unit balls centred at (±3, 0, 0) joined by a tube of radius 0.3 along x.
 * Parts: 0 left ball, 1 tube, 2 right ball.
 */
SampledCloud
dumbbellCloud(std::size_t count, std::uint32_t seed = 1);

/** \brief Union of two capsules of radius 0.5 from the origin to (4,0,0) and to (0,4,0).
 * Parts: 0 the x arm, 1 the y arm.
 */
SampledCloud
lTubeCloud(std::size_t count, std::uint32_t seed = 1);

/** \brief Unit sphere at the origin (part 0). */
SampledCloud
sphereCloud(std::size_t count, std::uint32_t seed = 1);

/** \brief Torus around z, major radius 2, minor radius 0.5 (part 0). */
SampledCloud
torusCloud(std::size_t count, std::uint32_t seed = 1);

/** \brief Flat unit disc in the plane z = 0, normals +z, no interior (part 0). */
SampledCloud
discCloud(std::size_t count, std::uint32_t seed = 1);

} // namespace test
} // namespace segmat
