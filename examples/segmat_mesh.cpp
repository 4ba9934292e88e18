/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_mesh: segment a triangle mesh into parts with SEG-MAT; its two medial meshes are computed
 * from it unless given.
 */
#include <segmat/common/error.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include "box_output.h"
#include "cli_options.h"
#include "render_call.h"
#include "detail_level_option.h"
#include "hierarchy_output.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

const char* const kUsage =
    "usage: segmat_mesh MESH -o PREFIX [-b BASE.ma -s STRUCTURED.ma] [--save-mat] [-g DELTA0]\n"
    "                   [-n ETA] [--seed S] [--max-bend DEG] [--reference-crease]\n"
    "                   [--threads T]\n"
    "                   [--level L] [--hierarchy] [--boxes] [--json] [--png PICTURE.png]\n"
    "  MESH            closed triangle mesh (.off, .ply, .obj, .stl)\n"
    "  -o PREFIX       writes PREFIX.seg (one label per face, PSB format) and PREFIX.ply\n"
    "                  (faces coloured by part)\n"
    "  -b BASE.ma      base medial mesh (Q-MAT .ma, e.g. 2000 spheres) } both or neither;\n"
    "  -s STRUCT.ma    structured medial mesh (e.g. 15-30 spheres)     } default: computed\n"
    "  --save-mat      also write the computed medial meshes to PREFIX_base.ma and\n"
    "                  PREFIX_struct.ma\n"
    "  --threads T     threads of the medial-mesh computation (default 1; 0 = all)\n"
    "  -g DELTA0       growing threshold (default 0.015)\n"
    "  -n ETA          minimal region, fraction of the base MAT's spheres (default 0.002)\n"
    "  --seed S        seed of the merging's visibility sampling (default 386727)\n"
    "  --max-bend DEG  largest turn of a bulky tube inside one part (default 60; 90 = off,\n"
    "                  as in SEG-MAT)\n"
    "  --reference-crease  price concave creases in the surface cut as SEG-MAT does\n"
    "                  (default: a sharp concave crease is much cheaper to cut than a shallow\n"
    "                  one; see README)\n"
    "  --json          print one JSON object: parts, face_counts, seconds per stage\n"
    "  --png FILE      also draw the parts into a PNG (segmat_render, built with VTK)\n"
    "  --level L       coarse, default or fine: sets -g and -n together (docs/levels.md);\n"
    "                  a number in [-1, 1] goes between them (-1 coarse, 0 default, 1 fine)\n"
    "  --hierarchy     also segment at every level, coarse to fine, each part inside one part\n"
    "                  of the level above; writes PREFIX_level0.seg.. and PREFIX_hierarchy.json\n"
    "  --boxes         also write PREFIX_boxes.json and PREFIX_boxes.ply: one tight oriented\n"
    "                  box per part (docs/abstraction.md)\n";



} // namespace

using namespace segmat::cli;

int
main(int argc, char** argv)
{
  std::string mesh_path, base_path, structured_path, prefix;
  std::string png; // --png: a picture by segmat_render
  bool json = false, save_mat = false, boxes = false, hierarchy = false;
  segmat::MeshSegmentation segmentation;
  segmentation.setNumberOfThreads(1);
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      const auto value = [&]() -> std::string {
        if (i + 1 >= argc)
          throw segmat::Error("option " + arg + " needs a value");
        return argv[++i];
      };
      if (arg == "-h" || arg == "--help") {
        std::cout << kUsage;
        return 0;
      }
      if (arg == "-b")
        base_path = value();
      else if (arg == "-s")
        structured_path = value();
      else if (arg == "-o")
        prefix = value();
      else if (arg == "-g") {
        const double delta0 = parseNumber(arg, value());
        if (!(delta0 > 0.0))
          throw segmat::Error("option -g: the growing threshold must be > 0");
        segmentation.setGrowingThreshold(delta0);
      }
      else if (arg == "-n") {
        const double eta = parseNumber(arg, value());
        if (eta < 0.0 || eta > 1.0)
          throw segmat::Error("option -n: the minimal region fraction must be in [0, 1]");
        segmentation.setMinRegionFraction(eta);
      }
      else if (arg == "--seed") {
        const double seed = parseNumber(arg, value());
        if (seed < 0.0 || seed > 4294967295.0 || seed != std::floor(seed))
          throw segmat::Error("option --seed: give a whole number in [0, 2^32)");
        segmentation.setRandomSeed(static_cast<unsigned>(seed));
      }
      else if (arg == "--max-bend")
        segmentation.setMaxBendAngle(parseBendAngle(arg, value()));
      else if (arg == "--reference-crease")
        segmentation.setCreaseModel(segmat::CreaseModel::Reference);
      else if (arg == "--json")
        json = true;
      else if (arg == "--png")
        png = value();
      else if (arg == "--boxes")
        boxes = true;
      else if (arg == "--level")
        applyDetailLevel(segmentation, value());
      else if (arg == "--hierarchy")
        hierarchy = true;
      else if (arg == "--save-mat")
        save_mat = true;
      else if (arg == "--threads") {
        const double threads = parseNumber(arg, value());
        if (threads < 0.0 || threads > 4096.0 || threads != std::floor(threads))
          throw segmat::Error("option --threads: give a whole number >= 0");
        segmentation.setNumberOfThreads(static_cast<unsigned>(threads));
      }
      else if (!arg.empty() && arg[0] == '-')
        throw segmat::Error("unknown option " + arg);
      else if (mesh_path.empty())
        mesh_path = arg;
      else
        throw segmat::Error("unexpected argument " + arg);
    }
    if (mesh_path.empty() || prefix.empty())
      throw segmat::Error("MESH and -o are required");
    if (base_path.empty() != structured_path.empty())
      throw segmat::Error("give both -b and -s, or neither (the medial meshes are then computed)");
    if (save_mat && !base_path.empty())
      throw segmat::Error("--save-mat writes computed medial meshes: not with -b and -s");
  }
  catch (const segmat::Error& e) {
    std::cerr << "segmat_mesh: " << e.what() << "\n" << kUsage;
    return 2;
  }

  // Exit status as segmat_eval: 2 for bad usage or a missing or malformed input, 1 otherwise.
  auto start = std::chrono::steady_clock::now();
  segmat::TriangleMesh::Ptr mesh;
  segmat::MedialMesh::Ptr base, structured;
  try {
    mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadMesh(mesh_path));
    if (mesh->empty())
      throw segmat::Error(mesh_path, 0, "the mesh has no faces");
    if (!base_path.empty()) {
      base = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(base_path));
      structured = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(structured_path));
      if (base->empty())
        throw segmat::Error(base_path, 0, "the base medial mesh has no spheres");
    }
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_mesh: " << e.what() << "\n";
    return 2;
  }
  const double load_seconds = secondsSince(start);

  try {
    segmentation.setInputMesh(mesh);
    if (base) { // otherwise segment() computes them
      segmentation.setBaseMat(base);
      segmentation.setStructuredMat(structured);
    }
    std::vector<int> labels;
    if (!segmentation.segment(labels))
      throw segmat::Error(mesh_path, 0, "segmentation failed (see the message above)");
    secondsSince(start);
    segmat::io::saveSeg(prefix + ".seg", labels);
    segmat::io::saveColoredMeshPly(prefix + ".ply", *mesh, labels);
    if (!png.empty())
      renderPicture(mesh_path, prefix + ".seg", png);
    if (boxes)
      writePartBoxes(prefix, mesh, labels);
    if (save_mat) {
      segmat::io::saveMa(prefix + "_base.ma", *segmentation.getBaseMat());
      segmat::io::saveMa(prefix + "_struct.ma", *segmentation.getStructuredMat());
    }
    const double write_seconds = secondsSince(start);

    std::vector<pcl::PointIndices> parts;
    segmentation.getParts(parts);
    std::vector<std::pair<std::string, double>> seconds{{"load", load_seconds}};
    for (const auto& stage : segmentation.getStageSeconds())
      seconds.push_back(stage);
    seconds.emplace_back("write", write_seconds);
    if (hierarchy) // after the report's figures were taken: it segments again
      writeHierarchy(prefix, segmentation);

    if (json) {
      std::printf("{\"parts\": %zu, \"mat_computed\": %s, \"base_spheres\": %zu, "
                  "\"structured_spheres\": %zu, \"face_counts\": [",
                  parts.size(), segmentation.hasComputedMats() ? "true" : "false",
                  segmentation.getBaseMat()->numVertices(),
                  segmentation.getStructuredMat()->numVertices());
      for (std::size_t k = 0; k < parts.size(); ++k)
        std::printf("%s%zu", k ? ", " : "", parts[k].indices.size());
      std::printf("], \"seconds\": {");
      for (std::size_t k = 0; k < seconds.size(); ++k)
        std::printf("%s\"%s\": %.6f", k ? ", " : "", seconds[k].first.c_str(), seconds[k].second);
      std::printf("}}\n");
    }
    else {
      std::printf("parts: %zu\nface counts:", parts.size());
      for (const auto& part : parts)
        std::printf(" %zu", part.indices.size());
      std::printf("\nseconds:");
      for (const auto& stage : seconds)
        std::printf(" %s %.4f", stage.first.c_str(), stage.second);
      std::printf("\nwrote %s.seg and %s.ply", prefix.c_str(), prefix.c_str());
      if (save_mat)
        std::printf(", %s_base.ma and %s_struct.ma", prefix.c_str(), prefix.c_str());
      std::printf("\n");
    }
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
