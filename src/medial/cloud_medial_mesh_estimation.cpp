/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/cloud_medial_mesh_estimation.h>

#include "../common/checked_setter.h"
#include <segmat/geometry/splat_surface.h>
#include <segmat/geometry/winding_number.h>

#include "../common/point_kd_tree.h"

#include <pcl/console/print.h>

#include <cmath>
#include <cstdint>

namespace segmat {

CloudMedialMeshEstimation::CloudMedialMeshEstimation()
{
  // On a splat surface the test is a full winding-number evaluation per collapse (the face
  // crossing count needs a closed surface): 30 % of Q-MAT's time, for the same PSB scores.
  estimation_.setKeepCentresInside(false);
}

void
CloudMedialMeshEstimation::setAreaKSearch(int k)
{
  detail::assignChecked(area_k_, k, k >= 1, "CloudMedialMeshEstimation::setAreaKSearch",
                        "at least 1");
}

bool
CloudMedialMeshEstimation::compute(MedialMesh& base, MedialMesh& structured)
{
  base = MedialMesh();
  structured = MedialMesh();
  return computeInitialMat() && simplify(base, structured);
}

bool
CloudMedialMeshEstimation::computeInitialMat()
{
  splats_ = std::make_shared<TriangleMesh>();
  if (!cloud_) {
    PCL_ERROR("[segmat::CloudMedialMeshEstimation::compute] No input cloud.\n");
    return false;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  auto points = std::make_shared<std::vector<Eigen::Vector3d>>();
  auto normals = std::make_shared<std::vector<Eigen::Vector3d>>();
  for (const pcl::PointNormal& p : *cloud_) {
    const Eigen::Vector3d position = p.getVector3fMap().cast<double>();
    const Eigen::Vector3d normal = p.getNormalVector3fMap().cast<double>();
    if (!position.allFinite() || !normal.allFinite() || !(normal.norm() > 0.0))
      continue;
    points->push_back(position);
    normals->push_back(normal.normalized());
    xyz->push_back(pcl::PointXYZ(p.x, p.y, p.z));
  }
  if (points->size() < 4) {
    PCL_ERROR("[segmat::CloudMedialMeshEstimation::compute] Only %zu points with a finite "
              "position and normal (need 4).\n",
              points->size());
    return false;
  }

  // Area per point from the k-th neighbour's squared distance (the point itself comes first).
  const int k = std::min<int>(area_k_, static_cast<int>(points->size()) - 1);
  detail::PointKdTree tree;
  tree.setInputCloud(xyz);
  std::vector<double> areas(points->size());
  pcl::Indices found;
  std::vector<float> distances;
  constexpr double kPi = 3.14159265358979323846;
  for (std::size_t i = 0; i < points->size(); ++i) {
    tree.nearestKSearch((*xyz)[i], k + 1, found, distances);
    areas[i] = distances.empty() ? 0.0 : kPi * double(distances.back()) / (k + 1);
  }
  *splats_ = makeSplatSurface(*points, *normals, areas);
  if (splats_->empty()) {
    PCL_ERROR("[segmat::CloudMedialMeshEstimation::compute] The points all coincide: no "
              "surface area.\n");
    return false;
  }
  // The splats are oriented by the normals and share no edge: no orientation repair.
  auto winding_number = std::make_shared<WindingNumber>(*splats_, false);
  estimation_.setInputMesh(splats_);
  // The normals let the Voronoi step skip the winding number where they settle the question.
  estimation_.setSurfaceSamples(points, normals);
  estimation_.setWindingNumber(winding_number);
  const bool ok = estimation_.computeInitialMat();
  // Do not keep the cloud's data alive in the member (simplify() needs only the splats).
  estimation_.setSurfaceSamples(nullptr);
  estimation_.setWindingNumber(nullptr);
  if (!ok)
    estimation_.setInputMesh(nullptr);
  return ok;
}

bool
CloudMedialMeshEstimation::simplify(MedialMesh& base, MedialMesh& structured)
{
  const bool ok = estimation_.simplify(base, structured);
  estimation_.setInputMesh(nullptr);
  return ok;
}

} // namespace segmat
