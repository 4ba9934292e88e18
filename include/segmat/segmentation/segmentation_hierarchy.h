/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>
#include <segmat/segmentation/detail_level.h>

#include <vector>

namespace segmat {

class MeshSegmentation;

/** \brief One level of a nested segmentation hierarchy. */
struct HierarchyLevel
{
  DetailLevel level;        ///< the δ and η it was segmented with
  std::vector<int> labels;  ///< one label per face, 0..K−1 in order of each part's first face
  std::vector<int> parents; ///< per part: the part of the previous (coarser) level holding it;
                            ///< −1 on the first level
};

/** \brief Cuts the parts of \a coarse along the boundaries of \a fine, so that every part of the
 * result lies inside one part of \a coarse.
 *
 * The faces are grouped into connected pieces (across mesh edges) with the same coarse and fine
 * label; then, smallest first, each piece with less than \a min_area_fraction of the mesh's area
 * joins the neighbouring piece of the same coarse part with which it shares the longest
 * boundary (a piece with no such neighbour stays). Nesting therefore holds by construction,
 * whatever \a fine is.
 * \param[in] mesh the mesh
 * \param[in] coarse one label per face (the parents)
 * \param[in] fine one label per face (the finer segmentation)
 * \param[in] min_area_fraction pieces below this fraction of the total area are merged
 * \param[out] nested one label per face, 0..K−1 in order of first face
 * \param[out] parents per nested part, its coarse label
 * \throws segmat::Error when a label count differs from the face count.
 */
void
nestSegmentation(const TriangleMesh& mesh, const std::vector<int>& coarse,
                 const std::vector<int>& fine, double min_area_fraction, std::vector<int>& nested,
                 std::vector<int>& parents);

/** \brief Segments the input mesh of \a segmentation at every level, coarse to fine, and nests
 * each level inside the previous one (nestSegmentation with the finer level's η as the area
 * fraction).
 *
 * The medial meshes, graph and structure tags are computed by the first segment() and reused by
 * the others (MeshSegmentation recomputes nothing when only δ and η change). The segmentation's
 * δ and η are left at the last level's values.
 * \param[in,out] segmentation with its input mesh (and medial meshes, if given) set
 * \param[in] levels coarse to fine
 * \param[out] hierarchy one entry per level
 * \return false when a segmentation fails
 */
bool
segmentHierarchy(MeshSegmentation& segmentation, const std::vector<DetailLevel>& levels,
                 std::vector<HierarchyLevel>& hierarchy);

} // namespace segmat
