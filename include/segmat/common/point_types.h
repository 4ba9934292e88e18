/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// Pulls in PCL's point machinery (~2 s per translation unit): include it only where medial
// clouds are made, saved or searched, never from a widely included header.
#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace segmat {

/** \brief A medial point: the centre of a maximal inscribed ball, its radius and a normal.
 *
 * The point type of a cloud's meso-skeleton (SEG-MAT, Lin et al. 2022, §6) and of medial-mesh
 * vertices exported as clouds. Registered with PCL, so `pcl::PointCloud<segmat::MedialPoint>`
 * saves to PCD/PLY with named fields (`radius` shows up as a scalar field in CloudCompare).
 * Searching: copy the xyz into a `pcl::PointCloud<pcl::PointXYZ>` and use PCL's precompiled
 * kd-tree rather than instantiating FLANN for this type.
 */
struct EIGEN_ALIGN16 MedialPoint
{
  PCL_ADD_POINT4D;  // x, y, z
  PCL_ADD_NORMAL4D; // normal_x, normal_y, normal_z: sheet normal (zero when unknown)
  float radius;                ///< radius of the medial ball
  std::int32_t surface_index;  ///< input point the ball touches first (-1: none)
  std::int32_t contact_index;  ///< second touching input point (-1: none)
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace segmat

POINT_CLOUD_REGISTER_POINT_STRUCT(segmat::MedialPoint,
                                  (float, x, x)(float, y, y)(float, z, z)
                                  (float, normal_x, normal_x)(float, normal_y, normal_y)
                                  (float, normal_z, normal_z)(float, radius, radius)
                                  (std::int32_t, surface_index, surface_index)
                                  (std::int32_t, contact_index, contact_index))
