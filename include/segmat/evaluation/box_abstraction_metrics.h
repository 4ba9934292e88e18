/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/oriented_box.h>
#include <segmat/geometry/triangle_mesh.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace segmat {

/** \brief How well a set of boxes abstracts a solid shape: the two scores of SEG-MAT's primitive
 * abstraction table (Lin et al. 2022, §7), after Tulsiani et al. 2017 ("Learning shape
 * abstractions by assembling volumetric primitives") and Sun et al. 2019 ("Learning adaptive
 * hierarchical cuboid abstractions of 3D shape collections").
 */
struct BoxAbstractionScores
{
  double iou = 0.0;             ///< volume(shape ∩ ∪boxes) / volume(shape ∪ ∪boxes)
  double chamfer = 0.0;         ///< symmetric Chamfer distance, unsquared (see below)
  double chamfer_squared = 0.0; ///< the same with squared nearest distances
};

/** \brief Scores boxes against a closed triangle mesh.
 *
 * IoU: the cells of a regular grid over the shape's and the boxes' common bounding box, with
 * \a resolution cells along its longest side (cubic cells), are tested at their centres: inside
 * the shape when the generalised winding number exceeds 0.5 (WindingNumber), inside the union
 * when some box contains the centre. IoU = |both| / |either|.
 *
 * Chamfer: \a samples points drawn uniformly by area on the shape's surface and as many on the
 * boxes' surfaces (each box's six faces; seeded, deterministic). With the shape scaled to unit
 * bounding-box diagonal, `chamfer` = ½ (mean_a min_b |a − b| + mean_b min_a |a − b|) and
 * `chamfer_squared` the same with |a − b|².
 * \param[in] shape a closed mesh (the solid's surface)
 * \param[in] boxes the abstraction
 * \param[in] resolution grid cells along the longest side (≥ 2)
 * \param[in] samples points per surface (≥ 1)
 * \param[in] threads threads of the winding-number evaluation (0: OpenMP's default); the scores
 *            do not depend on it
 * \param[in] seed seed of the surface sampling
 * \throws segmat::Error for an empty shape, no box, resolution < 2 or samples < 1.
 */
BoxAbstractionScores
scoreBoxAbstraction(const TriangleMesh& shape, const std::vector<OrientedBox>& boxes,
                    int resolution = 64, std::size_t samples = 10000, unsigned threads = 1,
                    std::uint64_t seed = 1);

} // namespace segmat
