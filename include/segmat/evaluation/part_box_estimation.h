/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/oriented_box.h>
#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <map>
#include <memory>
#include <vector>

namespace segmat {

/** \brief One tight oriented box per part of a segmented mesh or point cloud: the primitive
 * abstraction of SEG-MAT (Lin et al. 2022, §7, which replaces every part by its minimal-volume
 * oriented bounding box).
 *
 * A mesh part is the set of vertices its faces use (a vertex shared by two parts belongs to
 * both); a cloud part is its points. Each part's box is computeMinimumVolumeBox() of those
 * points, so it holds all of them and is never larger than their axis-aligned box. Parts are
 * reported in increasing label order; negative labels (unlabelled) get no box.
 *
 * \code
 * segmat::PartBoxEstimation boxes;
 * boxes.setInputMesh(mesh, face_labels);     // or setInputPoints(points, labels)
 * std::vector<segmat::PartBox> out;
 * boxes.compute(out);
 * segmat::io::saveBoxesJson("out_boxes.json", out);
 * \endcode
 */
class PartBoxEstimation
{
public:
  using Ptr = std::shared_ptr<PartBoxEstimation>;
  using ConstPtr = std::shared_ptr<const PartBoxEstimation>;

  /** \brief A segmented mesh: one label per face.
   * \throws segmat::Error when the label count differs from the face count or a face has an
   *         out-of-range vertex index.
   */
  void
  setInputMesh(const TriangleMesh::ConstPtr& mesh, const std::vector<int>& face_labels);

  /** \brief A segmented point cloud: one label per point.
   * \throws segmat::Error when the label count differs from the point count.
   */
  void
  setInputPoints(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& labels);

  /** \brief Fits the boxes (parts in label order).
   * \param[out] boxes one box per label ≥ 0 that has at least one point
   */
  void
  compute(std::vector<PartBox>& boxes) const;

private:
  std::map<int, std::vector<Eigen::Vector3d>> part_points_; ///< points of each label ≥ 0
};

} // namespace segmat
