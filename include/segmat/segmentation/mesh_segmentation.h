/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/stage_timing.h>
#include <segmat/geometry/aabb_tree.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>
#include <segmat/segmentation/label_transfer.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/mat_region_growing.h>
#include <segmat/segmentation/mat_segmentation_parameters.h>
#include <segmat/segmentation/structure_tags.h>

#include <pcl/PointIndices.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

class MedialMeshEstimation;
struct MedialMeshEstimationStatistics;

/** \brief End-to-end part segmentation of a triangle mesh with SEG-MAT (Lin et al., "SEG-MAT:
 * 3D Shape Segmentation Using Medial Axis Transform", IEEE TVCG 2022).
 *
 * Stages, each timed (getStageSeconds()):
 *  -. "denoise": the mesh's noise is estimated; a noisy mesh (scanner noise on its vertices)
 *     is smoothed until its triangles turn as little as a clean triangulation's, and every later
 *     stage works on that copy. The faces, and so the labels, are the
 *     input's. A clean mesh is used as it is. No parameter: see docs/noise.md.
 *  0. "mat": the base and structured medial meshes from the mesh (MedialMeshEstimation: Voronoi
 *     MAT + Q-MAT, §3), only when none was given (setBaseMat / setStructuredMat);
 *  1. "graph": the base-MAT graph (MatGraph::fromMedialMesh, §4.1);
 *  2. "tags": structural tags from the structured MAT (computeStructureTags, §4.2);
 *  3. "surface_tree": an AabbTree over the mesh, for the merging's visibility test;
 *  4. "grow_merge": region growing, swallowing, tiny-patch absorption and merging
 *     (MatRegionGrowing, §4.3–4.4);
 *  5. "transfer": the parts carried to the faces by α-expansion (MeshLabelTransfer, §5).
 * Stages 0–3 (and the transfer's face-graph weights) depend only on the inputs: they are computed
 * once and reused when only δ0, η, α, λ or ω change and segment() runs again (CGAL's split of
 * sdf_values / segmentation_from_sdf_values). A reused stage reports 0 seconds.
 *
 * The medial meshes are computed from the mesh unless both are given (e.g. the authors' Q-MAT
 * files, io::loadMa); the computed ones are kept until the mesh or a MAT target changes and can
 * be read back with getBaseMat() / getStructuredMat() (e.g. to io::saveMa them).
 *
 * \code
 * segmat::MeshSegmentation seg;
 * seg.setInputMesh(mesh);           // TriangleMesh::ConstPtr (io::loadMesh)
 * std::vector<int> face_labels;
 * if (seg.segment(face_labels))     // computes the medial meshes, then the parts
 *   segmat::io::saveSeg("out.seg", face_labels);
 * // Or with given medial meshes (both, before segment()):
 * seg.setBaseMat(base);             // MedialMesh::ConstPtr (io::loadMa)
 * seg.setStructuredMat(structured); // MedialMesh::ConstPtr
 * \endcode
 */
class MeshSegmentation : public MatSegmentationParameters<MeshLabelTransfer>
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
   * on. Give both medial meshes or neither (null: computed by segment()); setting one after a
   * segment() that computed them drops the computed pair.
   */
  void
  setBaseMat(const MedialMesh::ConstPtr& base);

  /** \brief The base medial mesh: the given one, or the one the last segment() computed (null
   * before).
   */
  MedialMesh::ConstPtr
  getBaseMat() const
  {
    return base_;
  }

  /** \brief The structured (coarse, e.g. 15–30-sphere Q-MAT) medial mesh that tells thin parts
   * from bulky ones. An empty one is accepted (every node is then bulky, like the reference).
   * Give both medial meshes or neither (see setBaseMat()).
   */
  void
  setStructuredMat(const MedialMesh::ConstPtr& structured);

  /** \brief The structured medial mesh: the given one, or the one the last segment() computed
   * (null before).
   */
  MedialMesh::ConstPtr
  getStructuredMat() const
  {
    return structured_;
  }

  /** \brief Spheres of the computed base MAT (MedialMeshEstimation::setBaseTarget; default
   * 2000). Unused when the medial meshes are given.
   */
  void
  setBaseMatTarget(int spheres);

  /** \brief Spheres of the computed base MAT. */
  int
  getBaseMatTarget() const;

  /** \brief Spheres of the computed structured MAT (MedialMeshEstimation::setStructuredTarget;
   * default −1: max(15, ⌊0.001 × initial spheres⌋)). Unused when the medial meshes are given.
   */
  void
  setStructuredMatTarget(int spheres);

  /** \brief Spheres of the computed structured MAT (−1: automatic). */
  int
  getStructuredMatTarget() const;

  /** \brief Threads of the medial-mesh computation (MedialMeshEstimation::setNumberOfThreads)
   * and of the transfer's data term (0 = OpenMP's default). The output does not depend on it.
   */
  void
  setNumberOfThreads(unsigned threads);

  /** \brief Threads of the medial-mesh computation. */
  unsigned
  getNumberOfThreads() const;

  /** \brief Which deterministic sample jitter the computed medial meshes use
   * (VoronoiMat::setJitterSeed; default 0). Every seed is an equally valid draw; the parts of
   * some shapes depend on it (docs/robustness.md, "Sub-micro displacements"), and segmenting
   * under a few seeds measures how stable they are. Changing it drops the computed medial
   * meshes.
   */
  void
  setJitterSeed(std::uint32_t seed);

  /** \brief Which deterministic sample jitter the computed medial meshes use. */
  std::uint32_t
  getJitterSeed() const;

  /** \brief Turn the normalised frame onto the mesh's principal axes (default: true).
   *
   * Every sampling, jitter and Delaunay step then sees a rotated input as it sees the original,
   * and a rotation changes no label beyond what rounding does (on psb-dev: one shape, by 0.004
   * of Rand distance; shapes without unique principal axes, e.g. with equal principal variances,
   * are the exception). Off, the mesh is segmented in its own orientation: the Voronoi MAT's
   * axis-aligned steps then follow the input's axes, and a rotation moves part boundaries like
   * another jitter draw does (docs/robustness.md). Changing it drops the computed medial meshes.
   */
  void
  setPrincipalAxesFrame(bool enable);

  bool
  getPrincipalAxesFrame() const
  {
    return principal_axes_;
  }

  /** \brief Whether the current medial meshes were computed by segment() (not given). */
  bool
  hasComputedMats() const
  {
    return mats_computed_;
  }

  /** \brief Sizes and seconds of the medial stage that computed the current medial meshes
   * (MedialMeshEstimation::getStatistics()): among them the surface samples
   * (`voronoi.num_samples`) and the initial spheres, which follow the shape and not the noise
   * when denoising works (docs/noise.md). All zero while hasComputedMats() is false.
   */
  const MedialMeshEstimationStatistics&
  getMatStatistics() const;

  /** \brief Segment the mesh.
   * \param[out] face_labels one label per face, dense 0..k−1, numbered by descending part size
   *             (face count; ties: the part grown first comes first). Empty on failure.
   * \return false (PCL_ERROR) when the mesh has no faces, only one medial mesh is given, the
   *         base one is empty, the medial meshes cannot be computed (e.g. a mesh that encloses no
   *         volume), or a stage fails.
   *
   * The mesh is segmented in a normalised frame: centred on its bounding box, scaled by a power
   * of two to a diagonal near 1 (docs/robustness.md), turned onto its principal axes (unless
   * setPrincipalAxesFrame(false)) and put into position order. Translating, scaling or rotating
   * the input therefore changes nothing beyond the input's own rounding (shapes without unique
   * principal axes aside); a power-of-two scale and re-ordering change no label. Labels, parts and the medial meshes
   * returned are in the input's frame and order; getGraph() is in the normalised frame.
   */
  bool
  segment(std::vector<int>& face_labels);

  /** \brief The noise the last segment() estimated on the input's surface: the Gaussian σ of
   * its vertices' offsets from the surface their neighbours describe, in the mesh's units. */
  double
  getEstimatedNoise() const;

  /** \brief The noise left on the denoised surface after the last segment() (the same
   * estimate, on the smoothed copy), in the mesh's units: 0 for a mesh found clean. Radius
   * differences of this size do not count in the growing cost
   * (MatRegionGrowing::setRadiusTolerance). */
  double
  getRemainingNoise() const;

  /** \brief Smoothing passes the last segment() applied: 0 for a mesh found clean. */
  int
  getDenoisingPasses() const
  {
    return denoising_passes_;
  }

  /** \brief Faces of each part of the last segment(), in label order (indices ascending). */
  void
  getParts(std::vector<pcl::PointIndices>& parts) const;

  /** \brief Seconds spent in each stage by the last segment(), in pipeline order ("denoise",
   * "mat", "graph", "tags", "surface_tree", "grow_merge", "transfer"); a stage whose result was reused reports 0.
   */
  const StageTimings&
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
  /** \brief Makes working_mesh_ (the input, or its denoised copy) when it is missing. */
  void
  prepareWorkingMesh();

  /** \brief Forgets base_ and structured_ (and what depends on them) if segment() computed them. */
  void
  dropComputedMats();

  /** \brief segment() on the members as they are (mesh_ already in the normalised frame). */
  bool
  segmentInFrame(std::vector<int>& face_labels);

  struct FrameCache; // the normalised copies (src/segmentation/mesh_segmentation_frame.cpp)
  std::shared_ptr<FrameCache> frame_;

  TriangleMesh::ConstPtr mesh_;
  // The mesh every stage works on: the input (in its frame), or its denoised copy when noisy;
  // noise_sigma_ is in that frame's units.
  TriangleMesh::ConstPtr working_mesh_;
  double noise_sigma_ = 0.0;
  double remaining_sigma_ = 0.0; // σ̂ of the denoised copy; 0 when the input is used as it is
  int denoising_passes_ = 0;
  MedialMesh::ConstPtr base_;
  MedialMesh::ConstPtr structured_;
  // Computes base_ and structured_ when neither was given; mats_computed_ says they are its.
  std::shared_ptr<MedialMeshEstimation> estimation_;
  bool mats_computed_ = false;
  bool principal_axes_ = true;

  // The field: recomputed only when an input changes.
  MatGraph::Ptr graph_;
  bool tags_valid_ = false;
  StructureTags tags_;
  std::shared_ptr<AabbTree> surface_tree_;


  std::vector<int> face_labels_;
  std::vector<pcl::PointIndices> mat_parts_;
  StageTimings stage_seconds_;
};

} // namespace segmat
