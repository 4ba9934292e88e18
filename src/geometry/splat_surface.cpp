/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/splat_surface.h>

#include <Eigen/Geometry>

#include <cmath>

namespace segmat {

TriangleMesh
makeSplatSurface(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& areas)
{
  TriangleMesh soup;
  const std::size_t n = std::min({points.size(), normals.size(), areas.size()});
  soup.vertices.reserve(3 * n);
  soup.faces.reserve(n);
  // Equilateral triangle of area a: circumradius R = sqrt(4a / (3√3)).
  const double factor = std::sqrt(4.0 / (3.0 * std::sqrt(3.0)));
  const double c = -0.5, s = std::sqrt(3.0) / 2.0; // cos, sin of 120°
  for (std::size_t i = 0; i < n; ++i) {
    const double norm = normals[i].norm();
    if (!points[i].allFinite() || !normals[i].allFinite() || !(norm > 0.0) ||
        !(areas[i] > 0.0) || !std::isfinite(areas[i]))
      continue;
    const Eigen::Vector3d normal = normals[i] / norm;
    // u ⟂ n, v = n × u: corners at angles 0, 120°, 240° turn counter-clockwise about n.
    const Eigen::Vector3d u = normal.unitOrthogonal();
    const Eigen::Vector3d v = normal.cross(u);
    const double radius = factor * std::sqrt(areas[i]);
    const int first = static_cast<int>(soup.vertices.size());
    soup.vertices.push_back(points[i] + radius * u);
    soup.vertices.push_back(points[i] + radius * (c * u + s * v));
    soup.vertices.push_back(points[i] + radius * (c * u - s * v));
    soup.faces.emplace_back(first, first + 1, first + 2);
  }
  return soup;
}

} // namespace segmat
