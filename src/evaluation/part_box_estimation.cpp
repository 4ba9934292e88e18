/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/evaluation/part_box_estimation.h>

#include <algorithm>
#include <string>
#include <utility>

namespace segmat {
namespace {
void
checkCount(std::size_t labels, std::size_t expected, const char* what)
{
  if (labels != expected)
    throw Error("PartBoxEstimation: " + std::to_string(labels) + " labels for " +
                std::to_string(expected) + " " + what);
}

} // namespace

void
PartBoxEstimation::setInputMesh(const TriangleMesh::ConstPtr& mesh,
                                const std::vector<int>& face_labels)
{
  if (!mesh)
    throw Error("PartBoxEstimation: no mesh");
  checkCount(face_labels.size(), mesh->numFaces(), "faces");
  const int n = static_cast<int>(mesh->numVertices());
  // (label, vertex) pairs, each once: a part's vertices in vertex order, no duplicates.
  std::vector<std::pair<int, int>> members;
  for (std::size_t f = 0; f < mesh->numFaces(); ++f) {
    if (face_labels[f] < 0)
      continue;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh->faces[f][k];
      if (v < 0 || v >= n)
        throw Error("PartBoxEstimation: face " + std::to_string(f) + " has vertex index " +
                    std::to_string(v) + " out of range");
      members.emplace_back(face_labels[f], v);
    }
  }
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  part_points_.clear();
  for (const auto& m : members)
    part_points_[m.first].push_back(mesh->vertices[m.second]);
}

void
PartBoxEstimation::setInputPoints(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<int>& labels)
{
  checkCount(labels.size(), points.size(), "points");
  part_points_.clear();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (labels[i] >= 0)
      part_points_[labels[i]].push_back(points[i]);
}

void
PartBoxEstimation::compute(std::vector<PartBox>& boxes) const
{
  boxes.clear();
  for (const auto& part : part_points_) {
    PartBox box;
    box.part = part.first;
    box.points = part.second.size();
    box.box = computeMinimumVolumeBox(part.second);
    boxes.push_back(box);
  }
}

} // namespace segmat
