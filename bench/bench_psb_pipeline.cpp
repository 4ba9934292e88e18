/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_psb_pipeline: wall-clock seconds from a mesh file to its face labels — load, medial meshes
 * (Voronoi MAT + Q-MAT), segmentation, transfer — for every mesh of a folder, one thread, default
 * parameters. Prints per-shape medians over the repetitions, the median over the shapes, and the
 * median over the shapes of each stage.
 *
 *   build/bin/bench_psb_pipeline [DIR|MESH...] [-r REPETITIONS] [--out PREDDIR]
 * DIR defaults to ../shared/data/psb-dev/off (run from the repository root). With --out, writes
 * PREDDIR/N.seg for every mesh N.off, ready for `segmat_eval --psb PSBDIR --pred PREDDIR`.
 */
#include "bench_args.h"
#include "bench_common.h"

#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using segmat::bench::median;

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  int repetitions = 1;
  std::string out_dir;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-r")
      repetitions = std::max(1, segmat::bench::intArgument(argc, argv, i));
    else if (arg == "--out" && i + 1 < argc)
      out_dir = argv[++i];
    else if (arg == "-h" || arg == "--help" || (!arg.empty() && arg[0] == '-')) {
      std::fprintf(stderr, "usage: bench_psb_pipeline [DIR|MESH...] [-r REPETITIONS] "
                           "[--out PREDDIR]\n");
      return arg[0] == '-' && arg != "-h" && arg != "--help" ? 2 : 0;
    }
    else
      inputs.push_back(arg);
  }
  if (inputs.empty())
    inputs.push_back("../shared/data/psb-dev/off");
  std::vector<std::string> files;
  for (const auto& input : inputs)
    segmat::bench::appendPaths(input, files);
  if (!out_dir.empty())
    std::filesystem::create_directories(out_dir);

  using Clock = std::chrono::steady_clock;
  std::vector<std::string> stage_order{"load"};
  std::map<std::string, std::vector<double>> stage_medians; // per stage: one median per shape
  std::vector<double> shape_medians;
  std::size_t failed = 0;
  std::printf("%-10s %7s %5s %9s %9s\n", "shape", "faces", "parts", "median_s", "mat_s");
  for (const std::string& path : files) {
    std::map<std::string, std::vector<double>> stage_seconds;
    std::vector<double> totals;
    std::vector<int> labels;
    std::size_t faces = 0;
    bool ok = true;
    for (int r = 0; r < repetitions && ok; ++r) {
      const auto start = Clock::now();
      const segmat::TriangleMesh::Ptr mesh = segmat::bench::loadMeshOrSkip(path);
      if (!mesh) {
        ok = false;
        break;
      }
      const double load = std::chrono::duration<double>(Clock::now() - start).count();
      segmat::MeshSegmentation segmentation; // fresh: nothing reused between repetitions
      segmentation.setNumberOfThreads(1);
      segmentation.setInputMesh(mesh);
      ok = segmentation.segment(labels);
      totals.push_back(std::chrono::duration<double>(Clock::now() - start).count());
      faces = mesh->numFaces();
      stage_seconds["load"].push_back(load);
      for (const auto& stage : segmentation.getStageSeconds()) {
        if (std::find(stage_order.begin(), stage_order.end(), stage.name) == stage_order.end())
          stage_order.push_back(stage.name);
        stage_seconds[stage.name].push_back(stage.seconds);
      }
    }
    const std::string name = std::filesystem::path(path).stem().string();
    if (!ok) {
      std::printf("%-10s failed\n", name.c_str());
      ++failed;
      continue;
    }
    int parts = 0;
    for (int l : labels)
      parts = std::max(parts, l + 1);
    shape_medians.push_back(median(totals));
    for (const auto& stage : stage_seconds)
      stage_medians[stage.first].push_back(median(stage.second));
    std::printf("%-10s %7zu %5d %9.3f %9.3f\n", name.c_str(), faces, parts, shape_medians.back(),
                median(stage_seconds["mat"]));
    std::fflush(stdout);
    if (!out_dir.empty())
      segmat::io::saveSeg(out_dir + "/" + name + ".seg", labels);
  }

  std::printf("\n%zu shapes, %zu failed, %d repetition(s), one thread\n", shape_medians.size(),
              failed, repetitions);
  std::printf("median seconds per shape (mesh file -> labels): %.3f\n", median(shape_medians));
  std::printf("per-stage medians over shapes:");
  for (const auto& stage : stage_order)
    std::printf(" %s %.4f", stage.c_str(), median(stage_medians[stage]));
  std::printf("\n");
  if (!out_dir.empty())
    std::printf("wrote %s/N.seg (score: segmat_eval --psb PSBDIR --pred %s)\n", out_dir.c_str(),
                out_dir.c_str());
  return failed ? 1 : 0;
}
