/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_mesh_fit.h>
#include <segmat/geometry/mesh_distance.h>
#include <segmat/geometry/winding_number.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

namespace segmat {
namespace {
std::string
sphereText(const MedialMesh& mat, int v)
{
  char text[160];
  const Eigen::Vector3d& c = mat.centers()[v];
  std::snprintf(text, sizeof text, "sphere %d (centre %.6g %.6g %.6g, radius %.6g)", v, c.x(),
                c.y(), c.z(), mat.radii()[v]);
  return text;
}
} // namespace

bool
MedialMeshFit::check(const MedialMesh& mat, const TriangleMesh& mesh, std::string& reason) const
{
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : mesh.vertices)
    box.extend(p);
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  if (!std::isfinite(diagonal) || !(diagonal > 0.0)) {
    reason = "the mesh has no finite extent to check the medial mesh against";
    return false;
  }
  const int n = static_cast<int>(mat.numVertices());
  for (int v = 0; v < n; ++v) {
    const double r = mat.radii()[v];
    if (!mat.centers()[v].allFinite() || !std::isfinite(r) || r < 0.0) {
      reason = sphereText(mat, v) + " is not finite or has a negative radius";
      return false;
    }
    if (r > diagonal) {
      reason = sphereText(mat, v) + ": the radius exceeds the mesh's size (bounding-box "
               "diagonal " + std::to_string(diagonal) + ")";
      return false;
    }
  }
  Eigen::AlignedBox3d grown = box;
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(box_margin * diagonal);
  grown.extend(box.min() - margin).extend(box.max() + margin);
  for (int v = 0; v < n; ++v)
    if (!grown.contains(mat.centers()[v])) {
      reason = sphereText(mat, v) + " lies outside the mesh's bounding box: is this the "
               "medial mesh of another shape?";
      return false;
    }
  if (n == 0)
    return true;
  const WindingNumber winding(mesh);
  const MeshDistance distance(mesh);
  std::vector<double> w;
  winding.evaluate(mat.centers(), w);
  int away = 0, first_away = -1;
  for (int v = 0; v < n; ++v)
    if (!(w[v] > 0.5) && distance.distance(mat.centers()[v]) > surface_margin * diagonal) {
      if (first_away < 0)
        first_away = v;
      ++away;
    }
  if (away > outside_fraction * n) {
    reason = std::to_string(away) + " of " + std::to_string(n) +
             " sphere centres lie outside the surface, away from it (first: " +
             sphereText(mat, first_away) + "): is this the medial mesh of another shape?";
    return false;
  }
  return true;
}

} // namespace segmat
