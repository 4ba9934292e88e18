/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/point_types.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/meso_skeleton_estimation.h>
#include <segmat/segmentation/label_transfer.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/mat_region_growing.h>
#include <segmat/segmentation/mat_segmentation_parameters.h>
#include <segmat/segmentation/structure_tags.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

/** \brief The medial axis CloudSegmentation builds for a cloud. */
enum class CloudMedialAxis
{
  /// Voronoi medial mesh of the working points, inside test by the cloud winding number,
  /// simplified by Q-MAT to a base and a structured MAT (segmat::CloudMedialMeshEstimation):
  /// the mesh path's representation, slabs and cones included
  MedialMesh,
  /// shrinking-ball medial points linked by k-NN (segmat::MesoSkeletonEstimation,
  /// segmat::MedialPointGraph): no faces, so the grower drops C_mp and no node is thin
  MesoSkeleton
};

namespace detail {

/** \brief The MAT graph of a meso-skeleton: segmat::MedialPointGraph with k neighbours.
 * \return false (PCL_ERROR) when it cannot be built */
bool
medialPointGraph(const pcl::PointCloud<MedialPoint>::ConstPtr& skeleton, int k, MatGraph::Ptr& graph);

/** \brief The medial mesh of the working cloud and its MAT graph and structure tags (as on
 * meshes). Appends "medial" and "graph" to \a stage_seconds.
 * \return false when the estimation fails (it said why) or the base MAT gives no graph node */
bool
medialMeshGraph(const pcl::PointCloud<pcl::PointNormal>::ConstPtr& working,
                CloudMedialMeshEstimation& estimation, MedialMesh& base, MedialMesh& structured,
                MatGraph::Ptr& graph, StructureTags& tags,
                std::vector<std::pair<std::string, double>>& stage_seconds);

/** \brief When the base MAT computed from estimated normals falls apart (more than 8
 * components), orient \a working's normals again with the mirror relation
 * (NormalOrientation::setMirrorRelationFlag) and keep that medial mesh when it has at most 3/4
 * of the components. \a working, the medial meshes, \a graph and \a tags are replaced when the
 * retry is kept; its seconds are added to "medial" and "graph" either way.
 * \return true when the retry was kept */
bool
retryFragmentedWithMirrorNormals(pcl::PointCloud<pcl::PointNormal>::Ptr& working, int orientation_k,
                                 CloudMedialMeshEstimation& estimation, MedialMesh& base,
                                 MedialMesh& structured, MatGraph::Ptr& graph, StructureTags& tags,
                                 std::vector<std::pair<std::string, double>>& stage_seconds);

/** \brief What CloudSegmentation does once the MAT graph exists (untyped core).
 * \param[in] graph the MAT graph (medial mesh or meso-skeleton)
 * \param[in] tags its structure tags (empty: every node bulky)
 * \param[in] working the working cloud with oriented normals the medial axis came from
 * \param[in] transfer_k neighbours of the working cloud's graph in the transfer
 * \param[in] visibility use the ball-union visibility when merging parts
 * \param[in,out] grower the grower, parameters set (its graph and visibility are set here)
 * \param[in,out] transfer the transfer, ω set (its inputs are set here)
 * \param[out] working_labels one label per working point, in growing order (compacted)
 * \param[out] label_parts for each label, the index of its part in \a parts
 * \param[out] parts the grower's parts (MAT-graph nodes)
 * \param[in,out] stage_seconds "grow_merge", "transfer" are appended
 * \return false (PCL_ERROR) when a stage fails
 */
bool
segmentWorkingCloud(const MatGraph::Ptr& graph, const StructureTags& tags,
                    const pcl::PointCloud<pcl::PointNormal>& working, int transfer_k,
                    bool visibility, MatRegionGrowing& grower, CloudLabelTransfer& transfer,
                    std::vector<int>& working_labels, std::vector<int>& label_parts,
                    std::vector<pcl::PointIndices>& parts,
                    std::vector<std::pair<std::string, double>>& stage_seconds);

/** \brief A cloud's normalised frame: p ↦ (p − centre) × scale (scale a power of two). */
struct CloudFrame
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0;
};

/** \brief Moves the points of \a cloud into their normalised frame (centred on the bounding
 * box of the finite points, scaled by a power of two to a diagonal in [1/√2, √2); normals
 * unchanged). A cloud scaled by 2^k lands on the very same numbers.
 * \return the frame */
CloudFrame
moveToNormalizedFrame(pcl::PointCloud<pcl::PointNormal>& cloud);

/** \brief Maps what a segmentation in \a frame computed back to the input's frame: medial
 * meshes, the meso-skeleton (its surface and contact indices from the copy's points to the
 * input's through \a indices) and the noise and spacing estimates. */
void
moveFromNormalizedFrame(const CloudFrame& frame, const pcl::Indices& indices, MedialMesh& base,
                        MedialMesh& structured, pcl::PointCloud<MedialPoint>& skeleton,
                        MesoSkeletonStatistics& stats);

/** \brief Input labels from working labels, renumbered by descending point count (ties: the
 * lower label first); parts[l] lists the input points of label l, ascending.
 * \param[in] input_to_working per input point, its working point (-1: no label)
 * \param[in] working_labels per working point, its label
 * \param[out] labels per input point (-1 where input_to_working is -1)
 * \param[out] parts per final label, its input points
 * \param[out] rank per working label, its final label
 */
void
labelInputPoints(const std::vector<int>& input_to_working, const std::vector<int>& working_labels,
                 std::vector<int>& labels, std::vector<pcl::PointIndices>& parts,
                 std::vector<int>& rank);

} // namespace detail

/** \brief End-to-end part segmentation of a point cloud with SEG-MAT (Lin et al., "SEG-MAT: 3D
 * Shape Segmentation Using Medial Axis Transform", IEEE TVCG 2022, §6: point clouds).
 *
 * Stages, each timed (getStageSeconds()):
 *  1. "preprocessing": finite points, resampled to the working size (~20k), normals (the
 *     cloud's own, or PCA + MST orientation) — segmat::CloudPreprocessing;
 *  2. "medial": shrinking balls, filters, contraction, reduction to ~2000 medial points —
 *     segmat::MesoSkeletonEstimation;
 *  3. "graph": the MAT graph of the medial points — segmat::MedialPointGraph;
 *  4. "grow_merge": the mesh path's grower, unchanged (segmat::MatRegionGrowing: growing,
 *     swallowing, tiny patches); with point nodes its cost is C_r + α·C_θ (no medial
 *     primitives: C_mp drops out). No structured MAT exists for a cloud, so every node is bulky
 *     (tag 0). Then SEG-MAT's three merging rounds with the grower's own pieces, but with
 *     patches adjacent when a graph edge joins them (the grower asks for a shared sphere, which
 *     point nodes never have; see src/segmentation/cloud_segmentation.cpp). Merging tests
 *     visibility against the union of the medial balls (segmat::BallUnionVisibility;
 *     setVisibilityFlag);
 *  5. "transfer": α-expansion on the working cloud's k-NN graph (segmat::CloudLabelTransfer,
 *     data term = distance to each part's balls, crease-aware smoothness from the oriented
 *     normals; two cycles, as the reference); every input point then takes the label of the
 *     working point standing for it (its voxel's representative): "labels".
 * A noisy cloud needs no parameter: the preprocessing estimates the noise and the point
 * spacing, smooths the points when the noise is a noticeable share of the spacing
 * (getEstimatedNoise(), getDenoisingPasses()), and the rest of the pipeline runs as on a clean
 * cloud, once (docs/noise.md).
 * Parts are numbered by descending point count. A cloud that encloses no volume (a flat patch,
 * a handful of points) is one part, with a warning.
 *
 * \code
 * pcl::PointCloud<pcl::PointNormal>::Ptr cloud = ...;   // or PointXYZ: normals are estimated
 * segmat::CloudSegmentation<pcl::PointNormal> seg;
 * seg.setInputCloud(cloud);
 * std::vector<pcl::PointIndices> parts;
 * if (seg.segment(parts)) {
 *   const std::vector<int>& labels = seg.getLabels();  // one per input point
 *   pcl::PointCloud<pcl::PointXYZL> labelled;
 *   seg.getLabeledCloud(labelled);
 * }
 * \endcode
 *
 * Stages 1–3 (the field) depend only on the input, the working size, the normals flag, the
 * medial axis, its estimation's settings and, for the meso-skeleton, k: they are computed once
 * and reused when segment() runs again with other grower or transfer parameters (δ0, η, α, λ,
 * ω, the level of detail, visibility, the bend limit), as MeshSegmentation reuses its medial
 * meshes. A reused stage reports 0 seconds. The input is taken as unchanged while it is the
 * same object, of the same size, with the same indices.
 *
 * The cloud is segmented in a normalised frame: centred on its bounding box and scaled by a power
 * of two to a diagonal near 1 (docs/robustness.md); what the getters return is in the input's
 * frame. A cloud scaled by 2^k gets the same labels.
 *
 * PointT: any PCL type with xyz (instantiated for pcl::PointXYZ, pcl::PointNormal,
 * pcl::PointXYZRGBNormal). setIndices() restricts the segmentation to a subset; the other
 * points get label -1.
 */
template <typename PointT>
class CloudSegmentation : public pcl::PCLBase<PointT>,
                          public MatSegmentationParameters<CloudLabelTransfer>
{
public:
  using Ptr = std::shared_ptr<CloudSegmentation<PointT>>;
  using ConstPtr = std::shared_ptr<const CloudSegmentation<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;

  /** \brief Paper defaults: δ0 = 0.015, η = 0.002, α = 0.05, λ = 1.5, ω = 0.3; working size
   * 20000, k = 10, input normals used, visibility on.
   */
  CloudSegmentation();


  /** \brief Points kept for the medial step and the graph cut (> 0, default 20000). */
  void
  setWorkingSize(std::size_t size)
  {
    skeleton_estimation_.setWorkingSize(size);
    field_valid_ = false;
  }

  /** \brief Points kept for the medial step and the graph cut. */
  std::size_t
  getWorkingSize() const
  {
    return skeleton_estimation_.getParameters().working_size;
  }

  /** \brief Neighbours of the k-NN graphs (medial points and the transfer's points; > 0,
   * default 10).
   */
  void
  setKSearch(int k);

  /** \brief Neighbours of the k-NN graphs. */
  int
  getKSearch() const
  {
    return k_;
  }

  /** \brief Use the cloud's normals when PointT has them (default true); false estimates them.
   */
  void
  setUseInputNormalsFlag(bool flag)
  {
    skeleton_estimation_.setUseInputNormalsFlag(flag);
    field_valid_ = false;
  }

  /** \brief Whether the cloud's normals are used when PointT has them. */
  bool
  getUseInputNormalsFlag() const
  {
    return skeleton_estimation_.getParameters().use_input_normals;
  }

  /** \brief The noise the last segment() estimated on the cloud: the Gaussian σ of the working
   * points' offsets from their local surface, in the input's units (0 when the cloud's own
   * normals were used: such a cloud is taken as it is). */
  double
  getEstimatedNoise() const
  {
    return stats_.noise_sigma;
  }

  /** \brief Median nearest-neighbour distance of the working points of the last segment(), in
   * the input's units (0 when the cloud's own normals were used). */
  double
  getEstimatedSpacing() const
  {
    return stats_.spacing;
  }

  /** \brief Smoothing passes the last segment() applied to the working points: 0 for a cloud
   * found clean (or one whose normals were used). */
  int
  getDenoisingPasses() const
  {
    return stats_.smoothing_passes;
  }

  /** \brief Test visibility inside the medial balls before merging parts (default true). */
  void
  setVisibilityFlag(bool flag)
  {
    visibility_ = flag;
  }

  /** \brief Whether merging tests visibility. */
  bool
  getVisibilityFlag() const
  {
    return visibility_;
  }

  /** \brief Threads of the parallel steps (0: OpenMP's choice; results do not depend on it). */
  void
  setNumberOfThreads(unsigned int threads)
  {
    skeleton_estimation_.setNumberOfThreads(threads);
    mesh_estimation_.getMedialMeshEstimation().setNumberOfThreads(threads);
    transfer_.setNumberOfThreads(threads);
  }

  /** \brief The medial axis to build (default CloudMedialAxis::MedialMesh). */
  void
  setMedialAxis(CloudMedialAxis axis)
  {
    medial_axis_ = axis;
    field_valid_ = false;
  }

  /** \brief The medial axis built. */
  CloudMedialAxis
  getMedialAxis() const
  {
    return medial_axis_;
  }

  /** \brief The medial-mesh estimation (advanced: base/structured targets, sample limit, point
   * areas; see segmat::CloudMedialMeshEstimation). Used with CloudMedialAxis::MedialMesh. */
  CloudMedialMeshEstimation&
  getMedialMeshEstimation()
  {
    field_valid_ = false; // the caller may change it
    return mesh_estimation_;
  }

  /** \brief Every meso-skeleton parameter (advanced; see segmat::MesoSkeletonParameters). */
  void
  setMesoSkeletonParameters(const MesoSkeletonParameters& params)
  {
    skeleton_estimation_.setParameters(params);
    field_valid_ = false;
  }

  /** \brief The meso-skeleton parameters. */
  const MesoSkeletonParameters&
  getMesoSkeletonParameters() const
  {
    return skeleton_estimation_.getParameters();
  }

  /** \brief Segment the cloud (through the indices, when set).
   * \param[out] parts one entry per part, by descending size: the input points of the part,
   *             ascending. Empty on failure.
   * \return false (PCL_ERROR) when there is no input, no finite point, or a stage fails
   */
  bool
  segment(std::vector<pcl::PointIndices>& parts);

  /** \brief One label per input point from the last segment(): the part number, -1 for
   * non-finite points and points outside the indices.
   */
  const std::vector<int>&
  getLabels() const
  {
    return labels_;
  }

  /** \brief The input points with their labels (unlabelled: label 0xffffffff). */
  void
  getLabeledCloud(pcl::PointCloud<pcl::PointXYZL>& cloud) const;

  /** \brief The input points with their labels and a colour per label (pcl::GlasbeyLUT;
   * unlabelled points black, label 0xffffffff).
   */
  void
  getLabeledCloud(pcl::PointCloud<pcl::PointXYZRGBL>& cloud) const;

  /** \brief The meso-skeleton of the last segment(): medial points with radii and normals
   * (empty with CloudMedialAxis::MedialMesh). */
  pcl::PointCloud<MedialPoint>::ConstPtr
  getMesoSkeleton() const
  {
    return skeleton_;
  }

  /** \brief The base medial mesh of the last segment() (null with the meso-skeleton or before
   * any). A new object when segment() computed it again. */
  MedialMesh::ConstPtr
  getBaseMat() const
  {
    return base_;
  }

  /** \brief The structured medial mesh of the last segment() (null with the meso-skeleton or
   * before any). */
  MedialMesh::ConstPtr
  getStructuredMat() const
  {
    return structured_;
  }

  /** \brief The MAT graph of the last segment(), in the normalised frame the cloud was
   * segmented in (null when none was built). */
  MatGraph::ConstPtr
  getGraph() const
  {
    return graph_;
  }

  /** \brief Medial points of each part of the last segment(), in label order. */
  const std::vector<pcl::PointIndices>&
  getMatParts() const
  {
    return mat_parts_;
  }

  /** \brief Seconds per stage of the last segment(), in pipeline order: "preprocessing",
   * "medial", "graph", "grow_merge", "transfer", "labels".
   */
  const std::vector<std::pair<std::string, double>>&
  getStageSeconds() const
  {
    return stage_seconds_;
  }

  /** \brief Sizes and timings of the meso-skeleton step of the last segment(). */
  const MesoSkeletonStatistics&
  getMesoSkeletonStatistics() const
  {
    return stats_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

private:
  /** \brief Preprocessing, medial axis and graph of the input (the field); false when a stage
   * fails. */
  bool
  computeField();

  /** \brief Copies the input's xyz and the labels (and Glasbey colours for coloured types). */
  template <typename LabeledT>
  void
  fillLabeledCloud(pcl::PointCloud<LabeledT>& cloud) const;

  MesoSkeletonEstimation<PointT> skeleton_estimation_;
  CloudMedialMeshEstimation mesh_estimation_;
  CloudMedialAxis medial_axis_ = CloudMedialAxis::MedialMesh;
  int k_ = 10;
  bool visibility_ = true;
  MesoSkeletonStatistics stats_; ///< the last segment()'s preprocessing

  // The field: preprocessing, medial axis and graph, kept while only grower and transfer
  // parameters change (see segment()).
  bool field_valid_ = false;
  bool field_medial_ok_ = false;
  typename PointCloud::ConstPtr field_input_;
  std::size_t field_size_ = 0;
  pcl::Indices field_indices_;
  std::vector<std::pair<std::string, double>> field_seconds_;
  MedialMesh::ConstPtr base_, structured_;
  StructureTags tags_;
  pcl::PointCloud<pcl::PointNormal>::Ptr working_;
  std::vector<int> input_to_working_;

  pcl::PointCloud<MedialPoint>::Ptr skeleton_;
  MatGraph::Ptr graph_;
  std::vector<int> labels_;
  std::vector<pcl::PointIndices> mat_parts_;
  std::vector<std::pair<std::string, double>> stage_seconds_;
};

} // namespace segmat

#if defined(PCL_NO_PRECOMPILE) || defined(SEGMAT_NO_PRECOMPILE)
#include <segmat/segmentation/impl/cloud_segmentation.hpp>
#endif
