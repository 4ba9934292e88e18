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

/** \brief 1 − Rand index of two labelings of the same points (the share of point pairs that
 * one puts together and the other apart); entries < 0 in either are skipped. O(n + L_a·L_b).
 * 0 for identical partitions, whatever the label numbers. */
double
randDistance(const std::vector<int>& a, const std::vector<int>& b);

/** \brief The consensus of several labelings of the same points: the one with the least summed
 * randDistance() to the others (their medoid, as in cluster ensembles; Strehl & Ghosh, "Cluster
 * ensembles", JMLR 2002). Ties go to the lower index; -1 when \a labelings is empty. */
int
consensusLabeling(const std::vector<std::vector<int>>& labelings);

/** \brief Merges, in \a labels, the adjacent parts that the runs put together: while some pair
 * of parts (P, Q) joined by an edge has a mean co-association above \a threshold — the share of
 * the point pairs p ∈ P, q ∈ Q that a labeling gives one label, averaged over \a labelings —
 * the pair with the highest is merged (average linkage, so a chain of weak links does not join
 * parts, unlike single linkage). A noise-made cut falls in a different place in each run, so
 * most runs join its two sides; a real boundary is cut by all. Ties: the lower pair first.
 * \param[in] labelings the runs' labelings of the same points (labels >= 0; < 0 skipped)
 * \param[in] edges point pairs that are neighbours (the adjacency of parts)
 * \param[in,out] labels the labeling to merge (one of the runs'); a merged part takes the lower
 * label
 * \param[in] keep_reproduced_cuts when true, a pair that at least a third of \a labelings cut
 * alike (each side at least 80 % one label of the run, the two labels different) is never
 * merged, however often the other runs join it: a real boundary that the noise lets only some
 * runs find (the seat and back of a noisy chair, PSB 101) is reproduced where it is found,
 * while a noise cut falls somewhere else in each run
 * \return per label of the input \a labels, the label it ended in */
std::vector<int>
mergeByConsensus(const std::vector<std::vector<int>>& labelings,
                 const std::vector<std::pair<int, int>>& edges, double threshold,
                 std::vector<int>& labels, bool keep_reproduced_cuts = false);

/** \brief Moves each point of \a labels to the part the runs put it with most often, among its
 * own part and the parts of its neighbours: the part P with the highest
 * Σ_r |{q ∈ P : run r labels q as it labels the point}| / |P| — the point's mean
 * co-association with P over \a labelings (ties keep the point's part). The kept run's
 * boundaries are where its own thinning of the samples put them; the vote moves them to where
 * the runs agree. Parts are taken as they were before any point moved (one pass, independent of
 * the point order); a part is never created, only emptied.
 *
 * Only a neighbour's part is a candidate because the score favours a small part that other runs
 * hold inside a larger one: every point of that larger part then scores ~1 for the small part.
 * Without the restriction, points all over a noisy box (a box with a smaller box on top) would
 * join a small corner part that the other runs hold inside the box's part.
 * \param[in] labelings the runs' labelings of the same points (labels >= 0; < 0 skipped)
 * \param[in] edges point pairs that are neighbours (the k-NN graph of the transfer)
 * \param[in,out] labels the labeling to refine (one of the runs', after mergeByConsensus())
 * \return the number of points moved */
int
voteByConsensus(const std::vector<std::vector<int>>& labelings,
                const std::vector<std::pair<int, int>>& edges, std::vector<int>& labels);

/** \brief One segmentation of the working cloud through its medial mesh. */
struct MedialMeshRun
{
  pcl::PointCloud<pcl::PointNormal>::Ptr working; ///< with the normals the run used
  MedialMesh base, structured;
  MatGraph::Ptr graph;
  StructureTags tags;
  std::vector<int> working_labels, label_parts; ///< as segmentWorkingCloud()
  std::vector<pcl::PointIndices> parts;         ///< as segmentWorkingCloud()
};

/** \brief How segmentWithMedialMesh() ended. */
enum class MedialMeshRunStatus
{
  Segmented,     ///< \a result holds the chosen run
  NoMedialAxis,  ///< the first run found no medial axis (one part, for the caller)
  Failed         ///< a later stage failed (PCL_ERROR said which)
};

/** \brief The medial-mesh branch of CloudSegmentation::segment(): medial mesh, graph and tags
 * (with the mirror-normal retry when \a retry), growing and transfer — \a runs times with the
 * Voronoi samples thinned in different orders (run r: sample order seed = \a estimation's + r,
 * so run 0 is the plain pipeline). Each run's working labels are merged by mergeByConsensus()
 * over all the runs (above \a merge_threshold; > 1: no merging), the consensusLabeling() of
 * the merged labelings is kept (when \a keep_reproduced_cuts, merged again from its own labels
 * keeping the cuts a third of the runs reproduce), and its points are moved by
 * voteByConsensus().
 * Each run works on its own copies of \a working and of the three stages; up to \a threads
 * runs go side by side (0: OpenMP's choice; the result does not depend on it). Stage seconds are summed over the
 * runs. Run 0 decides the outcome; a later run that fails is left out. \a estimation ends up
 * as the kept run's (its statistics and splat surface; its own sample order seed).
 * \param[out] chosen the run kept */
MedialMeshRunStatus
segmentWithMedialMesh(const pcl::PointCloud<pcl::PointNormal>& working, int runs,
                      double merge_threshold, bool keep_reproduced_cuts, bool retry,
                      int orientation_k, int transfer_k, bool visibility, unsigned int threads,
                      CloudMedialMeshEstimation& estimation, const MatRegionGrowing& grower,
                      const CloudLabelTransfer& transfer, MedialMeshRun& result, int& chosen,
                      std::vector<std::pair<std::string, double>>& stage_seconds);

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
 * With the medial mesh (the default axis, CloudMedialAxis::MedialMesh), a cloud that the
 * preprocessing finds noisy goes through stages 2–5 several times with differently thinned
 * Voronoi samples, and the consensus run is kept (setConsensusRuns); its grower also merges
 * patches that share a long boundary without the visibility test
 * (setNoisyBoundaryMergeFactor).
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
  }

  /** \brief Whether the cloud's normals are used when PointT has them. */
  bool
  getUseInputNormalsFlag() const
  {
    return skeleton_estimation_.getParameters().use_input_normals;
  }

  /** \brief With estimated normals and the medial mesh: when the base MAT falls apart into
   * more than 8 components (a solid's medial axis is connected; no clean psb-dev cloud has more
   * than 8), orient
   * the normals again with the mirror relation (NormalOrientation::setMirrorRelationFlag) and
   * keep that medial mesh if it has at most 3/4 of the components (default true). Noise on a
   * plate thinner than the orientation neighbourhood flips whole patches of normals; the inside
   * test then cuts the plate's medial sheet to pieces. */
  void
  setFragmentedMatRetryFlag(bool flag)
  {
    fragmented_mat_retry_ = flag;
  }

  /** \brief Whether a fragmented base MAT is retried with mirror-related normals. */
  bool
  getFragmentedMatRetryFlag() const
  {
    return fragmented_mat_retry_;
  }

  /** \brief Segmentations of a noisy cloud from which one consensus is kept (>= 1, default 9;
   * 1: a single run). Noise makes the medial mesh foam, and which foam sheets survive Q-MAT
   * depends on which samples the Voronoi step keeps: single runs of one noisy cloud differ by
   * tenths of RI. With the medial mesh, each run thins the samples in another order
   * (CloudMedialMeshEstimation::setSampleOrderSeed) and the run whose working labels agree most
   * with the others' (detail::consensusLabeling: the medoid under the Rand distance) is kept;
   * a run that fragments the cloud by chance disagrees with all the others. Its boundaries then
   * move to where the runs agree (detail::voteByConsensus). A cloud counts as
   * noisy when the preprocessing smoothed it (estimated normals, noise above 10 % of the point
   * spacing); clean clouds get one run unless setConsensusForEveryCloudFlag(). Costs one
   * medial step, growing and transfer per run. */
  void
  setConsensusRuns(int runs);

  /** \brief Segmentations of a noisy cloud from which one consensus is kept. */
  int
  getConsensusRuns() const
  {
    return consensus_runs_;
  }

  /** \brief Co-association above which two adjacent parts of a consensus run merge, before the
   * medoid of the runs is chosen (default 0.5; > 1: no merging). Where noise cut a part, the cut
   * falls elsewhere in each run, so the other runs join most of what one run split there; a
   * real boundary is cut by all (detail::mergeByConsensus). A run's own vote for its cut counts
   * too: with nine runs, 0.5 asks that five of the other eight join the pair, where 0.4 let four
   * (a chair's seat and back that four runs grow into one part). */
  void
  setConsensusMergeThreshold(double threshold);

  /** \brief Co-association above which two adjacent parts of a consensus run merge. */
  double
  getConsensusMergeThreshold() const
  {
    return consensus_merge_threshold_;
  }

  /** \brief When the kept consensus run is merged, keep apart every pair of its parts that at
   * least a third of the runs cut alike (default true; detail::mergeByConsensus). Noise hides
   * some real boundaries from most runs: a noisy chair's seat and back that most of nine runs
   * grow into one part are then joined by the merge, though the runs that cut them cut them
   * in the same place — a noise cut falls somewhere else in each run. The medoid is still
   * chosen among the plainly merged runs (with such cuts kept there, the majority that misses
   * them would tend to look closer to each other). */
  void
  setConsensusKeepReproducedCutsFlag(bool flag)
  {
    consensus_keep_reproduced_cuts_ = flag;
  }

  /** \brief Whether the kept consensus run keeps the cuts a third of the runs reproduce. */
  bool
  getConsensusKeepReproducedCutsFlag() const
  {
    return consensus_keep_reproduced_cuts_;
  }

  /** \brief κ of MatRegionGrowing::setSharedBoundaryMergeFactor() for clouds treated as noisy
   * (default 0.5; 0: off). Patches of a noisy cloud's medial mesh
   * that share a long boundary merge without the visibility test: noise cuts plates and rims
   * along lines of spheres, and the pieces of a cut sheet need not see each other through the
   * noisy ball union (a cup's wall cut into strips that share 7–15 spheres each, ~√n of the
   * smaller strip; κ = 2 leaves such a wall in many parts). Clean clouds (and meshes) merge as
   * SEG-MAT does. */
  void
  setNoisyBoundaryMergeFactor(double factor);

  /** \brief κ of the long-boundary merge for clouds treated as noisy. */
  double
  getNoisyBoundaryMergeFactor() const
  {
    return noisy_boundary_factor_;
  }

  /** \brief For clouds treated as noisy, keep every sphere centre that Q-MAT merges inside the
   * splat surface (MedialMeshEstimation::setKeepCentresInside; default true; clean clouds never
   * test, for speed). A centre outside the shape is wrong by construction, and the mesh path
   * never allows one. On noisy thin plates it decides whether a plate becomes its own part: a
   * chair's back that would join the seat, glasses whose two lenses would join. Costs ~16 % of a
   * noisy cloud's time. */
  void
  setNoisyCentresInsideFlag(bool flag)
  {
    noisy_centres_inside_ = flag;
  }

  /** \brief Whether Q-MAT keeps the merged centres of a noisy cloud inside its surface. */
  bool
  getNoisyCentresInsideFlag() const
  {
    return noisy_centres_inside_;
  }

  /** \brief Apply setConsensusRuns() to every cloud, not only to noisy ones (default false;
   * e.g. for noisy scans that come with their own normals, which are not smoothed or measured).
   */
  void
  setConsensusForEveryCloudFlag(bool flag)
  {
    consensus_every_cloud_ = flag;
  }

  /** \brief Whether every cloud gets the consensus runs. */
  bool
  getConsensusForEveryCloudFlag() const
  {
    return consensus_every_cloud_;
  }

  /** \brief Runs the last segment() made: 1 for a clean cloud (and the meso-skeleton), the
   * consensus runs for a noisy one; 0 before any. */
  int
  getConsensusRunsMade() const
  {
    return runs_made_;
  }

  /** \brief The run whose segmentation the last segment() kept (0 with a single run); one run
   * with CloudMedialMeshEstimation::setSampleOrderSeed(seed + kept run) repeats it. */
  int
  getConsensusRunKept() const
  {
    return run_kept_;
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
    return mesh_estimation_;
  }

  /** \brief Every meso-skeleton parameter (advanced; see segmat::MesoSkeletonParameters). */
  void
  setMesoSkeletonParameters(const MesoSkeletonParameters& params)
  {
    skeleton_estimation_.setParameters(params);
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

  /** \brief The base medial mesh of the last segment() (empty with the meso-skeleton). */
  const MedialMesh&
  getBaseMat() const
  {
    return base_;
  }

  /** \brief The structured medial mesh of the last segment() (empty with the meso-skeleton). */
  const MedialMesh&
  getStructuredMat() const
  {
    return structured_;
  }

  /** \brief The MAT graph of the last segment() (null when none was built). */
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
    return skeleton_estimation_.getStatistics();
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

private:
  /** \brief Copies the input's xyz and the labels (and Glasbey colours for coloured types). */
  template <typename LabeledT>
  void
  fillLabeledCloud(pcl::PointCloud<LabeledT>& cloud) const;

  MesoSkeletonEstimation<PointT> skeleton_estimation_;
  CloudMedialMeshEstimation mesh_estimation_;
  CloudMedialAxis medial_axis_ = CloudMedialAxis::MedialMesh;
  int k_ = 10;
  bool visibility_ = true;
  bool fragmented_mat_retry_ = true;
  int consensus_runs_ = 9;
  double consensus_merge_threshold_ = 0.5;
  bool consensus_keep_reproduced_cuts_ = true;
  bool consensus_every_cloud_ = false;
  double noisy_boundary_factor_ = 0.5;
  bool noisy_centres_inside_ = true;
  int runs_made_ = 0;
  int run_kept_ = 0;

  MedialMesh base_, structured_;
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
