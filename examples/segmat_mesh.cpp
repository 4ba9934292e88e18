/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_mesh: segment a triangle mesh into parts with SEG-MAT, given its two medial meshes.
 */
#include <segmat/common/error.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

const char* const kUsage =
    "usage: segmat_mesh MESH -b BASE.ma -s STRUCTURED.ma -o PREFIX [-g DELTA0] [-n ETA] [--json]\n"
    "  MESH            triangle mesh (.off, .ply, .obj)\n"
    "  -b BASE.ma      base medial mesh (Q-MAT .ma, e.g. 2000 spheres)\n"
    "  -s STRUCT.ma    structured medial mesh (Q-MAT .ma, e.g. 15-30 spheres)\n"
    "  -o PREFIX       writes PREFIX.seg (one label per face, PSB format) and PREFIX.ply\n"
    "                  (faces coloured by part)\n"
    "  -g DELTA0       growing threshold (default 0.015)\n"
    "  -n ETA          minimal region, fraction of the base MAT's spheres (default 0.002)\n"
    "  --json          print one JSON object: parts, face_counts, seconds per stage\n";

double
parseNumber(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    throw segmat::Error("option " + option + ": '" + text + "' is not a number");
  return value;
}

double
secondsSince(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - start).count();
  start = now;
  return s;
}

} // namespace

int
main(int argc, char** argv)
{
  std::string mesh_path, base_path, structured_path, prefix;
  bool json = false;
  segmat::MeshSegmentation segmentation;
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
      else if (arg == "--json")
        json = true;
      else if (!arg.empty() && arg[0] == '-')
        throw segmat::Error("unknown option " + arg);
      else if (mesh_path.empty())
        mesh_path = arg;
      else
        throw segmat::Error("unexpected argument " + arg);
    }
    if (mesh_path.empty() || base_path.empty() || structured_path.empty() || prefix.empty())
      throw segmat::Error("MESH, -b, -s and -o are required");
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
    base = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(base_path));
    structured = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(structured_path));
    if (mesh->empty())
      throw segmat::Error(mesh_path, 0, "the mesh has no faces");
    if (base->empty())
      throw segmat::Error(base_path, 0, "the base medial mesh has no spheres");
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_mesh: " << e.what() << "\n";
    return 2;
  }
  const double load_seconds = secondsSince(start);

  try {
    segmentation.setInputMesh(mesh);
    segmentation.setBaseMat(base);
    segmentation.setStructuredMat(structured);
    std::vector<int> labels;
    if (!segmentation.segment(labels))
      throw segmat::Error(mesh_path, 0, "segmentation failed");
    secondsSince(start);
    segmat::io::saveSeg(prefix + ".seg", labels);
    segmat::io::saveColoredMeshPly(prefix + ".ply", *mesh, labels);
    const double write_seconds = secondsSince(start);

    std::vector<pcl::PointIndices> parts;
    segmentation.getParts(parts);
    std::vector<std::pair<std::string, double>> seconds{{"load", load_seconds}};
    for (const auto& stage : segmentation.getStageSeconds())
      seconds.push_back(stage);
    seconds.emplace_back("write", write_seconds);

    if (json) {
      std::printf("{\"parts\": %zu, \"face_counts\": [", parts.size());
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
      std::printf("\nwrote %s.seg and %s.ply\n", prefix.c_str(), prefix.c_str());
    }
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
