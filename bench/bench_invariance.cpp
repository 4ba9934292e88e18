/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_invariance: Rand distance between the parts of each mesh and of its transformed copies
 * (bench/shape_variants.h: translated, scaled, rotated, re-ordered, other file formats), per
 * transformation: mean, largest, and the models whose part count changed.
 *   bench_invariance DIR_OR_MESH... [--threads T] [--input-axes]
 * --input-axes segments in the meshes' own orientation (MeshSegmentation::setPrincipalAxesFrame(false)).
 * A folder contributes its off/ *.off files (a PSB-style folder) or its own files.
 */
#include <segmat/segmentation/mesh_segmentation.h>

#include "bench_args.h"
#include "shape_variants.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace segmat;

int
main(int argc, char** argv)
{
  std::vector<std::string> files;
  unsigned threads = 1;
  bool principal_axes = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--input-axes")
      principal_axes = false;
    else if (arg == "--threads")
      threads = static_cast<unsigned>(std::max(0, bench::intArgument(argc, argv, i)));
    else if (std::filesystem::is_directory(arg + "/off"))
      bench::appendPaths(arg + "/off", files);
    else
      bench::appendPaths(arg, files);
  }
  const auto segment = [&](const TriangleMesh& mesh, std::vector<int>& labels) {
    MeshSegmentation seg;
    seg.setNumberOfThreads(threads);
    seg.setPrincipalAxesFrame(principal_axes);
    seg.setInputMesh(std::make_shared<const TriangleMesh>(mesh));
    return seg.segment(labels);
  };
  const auto parts = [](const std::vector<int>& labels) {
    return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  };
  struct Tally
  {
    double sum = 0, largest = 0;
    int count = 0, identical = 0;
    std::vector<std::string> part_count_changed;
  };
  std::vector<std::string> order;
  std::map<std::string, Tally> tallies;
  const std::string stem =
      (std::filesystem::temp_directory_path() / ("bench_invariance_" + std::to_string(getpid())))
          .string();
  std::printf("%-10s %-12s %-8s %s\n", "model", "variant", "parts", "rand_distance");
  for (const std::string& path : files) {
    const TriangleMesh::Ptr mesh = bench::loadMeshOrSkip(path);
    std::vector<int> reference;
    if (!mesh || !segment(*mesh, reference))
      continue;
    const std::string model = std::filesystem::path(path).stem().string();
    for (const bench::MeshVariant& v : bench::meshVariants(*mesh, stem)) {
      std::vector<int> labels;
      if (!segment(v.mesh, labels))
        labels.assign(mesh->numFaces(), 0);
      labels = v.inOriginalOrder(labels);
      const double d = bench::randDistance(labels, reference);
      if (!tallies.count(v.name))
        order.push_back(v.name);
      Tally& t = tallies[v.name];
      t.sum += d;
      t.largest = std::max(t.largest, d);
      ++t.count;
      t.identical += labels == reference;
      if (parts(labels) != parts(reference))
        t.part_count_changed.push_back(model);
      std::printf("%-10s %-12s %d/%-6d %.6f\n", model.c_str(), v.name.c_str(), parts(labels),
                  parts(reference), d);
      std::fflush(stdout);
    }
  }
  for (const char* ext : {".ply", ".obj", ".stl"})
    std::filesystem::remove(stem + ext);
  std::printf("\n%-12s %-7s %-10s %-10s %-10s %s\n", "variant", "models", "mean_RD", "max_RD",
              "identical", "part count changed");
  for (const std::string& name : order) {
    const Tally& t = tallies[name];
    std::string changed;
    for (const std::string& m : t.part_count_changed)
      changed += (changed.empty() ? "" : ",") + m;
    std::printf("%-12s %-7d %-10.6f %-10.6f %-10d %s\n", name.c_str(), t.count, t.sum / t.count,
                t.largest, t.identical, changed.empty() ? "-" : changed.c_str());
  }
  return 0;
}
