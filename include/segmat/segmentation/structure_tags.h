/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace segmat {

class MedialMesh;
class MatGraph;

/** \brief Per-node structural tags of the base MAT (SEG-MAT, Lin et al. 2022, §4.2).
 *
 * Tag 0 means "bulky" (every normal component of the structured MAT, or no structured MAT);
 * tag k >= 1 means "inside thin part k-1" of the structured MAT. The region grower uses
 * `tag_ratio[tag]` to scale its threshold inside a thin part.
 */
struct StructureTags
{
  /// one tag per base-graph node; empty means "all 0"
  std::vector<int> node_tag;
  /// tag_ratio[k] = log2(ρ) of thin part k-1 (> 3 since ρ > 8); tag_ratio[0] = 0
  std::vector<double> tag_ratio{0.0};
  /// per base-graph node: the unit direction of the structured-MAT segment whose densified point
  /// is nearest when it belongs to a bulky (tag 0) line component, else zero (sheets, thin
  /// parts); empty when the structured MAT has neither a thin part nor a bulky line
  std::vector<Eigen::Vector3d> node_axis;

  /** \brief Number of thin parts. */
  int
  numThinParts() const
  {
    return tag_ratio.empty() ? 0 : static_cast<int>(tag_ratio.size()) - 1;
  }
};

/** \brief Thin-part detection on a structured MAT and transfer to the base graph
 * (SEG-MAT §4.2; the authors' `StructureDecompose` and `transfer_SMAT_MAT`).
 *
 * The structured MAT (~15–40 spheres) is cut into components: lines are cut at branch points
 * unless the two lines are nearly collinear (|cos| > 0.95), sheets at non-manifold edges, and a
 * line never joins a sheet. A line component with ρ = L / r_max > 100 is dropped; ρ > 8 is thin.
 * For a line, r_max leaves out its branch-point spheres (shared by 3+ structure nodes) when it
 * has other spheres: they belong to the body it grows from (a deviation from the reference).
 * A sheet component is thin when it is manifold and ρ = √A / r_max > 8. Every kept component is
 * densified (13 steps) and each base node takes the tag of the component owning the nearest
 * densified point to its centroid (ties: the first thin part). A thin part that would tag more
 * than 85 % of the base nodes with ρ ≤ 10 tags none (a deviation from the reference): a part is
 * thin against the rest of the shape, and a noisy bird whose body and wings merged into one
 * barely slender sheet (ρ ≈ 8.2) would otherwise get the raised threshold everywhere; a
 * dumbbell's sheet (ρ ≈ 13) and a cup's wall (ρ = 24–34) keep it. An untagged part keeps its
 * tag_ratio entry; its nodes are bulky without a direction (node_axis stays zero).
 *
 * \param[in] structured the structured (very coarse) MAT; may be empty (all tags 0)
 * \param[in] base the base MAT graph whose nodes are tagged
 * \return node_tag of size base.numNodes() and tag_ratio of size (thin parts + 1)
 */
StructureTags
computeStructureTags(const MedialMesh& structured, const MatGraph& base);

} // namespace segmat
