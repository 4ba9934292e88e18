/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "normalized_frame.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace segmat {
namespace detail {

NormalizedFrame
NormalizedFrame::of(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite())
      box.extend(p);
  NormalizedFrame frame;
  if (box.isEmpty())
    return frame;
  // Halves first, so that coordinates near the double limit cannot overflow; multiplying by
  // 1/2 is exact, so the centre still scales exactly with the input.
  frame.centre = box.min() * 0.5 + box.max() * 0.5;
  const Eigen::Vector3d half_extent = box.max() * 0.5 - box.min() * 0.5;
  const double largest = half_extent.maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest))
    return frame;
  // The binary exponent of diagonal × √2 = 2 × largest × relative, without forming the
  // product; the scale then puts the diagonal in [1/√2, √2).
  const double relative = (half_extent / largest).norm() * std::sqrt(2.0); // in [√2, √6]
  const int exponent = std::ilogb(largest) + 1;
  frame.scale = std::ldexp(
      1.0, -(exponent + std::ilogb(std::scalbn(largest, 1 - exponent) * relative)));
  return frame;
}

namespace {
// \a mat with every centre mapped by \a move and every radius multiplied by \a factor.
template <typename Move>
MedialMesh
mappedMat(const MedialMesh& mat, const Move& move, double factor)
{
  std::vector<Eigen::Vector3d> centres = mat.centers();
  std::vector<double> radii = mat.radii();
  for (Eigen::Vector3d& c : centres)
    c = move(c);
  for (double& r : radii)
    r *= factor;
  return MedialMesh(std::move(centres), std::move(radii), mat.edges(), mat.triangles());
}
} // namespace

MedialMesh
NormalizedFrame::toFrame(const MedialMesh& mat) const
{
  return mappedMat(mat, [this](const Eigen::Vector3d& c) { return toFrame(c); }, scale);
}

MedialMesh
NormalizedFrame::fromFrame(const MedialMesh& mat) const
{
  return mappedMat(mat, [this](const Eigen::Vector3d& c) { return fromFrame(c); }, 1.0 / scale);
}

CanonicalMesh
canonicalMesh(const TriangleMesh& mesh)
{
  CanonicalMesh out;
  out.frame = NormalizedFrame::of(mesh.vertices);
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<Eigen::Vector3d> moved(nv);
  for (int v = 0; v < nv; ++v)
    moved[v] = out.frame.toFrame(mesh.vertices[v]);
  std::vector<int> vertex_order(nv);
  std::iota(vertex_order.begin(), vertex_order.end(), 0);
  const auto lexLess = [&](int a, int b) {
    const Eigen::Vector3d &p = moved[a], &q = moved[b];
    if (p.x() != q.x())
      return p.x() < q.x();
    if (p.y() != q.y())
      return p.y() < q.y();
    return p.z() < q.z();
  };
  // Non-finite coordinates have no order: such a mesh keeps its own (and fails later anyway).
  if (std::all_of(moved.begin(), moved.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); }))
    std::stable_sort(vertex_order.begin(), vertex_order.end(), lexLess);
  std::vector<int> new_index(nv);
  out.mesh.vertices.resize(nv);
  for (int k = 0; k < nv; ++k) {
    new_index[vertex_order[k]] = k;
    out.mesh.vertices[k] = moved[vertex_order[k]];
  }
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<Eigen::Vector3i> faces(nf);
  for (int f = 0; f < nf; ++f) {
    Eigen::Vector3i face = mesh.faces[f];
    const bool valid = face.minCoeff() >= 0 && face.maxCoeff() < nv;
    if (valid)
      for (int k = 0; k < 3; ++k)
        face[k] = new_index[face[k]];
    // Rotate (keeps the orientation) so that the smallest index comes first.
    int first = 0;
    for (int k = 1; k < 3; ++k)
      if (face[k] < face[first])
        first = k;
    faces[f] = Eigen::Vector3i(face[first], face[(first + 1) % 3], face[(first + 2) % 3]);
  }
  out.face_order.resize(nf);
  std::iota(out.face_order.begin(), out.face_order.end(), 0);
  std::stable_sort(out.face_order.begin(), out.face_order.end(), [&](int a, int b) {
    return std::lexicographical_compare(faces[a].data(), faces[a].data() + 3, faces[b].data(),
                                        faces[b].data() + 3);
  });
  out.mesh.faces.resize(nf);
  for (int k = 0; k < nf; ++k)
    out.mesh.faces[k] = faces[out.face_order[k]];
  return out;
}

} // namespace detail
} // namespace segmat
