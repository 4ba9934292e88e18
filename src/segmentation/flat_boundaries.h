/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <pcl/PointIndices.h>

#include <vector>

namespace segmat {
namespace detail {

/** \brief One edge of a transfer's surface graph (faces sharing an edge, or neighbouring
 * points), as joinFlatBoundaries() reads it. */
struct BoundaryEdge
{
  int a = -1, b = -1;     ///< the two elements
  double curvature = 0.0; ///< crossingCurvature() of the pair (NaN: unknown, not counted)
  double weight = 1.0;    ///< share of the boundary: the shared edge's length, or 1 per point pair
};

/** \brief Curvature of the surface across two neighbouring elements: the angle between their
 * outward normals (radians) over the distance between their centres. Positive when the pair is
 * concave (computeCreaseCost()'s test), negative when convex; NaN when it cannot be measured
 * (coincident centres, a zero or non-finite normal: a degenerate face). */
double
crossingCurvature(const Eigen::Vector3d& centre_a, const Eigen::Vector3d& normal_a,
                  const Eigen::Vector3d& centre_b, const Eigen::Vector3d& normal_b);

/** \brief Largest |curvature| × diagonal of a flat boundary: 2, the curvature of the shape's
 * bounding sphere (radius half the diagonal). */
constexpr double kFlatBoundaryCurvature = 2.0;

/** \brief Joins labels whose shared boundary runs across flat surface.
 *
 * Parts meet where the surface folds (the minima rule): a boundary that crosses a plane or a
 * nearly flat stretch of surface separates nothing a person would separate, such as the middle
 * and the rims of a box's face, which a medial axis reads as parts of different thickness. Two
 * labels are joined when the weighted median of |curvature| over the edges between them, times
 * \a diagonal, is at most kFlatBoundaryCurvature: most of their boundary curves less than the
 * shape's bounding sphere. The median, not the mean, so that the few edges where a flat
 * boundary meets a crease do not count. Edges of unknown curvature or without weight are left
 * out. The flattest pair is joined first and the boundaries are measured again, until no pair
 * is flat.
 * \param[in] labels one label in [0, num_labels) per element
 * \param[in] num_labels number of labels
 * \param[in] edges the surface graph
 * \param[in] diagonal the surface's bounding-box diagonal
 * \return for each label its group, numbered in order of each group's lowest label
 */
std::vector<int>
joinFlatBoundaries(const std::vector<int>& labels, int num_labels,
                   const std::vector<BoundaryEdge>& edges, double diagonal);

/** \brief The MAT-graph nodes of a label that joins \a members of \a parts: their nodes,
 * ascending. */
pcl::PointIndices
joinParts(const std::vector<pcl::PointIndices>& parts, const std::vector<int>& members);

} // namespace detail
} // namespace segmat
