/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_mesh_segmentation: wall-clock seconds of each stage of MeshSegmentation on one shape
 * (default: teddy with the authors' MATs), medians over repetitions, one thread.
 *
 *   build/bin/bench_mesh_segmentation [MESH BASE.ma STRUCTURED.ma] [-r REPETITIONS]
 * Run from the repository root (the default paths are data/teddy/...).
 */
#include "bench_common.h"

#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>
#include <vector>

using segmat::bench::median;

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  std::string mesh_path = "data/teddy/teddy.off", base_path = "data/teddy/teddy_mat.ma",
              structured_path = "data/teddy/teddy_smat.ma";
  int repetitions = 7;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-r" && i + 1 < argc)
      repetitions = std::max(1, std::atoi(argv[++i]));
    else
      positional.push_back(arg);
  }
  if (positional.size() == 3) {
    mesh_path = positional[0];
    base_path = positional[1];
    structured_path = positional[2];
  }
  else if (!positional.empty()) {
    std::fprintf(stderr, "usage: bench_mesh_segmentation [MESH BASE.ma STRUCTURED.ma] [-r N]\n");
    return 2;
  }

  std::vector<std::string> order{"load"};
  std::map<std::string, std::vector<double>> seconds;
  std::vector<double> totals, reruns, cpu_totals;
  std::size_t num_parts = 0, num_faces = 0;
  try {
    for (int rep = 0; rep < repetitions; ++rep) {
      auto start = std::chrono::steady_clock::now();
      auto mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadMesh(mesh_path));
      auto base = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(base_path));
      auto structured = std::make_shared<segmat::MedialMesh>(segmat::io::loadMa(structured_path));
      seconds["load"].push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

      segmat::MeshSegmentation segmentation;
      segmentation.setInputMesh(mesh);
      segmentation.setBaseMat(base);
      segmentation.setStructuredMat(structured);
      std::vector<int> labels;
      start = std::chrono::steady_clock::now();
      const std::clock_t cpu_start = std::clock();
      if (!segmentation.segment(labels)) {
        std::fprintf(stderr, "segmentation failed\n");
        return 1;
      }
      cpu_totals.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
      totals.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      for (const auto& stage : segmentation.getStageSeconds()) {
        if (rep == 0)
          order.push_back(stage.name);
        seconds[stage.name].push_back(stage.seconds);
      }
      std::vector<pcl::PointIndices> parts;
      segmentation.getParts(parts);
      num_parts = parts.size();
      num_faces = labels.size();

      // Re-run with another δ0: the field (graph, tags, face graph) is reused.
      segmentation.setGrowingThreshold(0.02);
      start = std::chrono::steady_clock::now();
      segmentation.segment(labels);
      reruns.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  }
  catch (const std::exception& e) {
    std::fprintf(stderr, "bench_mesh_segmentation: %s\n", e.what());
    return 1;
  }

  std::printf("%s: %zu faces, %zu parts; median of %d runs, OMP_NUM_THREADS=%s\n",
              mesh_path.c_str(), num_faces, num_parts, repetitions, std::getenv("OMP_NUM_THREADS"));
  for (const std::string& stage : order)
    std::printf("  %-12s %8.4f s\n", stage.c_str(), median(seconds[stage]));
  std::printf("  %-12s %8.4f s   (graph + tags + grow_merge + transfer, MATs given)\n",
              "segment", median(totals));
  std::printf("  %-12s %8.4f s   (process CPU time of segment(); wall times above are inflated\n"
              "                          when other processes share the cores)\n",
              "segment CPU", median(cpu_totals));
  std::printf("  %-12s %8.4f s   (segment() again with another delta0: field reused)\n",
              "re-segment", median(reruns));
  return 0;
}
