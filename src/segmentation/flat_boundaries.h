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
  double curvature = 0.0; ///< across the pair (measureSideCurvatures(); NaN: unknown, not counted)
  double weight = 1.0;    ///< share of the boundary: the shared edge's length, or 1 per point pair
};

/** \brief A transfer's surface graph, as the flat-boundary rule reads it: the element pairs
 * (faces sharing an edge, or neighbouring points) and each element's outward normal. The
 * curvature across a boundary is measured between its two sides (measureSideCurvatures()). */
struct BoundaryGraph
{
  std::vector<BoundaryEdge> edges;
  std::vector<Eigen::Vector3d> normals; ///< per element
  /// Each element's neighbours over \a edges: neighbours[offsets[i] .. offsets[i + 1]), filled
  /// by indexNeighbours(). Kept with the graph, which serves every transfer of one surface.
  std::vector<int> offsets, neighbours;
};

/** \brief Fills \a graph's neighbour lists from its edges, for \a num_elements elements. */
void
indexNeighbours(BoundaryGraph& graph, int num_elements);

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

/** \brief Steps of the surface graph that one side of a boundary spans
 * (measureSideCurvatures()). Normals turn from one element to the next by whatever noise the
 * surface still has. A cloud's normals are fitted to 16 neighbours, a radius of about two point
 * spacings, so neighbouring normals share most of their points and their noise: averaged over
 * one or two steps of the 10-neighbour graph (about 1.5 spacings each) the noise stays, and
 * three steps reach about twice the fits' radius. On a mesh three steps of the face graph take
 * up to about 20 faces a side. */
constexpr int kSideSteps = 3;

/** \brief A side stops at a crease: an element whose normal turns from the side's first one
 * by this much or more is left out, and the side does not spread through it. 45° is where the
 * bilateral normal filter's range weight (σ_r = 0.35) falls below a tenth. On a coarse mesh a
 * side would otherwise reach across a crease onto the next flat face, in a share that the
 * other side need not mirror (MeshLabelTransfer.BarSplitsAtTheMiddle). */
constexpr double kSideCreaseDegrees = 45.0;

/** \brief The curvature across every edge between two labels, measured between the edge's two
 * sides: each end's label's elements within kSideSteps steps of it over the graph (through that
 * label only, and short of kSideCreaseDegrees), by crossingCurvature() of their mean positions
 * and mean normals. A fold stays a fold, since each side averages its own part of the surface;
 * noise in the normals averages out. Along a boundary that runs around a tube, pairs of
 * elements turn with the tube, while the two sides' means turn only as the surface does across
 * the boundary.
 * \param[in] graph the surface graph, with its neighbour lists (indexNeighbours())
 * \param[in] labels one label per element
 * \param[in] positions each element's position
 * \return the graph's edges between two labels, in graph order, each with its curvature
 * measured (the edges inside a label are all that joinFlatBoundaries() would leave out) */
std::vector<BoundaryEdge>
measureSideCurvatures(const BoundaryGraph& graph, const std::vector<int>& labels,
                      const std::vector<Eigen::Vector3d>& positions);

/** \brief The MAT-graph nodes of a label that joins \a members of \a parts: their nodes,
 * ascending. */
pcl::PointIndices
joinParts(const std::vector<pcl::PointIndices>& parts, const std::vector<int>& members);

} // namespace detail
} // namespace segmat
