/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_psb_metrics [PSB_DIR]: time of the PSB metrics per model, files already in memory —
 * building the PsbEvaluator (areas, radius, edge graph) and scoring human #0 against every human.
 * Default PSB_DIR: ../shared/data/psb-dev beside the source tree.
 */
#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

int
main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  using Clock = std::chrono::steady_clock;
  // The source path is absolute under CMake: the shared data sit beside the repository.
  const std::string dir = argc > 1 ? std::string(argv[1])
                                   : (fs::path(__FILE__).parent_path().parent_path().parent_path() /
                                      "shared" / "data" / "psb-dev").string();
  std::vector<int> ids;
  for (const auto& entry : fs::directory_iterator(fs::path(dir) / "off"))
    if (entry.path().extension() == ".off")
      ids.push_back(std::stoi(entry.path().stem().string()));
  std::sort(ids.begin(), ids.end());
  std::printf("%-6s %-7s %-7s %-10s %-10s %-10s\n", "model", "faces", "humans", "setup_ms",
              "score_ms", "total_ms");
  double worst = 0.0, sum = 0.0;
  for (int id : ids) {
    const segmat::TriangleMesh mesh = segmat::io::loadOff((fs::path(dir) / "off" /
                                                           (std::to_string(id) + ".off")).string());
    std::vector<std::vector<int>> humans;
    for (const std::string& p : segmat::psbHumanSegmentationPaths(dir, id))
      humans.push_back(segmat::io::loadSeg(p, static_cast<long>(mesh.numFaces())));
    const auto t0 = Clock::now();
    const segmat::PsbEvaluator evaluator(mesh);
    const auto t1 = Clock::now();
    segmat::PsbScores mean;
    evaluator.scoreAgainstAll(humans[0], humans, mean);
    const auto t2 = Clock::now();
    const double setup = std::chrono::duration<double, std::milli>(t1 - t0).count();
    const double score = std::chrono::duration<double, std::milli>(t2 - t1).count();
    std::printf("%-6d %-7zu %-7zu %-10.2f %-10.2f %-10.2f\n", id, mesh.numFaces(), humans.size(),
                setup, score, setup + score);
    worst = std::max(worst, setup + score);
    sum += setup + score;
  }
  std::printf("models %zu, total %.1f ms, slowest %.1f ms\n", ids.size(), sum, worst);
  return 0;
}
