/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>
#include <segmat/medial/medial_mesh_estimation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <memory>

namespace segmat {

/** \brief The base and structured medial meshes of an oriented point cloud: the mesh path's
 * MedialMeshEstimation (Voronoi MAT of the samples + Q-MAT, Li et al. 2015), with the cloud's
 * points as the surface samples and the cloud winding number of Barill et al. 2018 as the
 * inside test (makeSplatSurface()).
 *
 * A full medial mesh — slabs and cones with their connectivity — keeps thin sheets (cup walls,
 * table tops, fins) whole where a graph of loose medial points fragments, and lets the grower
 * use the medial-primitive term C_mp as on meshes. It needs consistently outward normals (the
 * inside test reads them) and a sampling dense enough to resolve the thinnest part.
 *
 * Each point's area is π d² / (k + 1), d its distance to its k-th nearest neighbour: the area
 * per point of a locally uniform sampling.
 *
 * \code
 * pcl::PointCloud<pcl::PointNormal>::Ptr cloud = ...;  // outward normals (CloudPreprocessing)
 * segmat::CloudMedialMeshEstimation estimation;
 * estimation.setInputCloud(cloud);
 * segmat::MedialMesh base, structured;
 * if (estimation.compute(base, structured)) ...
 * \endcode
 */
class CloudMedialMeshEstimation
{
public:
  using Ptr = std::shared_ptr<CloudMedialMeshEstimation>;
  using ConstPtr = std::shared_ptr<const CloudMedialMeshEstimation>;

  /** \brief Defaults: k = 8 for the point areas; MedialMeshEstimation's targets and limits,
   * merged centres not tested against the surface (MedialMeshEstimation::setKeepCentresInside). */
  CloudMedialMeshEstimation();

  /** \brief The points with unit outward normals (points or normals that are not finite are
   * skipped). */
  void
  setInputCloud(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud)
  {
    cloud_ = cloud;
  }

  /** \brief The input cloud. */
  const pcl::PointCloud<pcl::PointNormal>::ConstPtr&
  getInputCloud() const
  {
    return cloud_;
  }

  /** \brief Neighbour rank k of the point-area estimate (default 8; values < 1 are refused with a
   * warning). */
  void
  setAreaKSearch(int k);

  /** \brief Neighbour rank k of the point-area estimate. */
  int
  getAreaKSearch() const
  {
    return area_k_;
  }

  /** \brief The underlying mesh-path estimation, for its targets, sample limit and threads
   * (setBaseTarget, setStructuredTarget, setMaxSampleCount, setNumberOfThreads, ...). Its input
   * mesh, samples and winding number are set by compute(). */
  MedialMeshEstimation&
  getMedialMeshEstimation()
  {
    return estimation_;
  }

  /** \brief The underlying mesh-path estimation. */
  const MedialMeshEstimation&
  getMedialMeshEstimation() const
  {
    return estimation_;
  }

  /** \brief Computes the initial, base and structured medial meshes.
   * \param[out] base the base MAT
   * \param[out] structured the structured MAT
   * \return false (PCL_ERROR, empty outputs) when there is no input, fewer than 4 usable oriented
   *         points, or the estimation fails (e.g. the cloud encloses no volume)
   */
  bool
  compute(MedialMesh& base, MedialMesh& structured);

  /** \brief compute() in two halves, as MedialMeshEstimation: the initial MAT of the cloud
   * (getMedialMeshEstimation().getInitialMat()), then its simplification. The cloud must stay
   * as it is between the two.
   * \return false (PCL_ERROR) as compute() */
  bool
  computeInitialMat();

  /** \brief The simplification of the initial MAT of the last computeInitialMat(), once per
   * computeInitialMat() (MedialMeshEstimation::simplify()). */
  bool
  simplify(MedialMesh& base, MedialMesh& structured);

  /** \brief The splat surface of the last compute() or computeInitialMat() (one triangle per
   * used point). */
  const TriangleMesh&
  getSplatSurface() const
  {
    return *splats_;
  }

  /** \brief Counts and timings of the last compute(). */
  const MedialMeshEstimationStatistics&
  getStatistics() const
  {
    return estimation_.getStatistics();
  }

private:
  pcl::PointCloud<pcl::PointNormal>::ConstPtr cloud_;
  int area_k_ = 8;
  MedialMeshEstimation estimation_;
  TriangleMesh::Ptr splats_ = std::make_shared<TriangleMesh>();
};

} // namespace segmat
