/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace segmat {

/** \brief Deterministic surface samples of a triangle mesh with a bounded gap: every vertex that
 * a face uses, plus extra points so that no edge and no triangle interior is sampled more sparsely
 * than `max_spacing`.
 *
 * Mesh vertices carry the detail a modeller put in (thin parts, sharp features); the extra
 * points only fill long edges and big triangles, which plain vertex sampling (Q-MAT's initial
 * MAT) leaves too sparse for a faithful Voronoi medial axis.
 *  - Each mesh edge longer than h = `max_spacing` is split evenly into ceil(L / h) parts (the
 *    points are made once per edge, so neighbouring faces share them).
 *  - Each triangle gets the points of a triangular lattice of spacing h in its plane (rows parallel
 *    to its longest edge) that are at least h/2 from its three sides, so long slivers get none.
 * The output is: used vertices in index order, edge points in (smaller, larger vertex) order, then
 * interior points in face order. Fill points are computed from positions only, so an unwelded or
 * re-oriented copy of the mesh gets the same points. Nothing is random and nothing is
 * deduplicated here.
 * \param[in] mesh the surface; faces with an out-of-range index are skipped
 * \param[in] max_spacing h in mesh units; 0, negative or infinite adds no points
 * \return the samples
 */
std::vector<Eigen::Vector3d>
sampleSurface(const TriangleMesh& mesh, double max_spacing);

/** \brief Roughly how many points sampleSurface(mesh, max_spacing) returns (used vertices, plus
 * L / h per edge, plus area / (h² √3 / 2) per face; an over-estimate), in double so that an absurd
 * spacing cannot overflow. Lets a caller refuse a spacing before allocating the samples.
 */
double
estimateSurfaceSampleCount(const TriangleMesh& mesh, double max_spacing);

/** \brief Greedy Poisson-disk thinning: visits the points in index order and keeps a point when
 * no kept point lies within `radius` of it.
 *
 * Regions already sparser than `radius` keep every point; denser ones are thinned to a spacing of
 * about `radius`. Deterministic; O(n) with a hash grid.
 * \param[in] points the points (non-finite ones are dropped)
 * \param[in] radius the exclusion radius; ≤ 0 keeps every finite point
 * \return the indices of the kept points, ascending
 */
std::vector<int>
thinPoints(const std::vector<Eigen::Vector3d>& points, double radius);

/** \brief thinPoints() with a radius (searched to within 15 % of the count) that keeps at
 * most `max_count` points; all points when there are no more than that.
 */
std::vector<int>
thinPointsToCount(const std::vector<Eigen::Vector3d>& points, std::size_t max_count);

} // namespace segmat
