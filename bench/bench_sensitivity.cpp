/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_sensitivity: how the PSB score moves with each parameter (SEG-MAT, Lin et al. 2022, §8).
 * For every psb-dev mesh the medial meshes are computed once (the "mat" stage), then the mesh is
 * segmented again for every setting: α, λ and ω at 85 %..115 % of their defaults in 5 % steps,
 * δ and η over a wider range, and the named detail levels (coarse, fine). MeshSegmentation
 * recomputes nothing but the growing, merging and transfer when only these change, so one MAT
 * serves all settings; the printed seconds show it. Prints, per setting, the mean 1 − RI
 * against the human segmentations and the mean part count, then min / max per parameter.
 *
 *   build/bin/bench_sensitivity [PSB_DIR] [--ids ID,ID,...]
 * PSB_DIR (default ../shared/data/psb-dev) holds off/N.off and seg/Benchmark/N/N_k.seg.
 */
#include "bench_args.h"
#include "bench_common.h"

#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/detail_level.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Setting
{
  std::string parameter; // "alpha", "lambda", "omega", "delta", "eta", "level" or "default"
  double value;          // the parameter's value (for "level": the index in detailLevels())
  std::string label;
};

void
apply(segmat::MeshSegmentation& seg, const Setting& s, const segmat::MeshSegmentation& defaults)
{
  seg.setAngleWeight(defaults.getAngleWeight());
  seg.setPrimitiveWeight(defaults.getPrimitiveWeight());
  seg.setSmoothnessWeight(defaults.getSmoothnessWeight());
  seg.setGrowingThreshold(defaults.getGrowingThreshold());
  seg.setMinRegionFraction(defaults.getMinRegionFraction());
  if (s.parameter == "alpha")
    seg.setAngleWeight(s.value);
  else if (s.parameter == "lambda")
    seg.setPrimitiveWeight(s.value);
  else if (s.parameter == "omega")
    seg.setSmoothnessWeight(s.value);
  else if (s.parameter == "delta")
    seg.setGrowingThreshold(s.value);
  else if (s.parameter == "eta")
    seg.setMinRegionFraction(s.value);
  else if (s.parameter == "level") {
    const segmat::DetailLevel& level = segmat::detailLevels()[static_cast<int>(s.value)];
    seg.setGrowingThreshold(level.growing_threshold);
    seg.setMinRegionFraction(level.min_region_fraction);
  }
}

std::vector<Setting>
settings(const segmat::MeshSegmentation& d)
{
  std::vector<Setting> out{{"default", 0.0, "default"}};
  char buffer[64];
  const std::pair<const char*, double> scaled[] = {{"alpha", d.getAngleWeight()},
                                                    {"lambda", d.getPrimitiveWeight()},
                                                    {"omega", d.getSmoothnessWeight()}};
  for (const auto& [name, value] : scaled)
    for (int percent = -15; percent <= 15; percent += 5)
      if (percent != 0) {
        std::snprintf(buffer, sizeof buffer, "%+d%%", percent);
        out.push_back({name, value * (1.0 + percent / 100.0), buffer});
      }
  for (const double delta : {0.0075, 0.01, 0.0125, 0.02, 0.025, 0.03}) {
    std::snprintf(buffer, sizeof buffer, "%g", delta);
    out.push_back({"delta", delta, buffer});
  }
  for (const double eta : {0.0005, 0.001, 0.004, 0.008}) {
    std::snprintf(buffer, sizeof buffer, "%g", eta);
    out.push_back({"eta", eta, buffer});
  }
  for (std::size_t k = 0; k < segmat::detailLevels().size(); ++k) {
    const segmat::DetailLevel& level = segmat::detailLevels()[k];
    std::snprintf(buffer, sizeof buffer, "%s(%g,%g)", level.name.c_str(), level.growing_threshold,
                  level.min_region_fraction);
    if (level.name != "default")
      out.push_back({"level", static_cast<double>(k), buffer});
  }
  return out;
}

} // namespace

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  std::string dir = "../shared/data/psb-dev";
  std::vector<int> ids;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--ids" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string id; std::getline(list, id, ',');)
        ids.push_back(std::stoi(id));
    }
    else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "usage: bench_sensitivity [PSB_DIR] [--ids ID,ID,...]\n");
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
    else
      dir = arg;
  }
  if (ids.empty())
    for (const auto& entry : std::filesystem::directory_iterator(dir + "/off"))
      if (entry.path().extension() == ".off")
        ids.push_back(std::stoi(entry.path().stem().string()));
  std::sort(ids.begin(), ids.end());

  const segmat::MeshSegmentation defaults;
  const std::vector<Setting> all = settings(defaults);
  std::vector<double> ri_sum(all.size(), 0.0), parts_sum(all.size(), 0.0);
  double mat_seconds = 0.0, segment_seconds = 0.0;
  std::size_t segmentations = 0, shapes = 0;
  using Clock = std::chrono::steady_clock;
  std::printf("%5s %7s %7s %9s %8s\n", "shape", "mat_s", "segs", "seg_s", "1-RI");
  for (const int id : ids) {
    const std::string path = dir + "/off/" + std::to_string(id) + ".off";
    const segmat::TriangleMesh::Ptr mesh = segmat::bench::loadMeshOrSkip(path);
    if (!mesh)
      continue;
    segmat::PsbEvaluator evaluator(*mesh);
    std::vector<std::vector<int>> humans;
    for (const std::string& human : segmat::psbHumanSegmentationPaths(dir, id))
      humans.push_back(segmat::loadLabelsFor(evaluator, human));
    if (humans.empty())
      continue;
    segmat::MeshSegmentation seg;
    seg.setNumberOfThreads(1);
    seg.setInputMesh(mesh);
    double shape_mat = 0.0, shape_segment = 0.0, default_ri = 0.0;
    bool ok = true;
    for (std::size_t s = 0; s < all.size() && ok; ++s) {
      apply(seg, all[s], defaults);
      std::vector<int> labels;
      const auto start = Clock::now();
      ok = seg.segment(labels);
      const double total = std::chrono::duration<double>(Clock::now() - start).count();
      double mat = 0.0;
      for (const auto& stage : seg.getStageSeconds())
        if (stage.name == "mat")
          mat = stage.seconds;
      shape_mat += mat;
      shape_segment += total - mat;
      segmat::PsbScores scores;
      ok = ok && evaluator.scoreAgainstAll(labels, humans, scores);
      int parts = 0;
      for (const int l : labels)
        parts = std::max(parts, l + 1);
      ri_sum[s] += scores.RI;
      parts_sum[s] += parts;
      if (s == 0)
        default_ri = scores.RI;
    }
    if (!ok) {
      std::printf("%5d failed\n", id);
      return 1;
    }
    ++shapes;
    mat_seconds += shape_mat;
    segment_seconds += shape_segment;
    segmentations += all.size();
    std::printf("%5d %7.1f %7zu %9.1f %8.4f\n", id, shape_mat, all.size(), shape_segment,
                default_ri);
    std::fflush(stdout);
  }
  if (shapes == 0)
    return 1;
  std::printf("\n%zu shapes; medial meshes computed %zu times in %.0f s (once per shape), %zu "
              "segmentations in %.0f s (%.2f s each)\n",
              shapes, shapes, mat_seconds, segmentations, segment_seconds,
              segment_seconds / static_cast<double>(segmentations));
  std::printf("\n%-8s %-20s %10s %8s %7s\n", "param", "setting", "value", "1-RI", "parts");
  std::map<std::string, std::pair<double, double>> range;
  std::vector<std::string> order;
  for (std::size_t s = 0; s < all.size(); ++s) {
    const double ri = ri_sum[s] / shapes;
    std::printf("%-8s %-20s %10.5g %8.4f %7.2f\n", all[s].parameter.c_str(), all[s].label.c_str(),
                all[s].parameter == "level" ? 0.0 : all[s].value, ri, parts_sum[s] / shapes);
    for (const std::string& p : {std::string("alpha"), std::string("lambda"), std::string("omega"),
                                 std::string("delta"), std::string("eta")})
      if (all[s].parameter == p || all[s].parameter == "default") {
        if (!range.count(p)) {
          range[p] = {ri, ri};
          order.push_back(p);
        }
        range[p].first = std::min(range[p].first, ri);
        range[p].second = std::max(range[p].second, ri);
      }
  }
  std::printf("\nmin / max mean 1-RI per parameter (default included)\n");
  for (const std::string& p : order)
    std::printf("%-8s %.4f - %.4f\n", p.c_str(), range[p].first, range[p].second);
  return 0;
}
