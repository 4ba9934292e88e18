/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "util/synthetic_mesh.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace segmat {
namespace test {
namespace {
const double kPi = 3.14159265358979323846;
} // namespace

TriangleMesh
tetrahedron()
{
  return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                      {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

TriangleMesh
box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int n)
{
  n = std::max(n, 1);
  TriangleMesh mesh;
  // Grid vertices are shared between sides through their integer grid coordinates.
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](std::array<int, 3> g) {
    auto it = index.find(g);
    if (it != index.end())
      return it->second;
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k)
      p[k] = g[k] == n ? hi[k] : lo[k] + (hi[k] - lo[k]) * g[k] / n;
    const int id = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(p);
    index.emplace(g, id);
    return id;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<int, 3> g00{}, g10{}, g11{}, g01{};
          for (auto* g : {&g00, &g10, &g11, &g01})
            (*g)[axis] = side * n;
          g00[u] = i, g00[v] = j;
          g10[u] = i + 1, g10[v] = j;
          g11[u] = i + 1, g11[v] = j + 1;
          g01[u] = i, g01[v] = j + 1;
          const int a = vertex(g00), b = vertex(g10), c = vertex(g11), d = vertex(g01);
          // (u, v, axis) is right-handed: u×v points along +axis, outward on the high side.
          if (side == 1) {
            mesh.faces.emplace_back(a, b, c);
            mesh.faces.emplace_back(a, c, d);
          }
          else {
            mesh.faces.emplace_back(a, c, b);
            mesh.faces.emplace_back(a, d, c);
          }
        }
    }
  return mesh;
}

TriangleMesh
icosphere(int subdivisions, double radius, const Eigen::Vector3d& center)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                 {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                 {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v)
    p.normalize();
  std::vector<Eigen::Vector3i> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end())
        return it->second;
      v.push_back((v[a] + v[b]).normalized());
      const int id = static_cast<int>(v.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<Eigen::Vector3i> g;
    g.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      g.emplace_back(tri[0], ab, ca);
      g.emplace_back(tri[1], bc, ab);
      g.emplace_back(tri[2], ca, bc);
      g.emplace_back(ab, bc, ca);
    }
    f.swap(g);
  }
  for (auto& p : v)
    p = center + radius * p;
  return TriangleMesh(std::move(v), std::move(f));
}

TriangleMesh
revolve(const std::vector<Eigen::Vector2d>& profile_in, int segments)
{
  std::vector<Eigen::Vector2d> profile = profile_in;
  if (profile.empty() || segments < 3)
    return {};
  // Open ends become flat caps closed at a centre vertex, which is then just a pole.
  if (profile.front().x() > 0.0)
    profile.insert(profile.begin(), Eigen::Vector2d(0.0, profile.front().y()));
  if (profile.back().x() > 0.0)
    profile.emplace_back(0.0, profile.back().y());

  TriangleMesh mesh;
  std::vector<std::vector<int>> ring(profile.size());
  for (std::size_t k = 0; k < profile.size(); ++k) {
    const double r = profile[k].x(), z = profile[k].y();
    if (r == 0.0) {
      ring[k].assign(segments, static_cast<int>(mesh.vertices.size()));
      mesh.vertices.emplace_back(0.0, 0.0, z);
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      ring[k].push_back(static_cast<int>(mesh.vertices.size()));
      mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
  }
  // Going down the profile × going around (+phi) points outward.
  for (std::size_t k = 0; k + 1 < profile.size(); ++k)
    for (int j = 0; j < segments; ++j) {
      const int jn = (j + 1) % segments;
      const int a = ring[k][j], b = ring[k + 1][j], c = ring[k + 1][jn], d = ring[k][jn];
      if (b != c)
        mesh.faces.emplace_back(a, b, c);
      if (a != d)
        mesh.faces.emplace_back(a, c, d);
    }
  return mesh;
}

TriangleMesh
cylinder(double radius, double length, int segments, int stacks)
{
  std::vector<Eigen::Vector2d> profile;
  const int cap_rings = std::max(1, stacks / 4);
  for (int i = 0; i <= cap_rings; ++i)
    profile.emplace_back(radius * i / cap_rings, length / 2);
  for (int i = 1; i < stacks; ++i)
    profile.emplace_back(radius, length / 2 - length * i / stacks);
  for (int i = cap_rings; i >= 0; --i)
    profile.emplace_back(radius * i / cap_rings, -length / 2);
  return revolve(profile, segments);
}

TriangleMesh
capsule(double radius, double length, int segments, int stacks, int cap_rings)
{
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= cap_rings; ++i) {
    const double theta = 0.5 * kPi * i / cap_rings;
    profile.emplace_back(i == 0 ? 0.0 : radius * std::sin(theta),
                         length / 2 + radius * std::cos(theta));
  }
  for (int i = 1; i < stacks; ++i)
    profile.emplace_back(radius, length / 2 - length * i / stacks);
  for (int i = cap_rings; i >= 0; --i) {
    const double theta = 0.5 * kPi * i / cap_rings;
    profile.emplace_back(i == 0 ? 0.0 : radius * std::sin(theta),
                         -length / 2 - radius * std::cos(theta));
  }
  return revolve(profile, segments);
}

TriangleMesh
torus(double major, double minor, int major_segments, int minor_segments)
{
  TriangleMesh mesh;
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      const double phi = 2.0 * kPi * i / major_segments;
      const double theta = 2.0 * kPi * j / minor_segments;
      const double r = major + minor * std::cos(theta);
      mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), minor * std::sin(theta));
    }
  auto id = [&](int i, int j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  // +phi × +theta points outward (at phi = theta = 0: y × z = x).
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      mesh.faces.emplace_back(a, b, c);
      mesh.faces.emplace_back(a, c, d);
    }
  return mesh;
}

double
signedVolume(const TriangleMesh& mesh)
{
  double six_volume = 0.0;
  for (const auto& f : mesh.faces)
    six_volume += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]]));
  return six_volume / 6.0;
}

TriangleMesh
merge(const std::vector<TriangleMesh>& parts)
{
  TriangleMesh out;
  for (const auto& part : parts) {
    const int offset = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& f : part.faces)
      out.faces.push_back(f + Eigen::Vector3i::Constant(offset));
  }
  return out;
}

} // namespace test
} // namespace segmat
