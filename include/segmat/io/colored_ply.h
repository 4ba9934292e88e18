/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <segmat/geometry/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace segmat {
namespace io {

/** \brief An 8-bit red, green, blue colour. */
using Rgb = std::array<std::uint8_t, 3>;

/** \brief The display colour of a segment label.
 *
 * Label l >= 0 gets entry l mod 256 of PCL's Glasbey table (pcl::GlasbeyLUT: maximally distinct
 * colours, the ones PCL's own viewers use for labels); a negative label (unlabelled) gets mid grey
 * (128, 128, 128).
 */
Rgb
labelColor(int label);

/** \brief Writes a mesh as an ASCII PLY with one `uchar red, green, blue` per face, the colour of
 * that face's label (MeshLab, CloudCompare and Blender show face colours).
 *
 * Coordinates are written as doubles in shortest round-trip form, so the file is exact and the
 * same mesh and labels always give the same bytes. Whole or not at all.
 * \param[in] path the file to write
 * \param[in] mesh the mesh
 * \param[in] face_labels one label per face (labelColor gives the colour)
 * \throws segmat::Error naming \a path when the label count differs from the face count, the mesh
 *         has a non-finite vertex or a bad index, or the file cannot be written.
 */
void
saveColoredMeshPly(const std::string& path, const TriangleMesh& mesh,
                   const std::vector<int>& face_labels);

/** \brief Writes points as an ASCII PLY with one `uchar red, green, blue` per vertex, the colour of
 * that point's label. Same guarantees as saveColoredMeshPly.
 * \throws segmat::Error naming \a path when the label count differs from the point count or the
 *         file cannot be written.
 */
void
saveColoredCloudPly(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<int>& labels);

/** \brief Same, for a labelled PCL cloud: the colour of each point's `label` field. */
void
saveColoredCloudPly(const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud);

} // namespace io
} // namespace segmat
