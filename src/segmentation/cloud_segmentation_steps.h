/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/: the untyped steps of CloudSegmentation<PointT>::segment()
// (src/segmentation/cloud_segmentation_impl.hpp), implemented in cloud_segmentation.cpp.

#include <segmat/common/stage_timing.h>
#include <segmat/common/point_types.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/cloud_medial_mesh_estimation.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/medial/meso_skeleton_estimation.h>
#include <segmat/segmentation/label_transfer.h>
#include <segmat/segmentation/mat_region_growing.h>
#include <segmat/segmentation/structure_tags.h>

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace segmat {

namespace detail {

/** \brief The MAT graph of a meso-skeleton: segmat::MedialPointGraph with k neighbours.
 * \return false (PCL_ERROR) when it cannot be built */
bool
medialPointGraph(const pcl::PointCloud<MedialPoint>::ConstPtr& skeleton, int k, MatGraph::Ptr& graph);

/** \brief The medial mesh of the working cloud and its MAT graph and structure tags (as on
 * meshes). Appends "medial" and "graph" to \a stage_seconds.
 *
 * With \a retry_fragmented (normals estimated from the points), an initial MAT that falls apart
 * (more than 8 components) has \a working's normals oriented again with the mirror relation
 * (NormalOrientation::setMirrorRelationFlag, \a orientation_k neighbours); that cloud replaces
 * \a working when its initial MAT has at most 3/4 of the components. Only the kept initial MAT
 * is simplified: Q-MAT drops isolated spheres and keeps the other components, so the initial
 * MATs, counted without their isolated spheres, tell what the base MATs would.
 * \param[out] statistics the kept estimation's statistics
 * \return false when the estimation fails (it said why) or the base MAT gives no graph node */
bool
medialMeshGraph(pcl::PointCloud<pcl::PointNormal>::Ptr& working, bool retry_fragmented,
                int orientation_k, CloudMedialMeshEstimation& estimation, MedialMesh& base,
                MedialMesh& structured, MatGraph::Ptr& graph, StructureTags& tags,
                StageTimings& stage_seconds, MedialMeshEstimationStatistics& statistics);

/** \brief What CloudSegmentation does once the MAT graph exists (untyped core).
 * \param[in] graph the MAT graph (medial mesh or meso-skeleton)
 * \param[in] tags its structure tags (empty: every node bulky)
 * \param[in] working the working cloud with oriented normals the medial axis came from
 * \param[in] transfer_k neighbours of the working cloud's graph in the transfer
 * \param[in] visibility use the ball-union visibility when merging parts
 * \param[in,out] grower the grower, parameters set (its graph and visibility are set here)
 * \param[in,out] transfer the transfer, ω set (its inputs are set here)
 * \param[out] working_labels one label per working point, in growing order (compacted)
 * \param[out] label_parts for each label, the indices of its parts in \a parts
 * \param[out] parts the grower's parts (MAT-graph nodes)
 * \param[in,out] stage_seconds "grow_merge", "transfer" are appended
 * \return false (PCL_ERROR) when a stage fails
 */
bool
segmentWorkingCloud(const MatGraph::Ptr& graph, const StructureTags& tags,
                    const pcl::PointCloud<pcl::PointNormal>& working, int transfer_k,
                    bool visibility, MatRegionGrowing& grower, CloudLabelTransfer& transfer,
                    std::vector<int>& working_labels,
                    std::vector<std::vector<int>>& label_parts,
                    std::vector<pcl::PointIndices>& parts,
                    StageTimings& stage_seconds);

/** \brief A cloud's normalised frame: p ↦ (p − centre) × scale (scale a power of two). */
struct CloudFrame
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0;
  pcl::Indices indices; ///< the input index of each point of the copy, in the copy's order
};

/** \brief Moves the points of \a cloud into their normalised frame (centred on the bounding
 * box of the finite points, scaled by a power of two to a diagonal in [1/√2, √2); normals
 * unchanged) and into position order (detail::positionOrder), so that neither where the cloud
 * lies, nor its size, nor the order of its points changes what follows. A cloud scaled by 2^k
 * lands on the very same numbers.
 * \param[in,out] cloud the copy of the input's points \a indices (point c is input indices[c])
 * \return the frame, with the input index of each point of the reordered copy */
CloudFrame
moveToNormalizedFrame(pcl::PointCloud<pcl::PointNormal>& cloud, const pcl::Indices& indices);

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

} // namespace segmat
