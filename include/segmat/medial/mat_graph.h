/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace segmat {

class MedialMesh;

/** \brief What a MAT-graph node stands for. */
enum class MatNodeKind : std::uint8_t
{
  Slab,  ///< a medial triangle: three spheres
  Cone,  ///< a pure medial edge: two spheres
  Point, ///< a lone medial point with a normal (meso-skeleton of a cloud): one sphere
};

/** \brief One node of the MAT graph: a medial primitive and what the cost terms need of it. */
struct MatNode
{
  MatNodeKind kind = MatNodeKind::Point;
  /// sphere indices into MatGraph::centers(); unused slots are -1 (cone: v[2]; point: v[1], v[2])
  Eigen::Vector3i v = Eigen::Vector3i::Constant(-1);
  double mean_radius = 0.0;        ///< r̄: mean radius of the node's spheres
  Eigen::Vector3d centroid;        ///< mean of the node's sphere centres (a cone's midpoint)
  Eigen::Vector3d normal;          ///< slab: unit plane normal; point: unit normal; cone: zero

  /** \brief Number of spheres (3, 2 or 1). */
  int
  size() const
  {
    return kind == MatNodeKind::Slab ? 3 : (kind == MatNodeKind::Cone ? 2 : 1);
  }
};

/** \brief The graph the region grower sees (SEG-MAT, Lin et al. 2022, §4.1).
 *
 * Nodes are medial slabs and pure medial cones of a medial mesh, or medial points of a cloud's
 * meso-skeleton. Both paths build this one type; nothing downstream knows which made it.
 * Adjacency is stored CSR-style, sorted and symmetric.
 */
class MatGraph
{
public:
  using Ptr = std::shared_ptr<MatGraph>;
  using ConstPtr = std::shared_ptr<const MatGraph>;

  MatGraph() = default;

  /** \brief Generic constructor: spheres, nodes (mean radius, centroid filled by the caller) and
   * adjacency lists (made symmetric, sorted and free of self-loops here).
   */
  MatGraph(std::vector<Eigen::Vector3d> centers, std::vector<double> radii,
           std::vector<MatNode> nodes, const std::vector<std::vector<int>>& adjacency);

  /** \brief The base-MAT graph of SEG-MAT §4.1 (the authors' `buildMATGraph`).
   *
   * Nodes: every triangle (in order), then every pure edge (in order). Two nodes are adjacent
   * when they share a sphere and the ratio of their mean radii is below \a radius_gate
   * (reference default 2.5, i.e. C_r < 1.5). Built from vertex incidence lists, not all pairs.
   */
  static MatGraph
  fromMedialMesh(const MedialMesh& mat, double radius_gate = 2.5);

  std::size_t numNodes() const { return nodes_.size(); }
  std::size_t numSpheres() const { return centers_.size(); }
  bool empty() const { return nodes_.empty(); }

  const MatNode& node(int i) const { return nodes_[i]; }
  const std::vector<MatNode>& nodes() const { return nodes_; }
  const std::vector<Eigen::Vector3d>& centers() const { return centers_; }
  const std::vector<double>& radii() const { return radii_; }

  /** \brief Neighbours of node i: pointer range [begin, end), ascending. */
  const int* neighboursBegin(int i) const { return adjacency_.data() + offsets_[i]; }
  const int* neighboursEnd(int i) const { return adjacency_.data() + offsets_[i + 1]; }
  int degree(int i) const { return offsets_[i + 1] - offsets_[i]; }
  /** \brief Number of undirected graph edges. */
  std::size_t numEdges() const { return adjacency_.size() / 2; }

  /** \brief True when some node is a slab or a cone, i.e. the medial-primitive term C_mp exists. */
  bool hasPrimitives() const;

  /** \brief Diagonal of the bounding box of the sphere centres. */
  double centerBoundingBoxDiagonal() const;

private:
  std::vector<Eigen::Vector3d> centers_;
  std::vector<double> radii_;
  std::vector<MatNode> nodes_;
  std::vector<int> offsets_{0};
  std::vector<int> adjacency_;
};

} // namespace segmat
