/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// --boxes of segmat_mesh and segmat_cloud (not installed): one oriented box per part, written to
// PREFIX_boxes.json and PREFIX_boxes.ply.

#include <segmat/evaluation/part_box_estimation.h>
#include <segmat/io/boxes.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <segmat/io/atomic_file.h>

#include <string>
#include <vector>

namespace segmat {
namespace cli {

/** The files --boxes writes after PREFIX (declare them with the run's other outputs). */
inline std::vector<std::string>
boxSuffixes()
{
  return {"_boxes.json", "_boxes.ply"};
}

/** Writes the boxes of the estimation's parts into \a outputs' temporaries (committed with the
 * run's other outputs); returns how many. */
inline std::size_t
writePartBoxes(const io::OutputSet& outputs, const std::string& prefix,
               const PartBoxEstimation& estimation)
{
  std::vector<PartBox> boxes;
  estimation.compute(boxes);
  io::saveBoxesJson(outputs.temporary(prefix + "_boxes.json"), boxes);
  io::saveBoxesPly(outputs.temporary(prefix + "_boxes.ply"), boxes);
  return boxes.size();
}

/** Boxes of a segmented mesh (one label per face). */
inline std::size_t
writePartBoxes(const io::OutputSet& outputs, const std::string& prefix,
               const TriangleMesh::ConstPtr& mesh, const std::vector<int>& face_labels)
{
  PartBoxEstimation estimation;
  estimation.setInputMesh(mesh, face_labels);
  return writePartBoxes(outputs, prefix, estimation);
}

/** Boxes of a labelled cloud (the `label` field; \a labels, when as long as the cloud, overrides
 * it so that unlabelled points (−1) get no box). */
inline std::size_t
writePartBoxes(const io::OutputSet& outputs, const std::string& prefix,
               const pcl::PointCloud<pcl::PointXYZL>& cloud, const std::vector<int>& labels)
{
  std::vector<Eigen::Vector3d> points(cloud.size());
  std::vector<int> point_labels(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    points[i] = cloud[i].getVector3fMap().cast<double>();
    point_labels[i] = labels.size() == cloud.size() ? labels[i] : static_cast<int>(cloud[i].label);
  }
  PartBoxEstimation estimation;
  estimation.setInputPoints(points, point_labels);
  return writePartBoxes(outputs, prefix, estimation);
}

} // namespace cli
} // namespace segmat
