/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <limits>
#include <memory>
#include <vector>

namespace segmat {

/** \brief A bounding-volume tree over a set of spheres that answers, exactly, the smallest
 * signed distance from a query point to the spheres' surfaces: min_i (|q − c_i| − r_i).
 *
 * This is SEG-MAT's point-to-part distance (the graph-cut data
 * term and the tiny-patch distance); a negative value means q lies inside some sphere. Each node
 * of the tree keeps the box of its centres and its largest radius, so |q − box| − r_max bounds
 * every sphere below it; branch-and-bound then visits a few dozen spheres instead of all.
 */
class SphereTree
{
public:
  using Ptr = std::shared_ptr<SphereTree>;
  using ConstPtr = std::shared_ptr<const SphereTree>;

  /** \brief An empty tree (every query returns +infinity). */
  SphereTree() = default;

  /** \brief Build over all spheres (\a centers, \a radii). */
  SphereTree(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii);

  /** \brief Build over the spheres \a indices of (\a centers, \a radii) (none when empty);
   * indices out of range are skipped, repeated ones count once.
   */
  SphereTree(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii,
             const std::vector<int>& indices);

  /** \brief Number of spheres in the tree. */
  std::size_t
  size() const
  {
    return centers_.size();
  }

  /** \brief True when the tree holds no sphere. */
  bool
  empty() const
  {
    return centers_.empty();
  }

  /** \brief Centre of sphere \a i, an index as given to the constructor (and as signedDistance()
   * reports it) of a sphere in the tree. */
  const Eigen::Vector3d&
  center(int i) const
  {
    return centers_[position_[i]];
  }

  /** \brief Radius of sphere \a i (see center()). */
  double
  radius(int i) const
  {
    return radii_[position_[i]];
  }

  /** \brief min over the spheres of |q − c| − r (+infinity when empty).
   * \param[in] q query point
   * \param[in] stop_below return as soon as a sphere with a value <= this is found (the value
   *            returned is then that sphere's, an upper bound of the minimum that is itself
   *            <= stop_below). Pass 0 when only max(0, distance) is needed.
   * \param[in,out] nearest in: a sphere index (as given to the constructor) to try first — the
   *            previous query's answer when queries are spatially coherent — or -1; out: the
   *            sphere that gave the returned value (-1 when empty).
   */
  double
  signedDistance(const Eigen::Vector3d& q,
                 double stop_below = -std::numeric_limits<double>::infinity(),
                 int* nearest = nullptr) const;

private:
  struct Node
  {
    Eigen::Vector3d lo, hi;  ///< box of the centres below
    double max_radius = 0.0; ///< largest radius below
    int first = 0, last = 0; ///< sphere range [first, last) in the reordered arrays
    int left = -1, right = -1;
  };

  void
  init(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii);

  int
  build(int first, int last);

  std::vector<Eigen::Vector3d> centers_; ///< reordered so every node's spheres are contiguous
  std::vector<double> radii_;
  std::vector<int> original_;            ///< position → index given to the constructor
  std::vector<int> position_;            ///< index given to the constructor → position, or -1
  std::vector<Node> nodes_;
};

} // namespace segmat
