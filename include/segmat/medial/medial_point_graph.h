/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/point_types.h>
#include <segmat/medial/mat_graph.h>

#include <pcl/point_cloud.h>

#include <cstddef>
#include <memory>

namespace segmat {

/** \brief The MAT graph of a meso-skeleton: medial points linked to near neighbours whose balls
 * overlap (SEG-MAT, Lin et al. 2022, §6: "the MAT graph is constructed … using the k-nearest
 * neighbours of each medial point").
 *
 * Node i = MatNode{kind Point, v = (i, −1, −1), mean_radius = r_i, centroid = c_i, normal = the
 * point's unit normal (zero when it has none)}; sphere i = (c_i, r_i).
 * Edge i–j when j is among the k nearest centres of i or i among those of j, and the balls
 * overlap: |c_i − c_j| < ρ·(r_i + r_j). The overlap gate keeps k-NN edges from jumping the gap
 * between two parts that only come close (fingers side by side).
 *
 * Connectivity fallback (on by default): k-NN of a very uneven point set can split one
 * connected union of balls into several graph components (a dense blob soaks up all k
 * neighbours). Candidate bridges are the 4k nearest centres of every node whose balls overlap
 * and that lie in another component; they are taken shortest first (ties by index), one per
 * pair of components (Kruskal), until no overlapping candidate links two components. Parts
 * whose balls do not overlap stay apart; a node with no overlapping ball nearby stays alone.
 */
class MedialPointGraph
{
public:
  using Ptr = std::shared_ptr<MedialPointGraph>;
  using ConstPtr = std::shared_ptr<const MedialPointGraph>;
  using MedialCloud = pcl::PointCloud<MedialPoint>;

  /** \brief Defaults: k = 10, ρ = 1, connectivity fallback on. */
  MedialPointGraph();

  /** \brief The medial points (finite centres, radii >= 0). */
  void
  setInputCloud(const MedialCloud::ConstPtr& cloud)
  {
    input_ = cloud;
  }

  /** \brief The medial points. */
  const MedialCloud::ConstPtr&
  getInputCloud() const
  {
    return input_;
  }

  /** \brief Neighbours per node (> 0, default 10). */
  void
  setKSearch(int k);

  /** \brief Neighbours per node. */
  int
  getKSearch() const
  {
    return k_;
  }

  /** \brief ρ of the overlap gate |c_i − c_j| < ρ(r_i + r_j) (> 0, default 1). */
  void
  setOverlapFactor(double rho);

  /** \brief ρ of the overlap gate. */
  double
  getOverlapFactor() const
  {
    return overlap_factor_;
  }

  /** \brief Bridge graph components whose balls overlap (default true). */
  void
  setConnectComponentsFlag(bool flag)
  {
    connect_components_ = flag;
  }

  /** \brief Whether overlapping components are bridged. */
  bool
  getConnectComponentsFlag() const
  {
    return connect_components_;
  }

  /** \brief Build the graph.
   * \param[out] graph the MAT graph (empty on failure)
   * \return false (PCL_ERROR) without input, with an empty cloud, or with a non-finite centre
   *         or radius, or a negative radius
   */
  bool
  compute(MatGraph& graph);

  /** \brief Connected components of the last graph (after bridging). */
  std::size_t
  getNumberOfComponents() const
  {
    return components_;
  }

  /** \brief Edges added by the connectivity fallback in the last compute(). */
  std::size_t
  getNumberOfBridges() const
  {
    return bridges_;
  }

private:
  MedialCloud::ConstPtr input_;
  int k_;
  double overlap_factor_;
  bool connect_components_;
  std::size_t components_ = 0;
  std::size_t bridges_ = 0;
};

} // namespace segmat
