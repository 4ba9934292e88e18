/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/aabb_tree.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>
#include <segmat/segmentation/label_transfer.h>
#include <segmat/segmentation/mat_graph.h>
#include <segmat/segmentation/mat_region_growing.h>
#include <segmat/segmentation/structure_tags.h>

#include <pcl/PointIndices.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

/** \brief End-to-end part segmentation of a triangle mesh with SEG-MAT (Lin et al., "SEG-MAT:
 * 3D Shape Segmentation Using Medial Axis Transform", IEEE TVCG 2022).
 *
 * Stages, each timed (getStageSeconds()):
 *  1. "graph": the base-MAT graph (MatGraph::fromMedialMesh, §4.1);
 *  2. "tags": structural tags from the structured MAT (computeStructureTags, §4.2);
 *  3. "surface_tree": an AabbTree over the mesh, for the merging's visibility test;
 *  4. "grow_merge": region growing, swallowing, tiny-patch absorption and merging
 *     (MatRegionGrowing, §4.3–4.4);
 *  5. "transfer": the parts carried to the faces by α-expansion (MeshLabelTransfer, §5).
 * Stages 1–3 (and the transfer's face-graph weights) depend only on the inputs: they are computed
 * once and reused when only δ0, η, α, λ or ω change and segment() runs again (CGAL's split of
 * sdf_values / segmentation_from_sdf_values). A reused stage reports 0 seconds.
 *
 * The medial meshes are inputs for now (e.g. the authors' Q-MAT files, io::loadMa); computing
 * them from the mesh is the job of a separate estimator. Without them segment() fails.
 *
 * \code
 * segmat::MeshSegmentation seg;
 * seg.setInputMesh(mesh);           // TriangleMesh::ConstPtr (io::loadMesh)
 * seg.setBaseMat(base);             // MedialMesh::ConstPtr (io::loadMa)
 * seg.setStructuredMat(structured); // MedialMesh::ConstPtr
 * std::vector<int> face_labels;
 * if (seg.segment(face_labels))
 *   segmat::io::saveSeg("out.seg", face_labels);
 * \endcode
 */
class MeshSegmentation
{
public:
  using Ptr = std::shared_ptr<MeshSegmentation>;
  using ConstPtr = std::shared_ptr<const MeshSegmentation>;

  /** \brief Paper defaults: δ0 = 0.015, η = 0.002, α = 0.05, λ = 1.5, ω = 0.3. */
  MeshSegmentation();

  /** \brief The surface to segment (its faces get the labels). */
  void
  setInputMesh(const TriangleMesh::ConstPtr& mesh);

  /** \brief The surface. */
  TriangleMesh::ConstPtr
  getInputMesh() const
  {
    return mesh_;
  }

  /** \brief The base (detailed, e.g. 2000-sphere Q-MAT) medial mesh: the graph the parts grow
   * on.
   */
  void
  setBaseMat(const MedialMesh::ConstPtr& base);

  /** \brief The base medial mesh. */
  MedialMesh::ConstPtr
  getBaseMat() const
  {
    return base_;
  }

  /** \brief The structured (coarse, e.g. 15–30-sphere Q-MAT) medial mesh that tells thin parts
   * from bulky ones. An empty one is accepted (every node is then bulky, like the reference).
   */
  void
  setStructuredMat(const MedialMesh::ConstPtr& structured);

  /** \brief The structured medial mesh. */
  MedialMesh::ConstPtr
  getStructuredMat() const
  {
    return structured_;
  }

  /** \brief δ0, the growing threshold (default 0.015). */
  void
  setGrowingThreshold(double delta0)
  {
    grower_.setGrowingThreshold(delta0);
  }

  /** \brief δ0. */
  double
  getGrowingThreshold() const
  {
    return grower_.getGrowingThreshold();
  }

  /** \brief η, the minimal region size as a fraction of the base MAT's spheres (default 0.002).
   */
  void
  setMinRegionFraction(double eta)
  {
    grower_.setMinRegionFraction(eta);
  }

  /** \brief η. */
  double
  getMinRegionFraction() const
  {
    return grower_.getMinRegionFraction();
  }

  /** \brief α, weight of the angle term of the growing cost (default 0.05). */
  void
  setAngleWeight(double alpha)
  {
    grower_.setAngleWeight(alpha);
  }

  /** \brief α. */
  double
  getAngleWeight() const
  {
    return grower_.getAngleWeight();
  }

  /** \brief λ, weight of the medial-primitive term of the growing cost (default 1.5). */
  void
  setPrimitiveWeight(double lambda)
  {
    grower_.setPrimitiveWeight(lambda);
  }

  /** \brief λ. */
  double
  getPrimitiveWeight() const
  {
    return grower_.getPrimitiveWeight();
  }

  /** \brief ω, weight of the graph cut's smoothness term (default 0.3). */
  void
  setSmoothnessWeight(double omega)
  {
    transfer_.setSmoothnessWeight(omega);
  }

  /** \brief ω. */
  double
  getSmoothnessWeight() const
  {
    return transfer_.getSmoothnessWeight();
  }

  /** \brief Segment the mesh.
   * \param[out] face_labels one label per face, dense 0..k−1, numbered by descending part size
   *             (face count; ties: the part grown first comes first). Empty on failure.
   * \return false (PCL_ERROR) when the mesh has no faces, a medial mesh is missing or the base
   *         one is empty, or a stage fails.
   */
  bool
  segment(std::vector<int>& face_labels);

  /** \brief Faces of each part of the last segment(), in label order (indices ascending). */
  void
  getParts(std::vector<pcl::PointIndices>& parts) const;

  /** \brief Seconds spent in each stage by the last segment(), in pipeline order ("graph",
   * "tags", "surface_tree", "grow_merge", "transfer"); a stage whose result was reused reports 0.
   */
  const std::vector<std::pair<std::string, double>>&
  getStageSeconds() const
  {
    return stage_seconds_;
  }

  /** \brief The base-MAT graph of the last segment() (null before). */
  MatGraph::ConstPtr
  getGraph() const
  {
    return graph_;
  }

  /** \brief MAT-graph nodes of each part of the last segment(), in label order: everything the
   * grower assigned (grown, swallowed and absorbed nodes).
   */
  const std::vector<pcl::PointIndices>&
  getMatParts() const
  {
    return mat_parts_;
  }

private:
  TriangleMesh::ConstPtr mesh_;
  MedialMesh::ConstPtr base_;
  MedialMesh::ConstPtr structured_;

  // The field: recomputed only when an input changes.
  MatGraph::Ptr graph_;
  bool tags_valid_ = false;
  StructureTags tags_;
  std::shared_ptr<AabbTree> surface_tree_;

  MatRegionGrowing grower_;
  MeshLabelTransfer transfer_;

  std::vector<int> face_labels_;
  std::vector<pcl::PointIndices> mat_parts_;
  std::vector<std::pair<std::string, double>> stage_seconds_;
};

} // namespace segmat
