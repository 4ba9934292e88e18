/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// medial_mesh, psb_metrics, labels_to_colors, load_mesh.
#include "arrays.h"
#include "bindings.h"

#include <segmat/common/error.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/mesh.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/common/colors.h>

#include <cmath>
#include <memory>
#include <string>

namespace segmat_python {

namespace {

py::dict
scoresDict(const segmat::PsbScores& s)
{
  py::dict d;
  d["CD"] = s.CD;
  d["HD"] = s.HD;
  d["Rm"] = s.Rm;
  d["Rf"] = s.Rf;
  d["RI"] = s.RI;
  d["GCE"] = s.GCE;
  d["LCE"] = s.LCE;
  d["GCEf"] = s.GCEf;
  d["LCEf"] = s.LCEf;
  d["count"] = s.count;
  d["cd_count"] = s.cd_count;
  return d;
}

} // namespace

void
bindTools(py::module_& m)
{
  m.def(
      "medial_mesh",
      [](const py::handle& vertices, const py::handle& faces, int spheres, bool structured,
         unsigned threads) {
        if (spheres < 1)
          throw py::value_error("medial_mesh(): spheres=" + std::to_string(spheres) +
                                " is not >= 1");
        const segmat::TriangleMesh::Ptr mesh = toMesh(vertices, faces);
        segmat::MedialMesh::ConstPtr base, coarse;
        bool ok = false;
        {
          // Through MeshSegmentation, so that these are the medial meshes it segments with
          // (normalised frame, noise removed first); the parts it also finds are dropped.
          py::gil_scoped_release release;
          segmat::MeshSegmentation segmentation;
          segmentation.setInputMesh(mesh);
          segmentation.setBaseMatTarget(spheres);
          segmentation.setNumberOfThreads(threads);
          std::vector<int> labels;
          ok = segmentation.segment(labels);
          base = segmentation.getBaseMat();
          coarse = segmentation.getStructuredMat();
        }
        if (!ok)
          throw segmat::Error("medial_mesh(): the medial mesh cannot be computed; the message "
                              "above says why (e.g. a surface that encloses no volume)");
        return toArrays(structured ? coarse : base);
      },
      py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("spheres") = 2000,
      py::arg("structured") = false, py::arg("threads") = 0,
      "The medial mesh of a closed triangle mesh (Voronoi MAT simplified by Q-MAT) as "
      "(centers (n,3), radii (n,), edges (e,2), triangles (t,3)). spheres: size of the base "
      "MAT; structured=True returns the coarse structured MAT instead.");

  m.def(
      "psb_metrics",
      [](const py::handle& vertices, const py::handle& faces, const py::handle& labels,
         const py::iterable& human_labels_list) {
        const segmat::TriangleMesh::Ptr mesh = toMesh(vertices, faces);
        const std::vector<int> prediction = toLabels(labels, mesh->numFaces(), "labels");
        std::vector<std::vector<int>> references;
        for (const py::handle& h : human_labels_list)
          references.push_back(toLabels(h, mesh->numFaces(), "human_labels_list[i]"));
        if (references.empty())
          throw py::value_error("psb_metrics(): human_labels_list is empty");
        segmat::PsbScores mean;
        std::vector<segmat::PsbScores> each;
        bool ok = false;
        {
          py::gil_scoped_release release;
          const segmat::PsbEvaluator evaluator(*mesh);
          ok = evaluator.ready() && evaluator.scoreAgainstAll(prediction, references, mean, &each);
        }
        if (!ok)
          throw py::value_error("psb_metrics(): the mesh cannot be scored (no face with area?)");
        py::dict d = scoresDict(mean);
        py::list per_reference;
        for (const segmat::PsbScores& s : each)
          per_reference.append(scoresDict(s));
        d["per_reference"] = per_reference;
        return d;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("labels"), py::arg("human_labels_list"),
      "Princeton Segmentation Benchmark scores of labels (one per face) against each human "
      "segmentation, averaged as the benchmark does: a dict CD, HD, Rm, Rf, RI, GCE, LCE, GCEf, "
      "LCEf (fractions, lower is better; CD NaN when undefined), count, cd_count, and "
      "per_reference (one such dict per human segmentation).");

  m.def(
      "labels_to_colors",
      [](const py::handle& labels) {
        const std::vector<int> l = toLabels(labels, 0, "labels");
        py::array_t<double> colors({static_cast<py::ssize_t>(l.size()), py::ssize_t{3}});
        auto c = colors.mutable_unchecked<2>();
        for (std::size_t i = 0; i < l.size(); ++i) {
          pcl::RGB rgb; // black: unlabelled (-1)
          rgb.r = rgb.g = rgb.b = 0;
          if (l[i] >= 0)
            rgb = pcl::GlasbeyLUT::at(static_cast<std::size_t>(l[i]) % pcl::GlasbeyLUT::size());
          c(i, 0) = rgb.r / 255.0;
          c(i, 1) = rgb.g / 255.0;
          c(i, 2) = rgb.b / 255.0;
        }
        return colors;
      },
      py::arg("labels"),
      "(n, 3) float64 RGB in [0, 1] per label (PCL's Glasbey table, the colours of the "
      "command-line programs' PLY files; negative labels black), e.g. for Open3D's "
      "vertex_colors.");

  m.def(
      "load_mesh",
      [](const std::string& path) {
        segmat::TriangleMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = segmat::io::loadMesh(path);
        }
        py::array_t<double> v({static_cast<py::ssize_t>(mesh.numVertices()), py::ssize_t{3}});
        py::array_t<int> f({static_cast<py::ssize_t>(mesh.numFaces()), py::ssize_t{3}});
        for (std::size_t i = 0; i < mesh.numVertices(); ++i)
          for (int k = 0; k < 3; ++k)
            v.mutable_at(i, k) = mesh.vertices[i][k];
        for (std::size_t i = 0; i < mesh.numFaces(); ++i)
          for (int k = 0; k < 3; ++k)
            f.mutable_at(i, k) = mesh.faces[i][k];
        return py::make_tuple(v, f);
      },
      py::arg("path"),
      "(vertices (n,3) float64, faces (m,3) int32) of a mesh file (.off, .ply, .obj, .stl), "
      "read as the command-line programs read it.");
}

} // namespace segmat_python
