/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/stage_timing.h>
#include <segmat/common/point_types.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/meso_skeleton_estimation.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/label_transfer.h>
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


/** \brief End-to-end part segmentation of a point cloud with SEG-MAT (Lin et al., "SEG-MAT: 3D
 * Shape Segmentation Using Medial Axis Transform", IEEE TVCG 2022, §6: point clouds).
 *
 * Stages, each timed (getStageSeconds()):
 *  1. "preprocessing": finite points, resampled to the working size (~20k), normals (the
 *     cloud's own, or PCA + MST orientation). Without normals the noise and the spacing are
 *     estimated and a noisy cloud is smoothed first (getEstimatedNoise(), getDenoisingPasses();
 *     docs/noise.md): a noisy cloud needs no parameter — segmat::CloudPreprocessing;
 *  2. "medial": with CloudMedialAxis::MedialMesh (the default) the Voronoi medial mesh of the
 *     working points, simplified by Q-MAT to a base and a structured MAT, as on meshes
 *     (segmat::CloudMedialMeshEstimation; when estimated normals leave the base MAT in many
 *     pieces, the normals are oriented again with the mirror relation and the less fragmented
 *     axis is kept); with CloudMedialAxis::MesoSkeleton shrinking balls reduced to ~2000 medial
 *     points (segmat::MesoSkeletonEstimation);
 *  3. "graph": the MAT graph (MatGraph::fromMedialMesh and the structure tags, or
 *     segmat::MedialPointGraph);
 *  4. "grow_merge": the mesh path's grower (segmat::MatRegionGrowing: growing, swallowing,
 *     tiny patches, SEG-MAT's three merging rounds with the visibility test against the union
 *     of the medial balls, setVisibilityFlag). Medial points have no primitives, so on the
 *     meso-skeleton the cost is C_r + α·C_θ and every node is bulky;
 *  5. "transfer": α-expansion on the working cloud's k-NN graph (segmat::CloudLabelTransfer,
 *     data term = distance to each part's balls, crease-aware smoothness from the oriented
 *     normals; two cycles, as the reference); every input point then takes the label of the
 *     working point standing for it (its voxel's representative): "labels".
 * Parts are numbered by descending point count. A cloud that encloses no volume (a flat patch,
 * a handful of points) is one part, with a warning.
 *
 * \code
 * pcl::PointCloud<pcl::PointNormal>::Ptr cloud = ...;   // or PointXYZ: normals are estimated
 * segmat::CloudSegmentation<pcl::PointNormal> seg;
 * seg.setInputCloud(cloud);
 * std::vector<int> labels;                             // one per input point
 * if (seg.segment(labels)) {                            // or segment(parts): PointIndices
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
 * PointT: pcl::PointXYZ, pcl::PointNormal or pcl::PointXYZRGBNormal (the library is compiled
 * for these; copy other types into one of them). setIndices() restricts the segmentation to a subset; the other
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
   * A cloud found noisy has its normals estimated either way, from the smoothed points
   * (docs/noise.md, "Clouds with normals").
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
   * points' offsets from the PCA plane of their 8 nearest points, in the input's units, whether
   * or not the cloud came with normals. It reads low once the
   * noise nears the point spacing (about half the true σ at σ = 0.5 % of the diagonal on 20 k
   * points; docs/noise.md, "Limits"). */
  double
  getEstimatedNoise() const
  {
    return stats_.noise_sigma;
  }

  /** \brief Median nearest-neighbour distance of the working points of the last segment(), in
   * the input's units. */
  double
  getEstimatedSpacing() const
  {
    return stats_.spacing;
  }

  /** \brief The noise left on the smoothed working points after the last segment() (the same
   * estimate, again), in the input's units: 0 for a cloud found clean. Radius differences of
   * this size do not count in the growing cost (MatRegionGrowing::setRadiusTolerance). */
  double
  getRemainingNoise() const
  {
    return stats_.remaining_sigma;
  }

  /** \brief Smoothing passes the last segment() applied to the working points: 0 for a cloud
   * found clean, with or without normals. */
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

  /** \brief Segment the cloud, as MeshSegmentation::segment() does for meshes.
   * \param[out] labels one label per input point (getLabels()): the part number, numbered by
   *             descending part size; -1 for non-finite points and points outside the indices.
   *             Empty on failure.
   * \return false (PCL_ERROR) as segment(std::vector<pcl::PointIndices>&) */
  bool
  segment(std::vector<int>& labels);

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
  const StageTimings&
  getStageSeconds() const
  {
    return stage_seconds_;
  }

  /** \brief Sizes and seconds of the medial-mesh step of the last segment() that computed the
   * medial axis (MedialMeshEstimation::getStatistics()): among them the Voronoi samples
   * (`voronoi.num_samples`, the working points up to the sample limit) and the initial
   * spheres. All zero with CloudMedialAxis::MesoSkeleton.
   */
  const MedialMeshEstimationStatistics&
  getMatStatistics() const
  {
    return mat_statistics_;
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
  MedialMeshEstimationStatistics mat_statistics_; ///< the last medial-mesh estimation's
  double working_remaining_sigma_ = 0.0; ///< stats_.remaining_sigma in the normalised frame
  double working_touching_ = 0.0; ///< a smoothed cloud's input σ̂ in that frame (else 0)

  // The field: preprocessing, medial axis and graph, kept while only grower and transfer
  // parameters change (see segment()).
  bool field_valid_ = false;
  bool field_medial_ok_ = false;
  typename PointCloud::ConstPtr field_input_;
  std::size_t field_size_ = 0;
  pcl::Indices field_indices_;
  StageTimings field_seconds_;
  MedialMesh::ConstPtr base_, structured_;
  StructureTags tags_;
  pcl::PointCloud<pcl::PointNormal>::Ptr working_;
  std::vector<int> input_to_working_;

  pcl::PointCloud<MedialPoint>::Ptr skeleton_;
  MatGraph::Ptr graph_;
  std::vector<int> labels_;
  std::vector<pcl::PointIndices> mat_parts_;
  StageTimings stage_seconds_;
};

} // namespace segmat

