/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "../common/point_kd_tree.h"
#include "../common/splitmix.h"

#include <segmat/common/error.h>
#include <segmat/evaluation/box_abstraction_metrics.h>
#include <segmat/geometry/winding_number.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace segmat {
namespace {

double
unitDouble(std::uint64_t& counter)
{
  return static_cast<double>(detail::splitmix64(counter++) >> 11) * 0x1.0p-53;
}

/** \a count points uniform by area on the mesh (a face by its cumulative area, then uniform
 * barycentric coordinates). */
std::vector<Eigen::Vector3d>
sampleByArea(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed)
{
  std::vector<double> cumulative(mesh.numFaces());
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.numFaces(); ++f)
    cumulative[f] = total += mesh.faceArea(static_cast<int>(f));
  std::vector<Eigen::Vector3d> out;
  if (!(total > 0.0))
    return out;
  std::uint64_t counter = seed * 0x9E3779B97F4A7C15ull;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = unitDouble(counter) * total;
    const std::size_t f = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
        mesh.numFaces() - 1);
    double u = unitDouble(counter), v = unitDouble(counter);
    if (u + v > 1.0) {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Eigen::Vector3i& t = mesh.faces[f];
    out.push_back(mesh.vertices[t[0]] + u * (mesh.vertices[t[1]] - mesh.vertices[t[0]]) +
                  v * (mesh.vertices[t[2]] - mesh.vertices[t[0]]));
  }
  return out;
}

/** Mean nearest distance (and squared) from each of \a from to \a to. */
std::pair<double, double>
meanNearest(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to)
{
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3d& p : to)
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z())));
  detail::PointKdTree tree;
  tree.setInputCloud(cloud);
  pcl::Indices index;
  std::vector<float> sq;
  double sum = 0.0, sum_sq = 0.0;
  for (const Eigen::Vector3d& p : from) {
    tree.nearestKSearch(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                      static_cast<float>(p.z())),
                        1, index, sq);
    // The exact distance to the found neighbour, in double.
    const double d2 = (p - to[index[0]]).squaredNorm();
    sum += std::sqrt(d2);
    sum_sq += d2;
  }
  const double n = static_cast<double>(from.size());
  return {sum / n, sum_sq / n};
}

} // namespace

BoxAbstractionScores
scoreBoxAbstraction(const TriangleMesh& shape, const std::vector<OrientedBox>& boxes,
                    int resolution, std::size_t samples, unsigned threads, std::uint64_t seed)
{
  if (shape.empty())
    throw Error("scoreBoxAbstraction: the shape has no faces");
  if (boxes.empty())
    throw Error("scoreBoxAbstraction: no boxes");
  if (resolution < 2 || samples < 1)
    throw Error("scoreBoxAbstraction: resolution must be >= 2 and samples >= 1");

  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3d& v : shape.vertices)
    bounds.extend(v);
  const double diagonal = bounds.diagonal().norm();
  for (const OrientedBox& box : boxes)
    for (const Eigen::Vector3d& c : box.corners())
      bounds.extend(c);
  const double cell = bounds.diagonal().maxCoeff() / resolution;
  if (!(cell > 0.0) || !(diagonal > 0.0))
    throw Error("scoreBoxAbstraction: the shape has no extent");
  Eigen::Vector3i cells;
  for (int k = 0; k < 3; ++k)
    cells[k] = std::max(1, static_cast<int>(std::ceil(bounds.diagonal()[k] / cell - 1e-9)));
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(static_cast<std::size_t>(cells.prod()));
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k)
        centres.push_back(bounds.min() + cell * (Eigen::Vector3d(i, j, k).array() + 0.5).matrix());
  std::vector<double> winding;
  WindingNumber(shape).evaluate(centres, winding, threads);
  std::size_t both = 0, either = 0;
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const bool in_shape = winding[c] > 0.5;
    const bool in_boxes = std::any_of(boxes.begin(), boxes.end(),
                                      [&](const OrientedBox& b) { return b.contains(centres[c]); });
    both += in_shape && in_boxes;
    either += in_shape || in_boxes;
  }

  BoxAbstractionScores scores;
  scores.iou = either ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
  const std::vector<Eigen::Vector3d> on_shape = sampleByArea(shape, samples, seed);
  const std::vector<Eigen::Vector3d> on_boxes = sampleByArea(boxesToMesh(boxes), samples, seed + 1);
  if (on_shape.empty() || on_boxes.empty())
    throw Error("scoreBoxAbstraction: the shape or the boxes have no area");
  const auto a = meanNearest(on_shape, on_boxes);
  const auto b = meanNearest(on_boxes, on_shape);
  scores.chamfer = 0.5 * (a.first + b.first) / diagonal;
  scores.chamfer_squared = 0.5 * (a.second + b.second) / (diagonal * diagonal);
  return scores;
}

} // namespace segmat
