/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/medial/mat_graph.h>

#include <Eigen/Core>

#include <vector>

namespace segmat {

/** \brief Weights of the growing cost (SEG-MAT, Lin et al. 2022, §4.3; the authors'
 * `checkFaceGrowing`). */
struct GrowingCostWeights
{
  double alpha = 0.05;            ///< α, weight of the angle term C_θ
  double lambda = 1.5;            ///< λ, weight of the medial-primitive term C_mp
  bool use_primitive_term = true; ///< false: cost = C_r + α·C_θ (graphs of points have no C_mp)
  double radius_tolerance = 0.0;  ///< radius differences up to this length do not count in C_r
};

/** \brief Radius term C_r = max(r̄_a, r̄_b) / min(r̄_a, r̄_b) − 1 (>= 0).
 *
 * With a \a tolerance t > 0: max(0, max − min − t) / min, so that differences the surface cannot
 * tell apart (its remaining noise) cost nothing. Guards r̄ = 0 (undefined in the authors' code):
 * two zero mean radii give 0, one gives +inf; a NaN radius gives NaN.
 */
double
radiusCost(const MatNode& a, const MatNode& b, double tolerance = 0.0);

/** \brief Angle term C_θ: the bend between two nodes in degrees / 180, in [0, 1].
 *
 *  - slab–slab: angle between the normals, both turned towards the midpoint of the two
 *    centroids as seen from the first shared sphere (0 = coplanar, 1 = folded flat);
 *  - cone–cone: 180° minus the angle at the shared sphere between the two cones (0 = straight
 *    continuation, 1 = folded back); without a shared sphere the angle between the lines;
 *  - cone–slab: 180° − acos(|d·n|), in [½, 1] (½: the line lies in the slab's plane);
 *  - point–point (and point–slab): acos(|n_a·n_b|), in [0, ½] (the authors' unused point-cloud
 *    branch);
 *  - point–cone: as cone–slab, the point's normal standing for the sheet normal.
 * A zero normal or direction (degenerate slab, zero-length cone, point without normal) gives ½.
 * Fix of the reference: when the slabs are coplanar the reference vector lies in their plane and
 * its sign test flips a normal at random (giving 180° for a flat pair); here a near-zero test
 * falls back to acos(|n_a·n_b|).
 * \param[in] centers sphere centres the nodes index into (MatGraph::centers())
 */
double
angleCost(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers);

/** \brief Medial-primitive term C_mp, in [0, ~1].
 *
 *  - slab–slab: (angle between the +sides + angle between the −sides) / 2π of the two slabs'
 *    tangent planes (computeSlabSides), with normals oriented as for C_θ; 1 when either slab
 *    has no tangent planes;
 *  - cone–cone (sharing sphere c, far ends 0 and 1): β = angle at c, φ_k = coneSlopeAngle(c, k),
 *    A = (β + φ0 + φ1)/π, B = (2π − β + φ0 + φ1)/π; the result is (A+B−2)/2, (A+B−1)/2 or
 *    (A+B)/2 when none, one or both of A, B are below 1 (a side that bends inwards counts as a
 *    primitive change: a neck scores ≈ 1). A or B within 1e-9 of 1 counts as 1, so that a
 *    straight cone or cylinder does not flip between 0 and ½ on rounding (a fix; the reference
 *    compares exactly). sign(0) = 0 and clamped asin: equal radii are defined (the authors'
 *    code divides 0 by 0). 1 when the cones share no sphere;
 *  - cone–slab: 1 (undefined in the authors' code); anything with a point: 1.
 */
double
primitiveCost(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers,
              const std::vector<double>& radii);

/** \brief min(C_r + α·C_θ, λ·C_mp), or C_r + α·C_θ when the primitive term is off.
 *
 * A NaN term (from NaN input data) makes the cost +inf: it never means "grow" (in the
 * authors' code a NaN made every comparison false and so accepted the node).
 */
double
combineGrowingCost(double radius_cost, double angle_cost, double primitive_cost,
                   const GrowingCostWeights& weights);

/** \brief Cost of growing from node i to node j of a graph (all three terms, combined).
 *
 * C_mp is evaluated only when weights.use_primitive_term is set; callers should clear it for
 * graphs without primitives (MatGraph::hasPrimitives()).
 */
double
growingCost(const MatGraph& graph, int i, int j, const GrowingCostWeights& weights);

/** \brief Growing threshold between two tagged nodes (SEG-MAT §4.2–4.3).
 *
 * δ0·tag_ratio[tag] inside one thin part, δ0 when both are bulky (tag 0), 0 across a tag change
 * (a node still joins at exactly zero cost: the test is cost <= threshold). A tag without a ratio
 * counts as bulky.
 */
double
growingThreshold(double delta0, int tag_a, int tag_b, const std::vector<double>& tag_ratio);

} // namespace segmat
