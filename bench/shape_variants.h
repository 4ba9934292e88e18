/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Transformed copies of a mesh that must keep its parts (header only), shared by
 * tests/test_invariance.cpp and bench/bench_invariance.cpp, the Rand distance they compare
 * labels with, and midpoint subdivision (bench_label_transfer: a scan-sized copy of a shape).
 */
#pragma once

#include <segmat/io/mesh.h>
#include <segmat/io/obj.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace segmat {
namespace bench {

/** \brief Pairs of elements one labelling puts together and the other apart, over all pairs
 * (elements labelled < 0 in either are left out); from the contingency table. */
inline double
randDistance(const std::vector<int>& a, const std::vector<int>& b)
{
  std::map<std::pair<int, int>, double> both;
  std::map<int, double> in_a, in_b;
  double n = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (a[i] < 0 || b[i] < 0)
      continue;
    ++both[{a[i], b[i]}];
    ++in_a[a[i]];
    ++in_b[b[i]];
    ++n;
  }
  const auto pairs = [](double c) { return c * (c - 1) / 2; };
  double together_both = 0, together_a = 0, together_b = 0;
  for (const auto& entry : both)
    together_both += pairs(entry.second);
  for (const auto& entry : in_a)
    together_a += pairs(entry.second);
  for (const auto& entry : in_b)
    together_b += pairs(entry.second);
  return n < 2 ? 0.0 : (together_a + together_b - 2 * together_both) / pairs(n);
}

/** \brief Each triangle split into four at its edges' midpoints: the same surface with four times
 * the faces. Face k of the result lies in face k % mesh.numFaces() of \a mesh. */
inline TriangleMesh
subdivided(const TriangleMesh& mesh)
{
  TriangleMesh out;
  out.vertices = mesh.vertices;
  std::map<std::pair<int, int>, int> midpoint;
  const auto mid = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto it = midpoint.find(key);
    if (it != midpoint.end())
      return it->second;
    out.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
    return midpoint[key] = static_cast<int>(out.vertices.size()) - 1;
  };
  const std::size_t nf = mesh.numFaces();
  out.faces.resize(4 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    out.faces[f] = Eigen::Vector3i(t[0], ab, ca);
    out.faces[nf + f] = Eigen::Vector3i(ab, t[1], bc);
    out.faces[2 * nf + f] = Eigen::Vector3i(ca, bc, t[2]);
    out.faces[3 * nf + f] = Eigen::Vector3i(ab, bc, ca);
  }
  return out;
}

/** \brief A fixed rigid rotation (no axis-aligned symmetry). */
inline Eigen::Matrix3d
someRotation()
{
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-1.9, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/** \brief One transformed copy of a mesh. */
struct MeshVariant
{
  std::string name;
  TriangleMesh mesh;
  std::vector<int> face_of; ///< variant face k is original face face_of[k] (empty: the same)
  bool identical = false;   ///< labels must be bit-identical to the original's

  /** \brief \a labels of this variant's faces, in the original's face order. */
  std::vector<int>
  inOriginalOrder(const std::vector<int>& labels) const
  {
    if (face_of.empty())
      return labels;
    std::vector<int> out(labels.size());
    for (std::size_t k = 0; k < labels.size(); ++k)
      out[face_of[k]] = labels[k];
    return out;
  }
};

/** \brief Translated far away (1000 diagonals), scaled by 1e3, 1e-3, 2^-7 and 2^30, rotated,
 * re-ordered (vertices and faces reversed, corners rotated), and read back from PLY, OBJ and
 * ASCII STL files written at \a stem + ".ply" etc. (PLY and STL store floats). */
inline std::vector<MeshVariant>
meshVariants(const TriangleMesh& mesh, const std::string& stem)
{
  const auto mapped = [&](const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f) {
    TriangleMesh out = mesh;
    for (Eigen::Vector3d& p : out.vertices)
      p = f(p);
    return out;
  };
  const double d = mesh.boundingBoxDiagonal();
  const Eigen::Vector3d far(1e3 * d, -2e3 * d, 5e2 * d);
  const Eigen::Matrix3d rotation = someRotation();
  std::vector<MeshVariant> variants;
  variants.push_back({"translated", mapped([&](const Eigen::Vector3d& p) { return p + far; }), {}, false});
  variants.push_back({"scale 1e3", mapped([](const Eigen::Vector3d& p) { return 1e3 * p; }), {}, false});
  variants.push_back({"scale 1e-3", mapped([](const Eigen::Vector3d& p) { return 1e-3 * p; }), {}, false});
  variants.push_back({"scale 2^-7", mapped([](const Eigen::Vector3d& p) { return std::ldexp(1.0, -7) * p; }), {}, true});
  variants.push_back({"scale 2^30", mapped([](const Eigen::Vector3d& p) { return std::ldexp(1.0, 30) * p; }), {}, true});
  variants.push_back({"rotated", mapped([&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return rotation * p; }), {}, false});

  MeshVariant reordered{"reordered", TriangleMesh(), {}, true};
  const int n = static_cast<int>(mesh.numVertices()), nf = static_cast<int>(mesh.numFaces());
  reordered.mesh.vertices.assign(mesh.vertices.rbegin(), mesh.vertices.rend());
  for (int k = 0; k < nf; ++k) {
    const Eigen::Vector3i f = (n - 1) * Eigen::Vector3i::Ones() - mesh.faces[nf - 1 - k];
    reordered.mesh.faces.emplace_back(f[2], f[0], f[1]);
    reordered.face_of.push_back(nf - 1 - k);
  }
  variants.push_back(std::move(reordered));

  io::saveMesh(stem + ".ply", mesh);
  variants.push_back({"PLY", io::loadMesh(stem + ".ply"), {}, false});
  io::saveObj(stem + ".obj", mesh);
  variants.push_back({"OBJ", io::loadMesh(stem + ".obj"), {}, false});
  {
    std::ofstream out(stem + ".stl");
    out.precision(9);
    out << "solid shape\n";
    for (const Eigen::Vector3i& f : mesh.faces) {
      out << "facet normal 0 0 0\nouter loop\n";
      for (int k = 0; k < 3; ++k)
        out << "vertex " << mesh.vertices[f[k]].transpose() << "\n";
      out << "endloop\nendfacet\n";
    }
    out << "endsolid shape\n";
  }
  variants.push_back({"STL", io::loadMesh(stem + ".stl"), {}, false});
  return variants;
}

} // namespace bench
} // namespace segmat
