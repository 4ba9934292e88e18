/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_noise: segmentation quality and time under Gaussian noise, for meshes and for clouds.
 *
 * Meshes: every vertex moves by Gaussian noise of sigma = LEVEL × the bounding-box diagonal
 * (faces kept, so the human segmentations still apply); the face labels are scored on the clean
 * mesh with the PSB metrics (1 − RI, mean over humans, then shapes), as scripts/eval_psb.sh does.
 * Clouds: 20 k points sampled area-uniformly from the clean mesh (seed 1), moved by the same
 * noise, segmented without normals; each point takes its source face's human labels and the
 * labels are scored with the point Rand index.
 * The noise is deterministic: the draw of shape N at level L uses seed N × 1000 + L × 10000
 * (+ --seed-offset), with the project's own normal deviates (tests/util/cloud_sampler).
 *
 *   build/bin/bench_noise [PSB_DIR] [--kind mesh|cloud] [--levels 0,0.2,0.5,1]
 *                         [--models 1,21,...|--half tune|check] [--points N] [--seed-offset K]
 *                         [--draws K] [--noise-draws K] [--input-axes] [--write DIR]
 *                         [--subdivide K] [--full-cut N]
 * --draws K (meshes) segments each noisy mesh K times, with jitter seeds 0..K-1
 * (MeshSegmentation::setJitterSeed), and averages: single draws differ by more than many changes
 * one would want to measure (docs/robustness.md). --noise-draws K (meshes and clouds) draws the
 * noise K times (σ > 0), draw k with seed offset --seed-offset + 4k, and averages over them too:
 * one noise draw moves a half of psb-dev by about 0.01 (docs/noise.md). --input-axes segments
 * meshes in their own
 * orientation (MeshSegmentation::setPrincipalAxesFrame(false)). --subdivide K splits every
 * triangle into four at its edges' midpoints, K times, before the noise (the same surface with
 * 4^K times the faces, each face with its parent's human labels: a scan-sized mesh), and
 * --full-cut N sets MeshSegmentation::setMaxFullCutElements (0: every face cut at once).
 * PSB_DIR defaults to ../shared/data/psb-dev. Levels are in percent of the diagonal. --half tune
 * takes ids 1, 21, 41, ... (id mod 20 = 1), --half check ids 6, 26, 46, ... --write DIR writes
 * the noisy meshes as DIR/LEVEL/off/N.off (the input of segmat_mesh or scripts/eval_psb.sh),
 * and the noisy clouds as DIR/LEVEL/xyz/N.xyz (x y z per line, the input of segmat_cloud).
 * Two options for clouds measure what denoising leaves (docs/noise.md, "Limits"):
 * --surface-error adds two columns: the median distance of the smoothed working points
 * (CloudPreprocessing, as the segmentation computes them) to the clean mesh, and their remaining
 * σ̂, both in % of the diagonal; --true-surface moves every noisy point onto the nearest point
 * of the clean mesh before segmenting, which is what a perfect denoiser would hand on.
 * --normals gives every cloud point the normal of the face it was sampled from (outward; the
 * noise moves the point and leaves its normal), as a scanner or a CAD sampler would, and the
 * segmentation reads them (CloudSegmentation::setUseInputNormalsFlag(true)).
 * Prints one row per shape and level on stderr, then a table per level: 1 − RI, parts per
 * shape, structured-MAT spheres per shape (with the clean level in the run, also how many
 * shapes' structured MATs grew to over 1.5 times their clean size), median and max seconds per
 * shape (one thread, segmentation from the file's geometry),
 * with several runs per shape the 1 − RI between two runs of the same shape (the mean over its
 * pairs of runs, then over the shapes: how much its parts change from one noise or jitter draw
 * to the next, whatever the humans say), and a table of each stage's median seconds per level
 * (the segmentation's getStageSeconds()).
 */
// The test sampler is compiled in (bench programs link only the library).
#include "../tests/util/cloud_sampler.cpp"
#include "bench_common.h"
#include "cloud_run.h"

#include <segmat/common/error.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/geometry/mesh_distance.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>
#include <segmat/medial/cloud_preprocessing.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Result
{
  double ri = 0.0;
  int parts = 0;
  int structured = 0; ///< spheres of the structured MAT (0 without one)
  int shape = 0;      ///< PSB id
  double seconds = 0.0;
  int draw = 0;                ///< noise draw × jitter draws + jitter draw
  double surface_error = 0.0;  ///< clouds, --surface-error: median distance, % of the diagonal
  double remaining_sigma = 0.0; ///< clouds, --surface-error: remaining σ̂, % of the diagonal
  segmat::StageTimings stages; ///< the segmentation's own stage times
  std::vector<int> labels;     ///< per face (meshes) or per sampled point (clouds)
};

std::vector<double>
parseList(const std::string& text)
{
  std::vector<double> values;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');)
    values.push_back(std::stod(item));
  return values;
}

Result
segmentMesh(const segmat::TriangleMesh& clean, double level, std::uint32_t seed, std::uint32_t draw,
            bool principal_axes, long full_cut, const std::vector<std::vector<int>>& humans,
            const std::string& write_path)
{
  auto input = std::make_shared<segmat::TriangleMesh>(clean);
  if (level > 0.0)
    segmat::test::addGaussianNoise(*input, level / 100.0, seed);
  if (!write_path.empty()) {
    std::filesystem::create_directories(std::filesystem::path(write_path).parent_path());
    segmat::io::saveOff(write_path, *input);
  }
  segmat::MeshSegmentation seg;
  seg.setInputMesh(input);
  seg.setNumberOfThreads(1);
  seg.setJitterSeed(draw);
  seg.setPrincipalAxesFrame(principal_axes);
  if (full_cut >= 0)
    seg.setMaxFullCutElements(std::size_t(full_cut));
  std::vector<int> labels;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = seg.segment(labels);
  Result r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.stages = seg.getStageSeconds();
  r.structured = seg.getStructuredMat() ? int(seg.getStructuredMat()->numVertices()) : 0;
  if (!ok)
    labels.assign(clean.numFaces(), 0);
  r.parts = int(std::set<int>(labels.begin(), labels.end()).size());
  r.labels = labels;
  const segmat::PsbEvaluator evaluator(clean);
  for (const auto& human : humans) {
    segmat::PsbScores scores;
    if (!evaluator.score(labels, human, scores))
      throw segmat::Error("cannot score a segmentation of this mesh");
    r.ri += scores.RI / double(humans.size());
  }
  return r;
}

/// What --surface-error and --true-surface compare against: the clean mesh.
struct TrueSurface
{
  const segmat::MeshDistance* distance = nullptr; ///< null: neither option
  double diagonal = 1.0;
  bool project = false; ///< --true-surface
  bool measure = false; ///< --surface-error
};

/// Median distance of the working points that CloudPreprocessing makes of \a cloud (normals
/// estimated, as in the segmentation) to the true surface, in % of the diagonal; its remaining
/// σ̂ in the same unit goes to \a remaining_sigma.
double
workingSurfaceError(const segmat::test::SampledCloud& cloud, const TrueSurface& truth,
                    double& remaining_sigma)
{
  segmat::CloudPreprocessing preprocessing;
  preprocessing.setInputCloud(cloud.toPointNormal());
  preprocessing.setUseInputNormalsFlag(false);
  preprocessing.setNumberOfThreads(1);
  pcl::PointCloud<pcl::PointNormal> working;
  if (!preprocessing.compute(working))
    throw segmat::Error("cannot preprocess a noisy cloud");
  remaining_sigma = 100.0 * preprocessing.getRemainingNoise() / truth.diagonal;
  std::vector<double> distances;
  for (const auto& p : working)
    distances.push_back(truth.distance->distance(p.getVector3fMap().cast<double>()));
  return 100.0 * segmat::bench::median(distances) / truth.diagonal;
}

Result
segmentCloud(const segmat::test::SampledCloud& clean, double level, std::uint32_t seed,
             const std::vector<std::vector<int>>& humans, const std::string& write_path,
             const TrueSurface& truth, bool normals)
{
  segmat::test::SampledCloud noisy = clean;
  if (level > 0.0)
    segmat::test::addGaussianNoise(noisy, level / 100.0, seed);
  double surface_error = 0.0, remaining_sigma = 0.0;
  if (truth.measure)
    surface_error = workingSurfaceError(noisy, truth, remaining_sigma);
  if (truth.project)
    for (Eigen::Vector3f& p : noisy.points) {
      Eigen::Vector3d nearest;
      truth.distance->distance(p.cast<double>(), &nearest);
      p = nearest.cast<float>();
    }
  if (!write_path.empty()) {
    std::filesystem::create_directories(std::filesystem::path(write_path).parent_path());
    segmat::io::writeFileAtomically(write_path, [&](std::ostream& out) {
      char line[96];
      for (const Eigen::Vector3f& p : noisy.points) {
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
        out << line;
      }
    });
  }
  segmat::bench::CloudRunSettings settings;
  settings.normals = normals;
  const segmat::bench::CloudRun run = segmat::bench::segmentSampledCloud(noisy, settings);
  Result r;
  r.seconds = run.seconds;
  r.stages = run.stages;
  r.parts = run.parts;
  r.structured = run.structured_spheres;
  r.surface_error = surface_error;
  r.remaining_sigma = remaining_sigma;
  const std::vector<int>& labels = run.labels;
  r.labels = labels;
  for (const auto& human : humans)
    r.ri += segmat::test::randIndexError(labels, clean.pointLabels(human)) / double(humans.size());
  return r;
}

/// Median seconds of each stage per level: where the time of a noisy input goes.
void
printStageTable(const std::vector<double>& levels, const std::vector<std::vector<Result>>& results)
{
  std::vector<std::string> names; // in pipeline order, as the first run reports them
  for (const auto& level : results)
    for (const Result& r : level)
      for (const segmat::StageTiming& stage : r.stages)
        if (std::find(names.begin(), names.end(), stage.name) == names.end())
          names.push_back(stage.name);
  if (names.empty())
    return;
  std::printf("\nMedian seconds per stage (each stage's median over the level's runs):\n\n"
              "| noise sigma (%% of diagonal) |");
  for (const std::string& name : names)
    std::printf(" %s |", name.c_str());
  std::printf("\n|---|");
  for (std::size_t k = 0; k < names.size(); ++k)
    std::printf("---|");
  std::printf("\n");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    std::printf("| %g |", levels[l]);
    for (const std::string& name : names) {
      std::vector<double> seconds;
      for (const Result& r : results[l]) {
        double sum = 0.0; // a stage may be reported in parts (the clouds' retried medial axis)
        for (const segmat::StageTiming& stage : r.stages)
          if (stage.name == name)
            sum += stage.seconds;
        seconds.push_back(sum);
      }
      std::printf(" %.3f |", seconds.empty() ? 0.0 : segmat::bench::median(seconds));
    }
    std::printf("\n");
  }
}

} // namespace

int
main(int argc, char** argv)
{
  std::string dir = "../shared/data/psb-dev", kind = "mesh", write_dir, half;
  std::vector<double> levels = {0.0, 0.2, 0.5, 1.0};
  std::vector<int> only;
  std::size_t points = 20000;
  std::uint32_t seed_offset = 0;
  int draws = 1, noise_draws = 1, repeat = 1, subdivisions = 0;
  long full_cut = -1; // the library's default
  bool principal_axes = true, normals = false;
  TrueSurface truth;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--kind" && has_value)
      kind = argv[++i];
    else if (arg == "--levels" && has_value)
      levels = parseList(argv[++i]);
    else if (arg == "--models" && has_value)
      for (double id : parseList(argv[++i]))
        only.push_back(int(id));
    else if (arg == "--half" && has_value)
      half = argv[++i];
    else if (arg == "--points" && has_value)
      points = std::stoul(argv[++i]);
    else if (arg == "--seed-offset" && has_value)
      seed_offset = std::uint32_t(std::stoul(argv[++i]));
    else if (arg == "--input-axes")
      principal_axes = false;
    else if (arg == "--true-surface")
      truth.project = true;
    else if (arg == "--surface-error")
      truth.measure = true;
    else if (arg == "--normals")
      normals = true;
    else if (arg == "--draws" && has_value)
      draws = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--noise-draws" && has_value)
      noise_draws = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--subdivide" && has_value)
      subdivisions = std::max(0, std::atoi(argv[++i]));
    else if (arg == "--full-cut" && has_value)
      full_cut = std::max(0L, std::atol(argv[++i]));
    else if (arg == "--repeat" && has_value)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--write" && has_value)
      write_dir = argv[++i];
    else if (!arg.empty() && arg[0] != '-')
      dir = arg;
    else {
      std::cerr << "usage: bench_noise [PSB_DIR] [--kind mesh|cloud] [--levels 0,0.2,0.5,1] "
                   "[--models 1,21,...|--half tune|check] [--points N] [--seed-offset K] "
                   "[--draws K] [--noise-draws K] [--repeat R] [--input-axes] [--write DIR] "
                   "[--surface-error] [--true-surface] [--normals] [--subdivide K] "
                   "[--full-cut N]\n";
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
  }
  if ((kind != "mesh" && kind != "cloud") || (!half.empty() && half != "tune" && half != "check") ||
      (draws > 1 && kind != "mesh") || (noise_draws > 1 && !write_dir.empty()) ||
      ((truth.project || truth.measure || normals) && kind != "cloud") ||
      ((subdivisions > 0 || full_cut >= 0) && kind != "mesh")) {
    std::cerr << "bench_noise: --kind is mesh or cloud, --half is tune or check, --draws is for "
                 "meshes, --write takes one noise draw, --surface-error, --true-surface and "
                 "--normals are for clouds, --subdivide and --full-cut for meshes\n";
    return 2;
  }
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);

  std::vector<int> models;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/off")) {
    const int id = std::atoi(entry.path().stem().string().c_str());
    const bool in_half = half.empty() || (half == "tune" ? id % 20 == 1 : id % 20 == 6);
    if (id > 0 && in_half && (only.empty() || std::count(only.begin(), only.end(), id)))
      models.push_back(id);
  }
  std::sort(models.begin(), models.end());
  if (models.empty()) {
    std::cerr << "bench_noise: no model in " << dir << "/off\n";
    return 1;
  }

  std::vector<std::vector<Result>> results(levels.size());
  // Per level, each shape's mean 1 − RI between two of its runs: how much the parts change from
  // one scan (noise draw, jitter draw) of the same shape to the next.
  std::vector<std::vector<double>> between(levels.size());
  std::size_t scored = 0; // shapes with human segmentations
  try {
    for (int id : models) {
      const std::string stem = std::to_string(id);
      segmat::TriangleMesh mesh = segmat::io::loadOff(dir + "/off/" + stem + ".off");
      std::vector<std::vector<int>> humans;
      for (int k = 0;; ++k) {
        const std::string path =
            dir + "/seg/Benchmark/" + stem + "/" + stem + "_" + std::to_string(k) + ".seg";
        if (!std::filesystem::exists(path))
          break;
        humans.push_back(segmat::io::loadSeg(path, long(mesh.numFaces())));
      }
      if (humans.empty())
        continue;
      // The same surface with 4^K times the faces; each face keeps its parent's human labels.
      for (int k = 0; k < subdivisions; ++k) {
        const std::size_t parents = mesh.numFaces();
        mesh = segmat::bench::subdivided(mesh);
        for (std::vector<int>& human : humans) {
          std::vector<int> finer(mesh.numFaces());
          for (std::size_t f = 0; f < finer.size(); ++f)
            finer[f] = human[f % parents];
          human.swap(finer);
        }
      }
      ++scored;
      std::unique_ptr<segmat::MeshDistance> distance;
      if (truth.project || truth.measure) {
        distance = std::make_unique<segmat::MeshDistance>(mesh);
        truth.distance = distance.get();
        truth.diagonal = mesh.boundingBoxDiagonal();
      }
      const segmat::test::SampledCloud cloud = kind == "cloud"
                                                   ? segmat::test::sampleMesh(mesh, points, 1)
                                                   : segmat::test::SampledCloud();
      for (std::size_t l = 0; l < levels.size(); ++l) {
        const std::size_t first_run = results[l].size();
        // The clean level has no noise to draw again.
        for (int k = 0; k < (levels[l] > 0.0 ? noise_draws : 1); ++k) {
          const std::uint32_t seed = std::uint32_t(id) * 1000u +
                                     std::uint32_t(levels[l] * 10000.0) + seed_offset +
                                     4u * std::uint32_t(k);
          std::string write_path;
          if (!write_dir.empty()) {
            char level_name[32];
            std::snprintf(level_name, sizeof level_name, "%g", levels[l]);
            write_path = write_dir + "/" + level_name +
                         (kind == "mesh" ? "/off/" + stem + ".off" : "/xyz/" + stem + ".xyz");
          }
          for (int d = 0; d < draws; ++d) {
            // --repeat: the same segmentation R times in a row; its time is their median (the
            // run with the median time gives the stages), so that one slow moment of the
            // machine does not move it. The labels must come out the same every time.
            std::vector<Result> repeats;
            for (int t = 0; t < repeat; ++t) {
              repeats.push_back(kind == "mesh" ? segmentMesh(mesh, levels[l], seed,
                                                             std::uint32_t(d), principal_axes,
                                                             full_cut, humans,
                                                             t == 0 ? write_path : "")
                                               : segmentCloud(cloud, levels[l], seed, humans,
                                                              t == 0 ? write_path : "", truth,
                                                              normals));
              if (repeats.back().labels != repeats.front().labels)
                throw segmat::Error("shape " + stem +
                                    ": a repeated segmentation gave other labels");
            }
            std::sort(repeats.begin(), repeats.end(),
                      [](const Result& a, const Result& b) { return a.seconds < b.seconds; });
            Result r = std::move(repeats[repeats.size() / 2]);
            r.draw = k * draws + d;
            r.shape = id;
            results[l].push_back(r);
            std::fprintf(stderr,
                         "%s %d sigma %g%% draw %d: 1-RI %.4f, %d parts, %.2f s, %d structured "
                         "spheres\n",
                         kind.c_str(), id, levels[l], r.draw, r.ri, r.parts, r.seconds,
                         r.structured);
          }
        }
        std::vector<Result>& runs = results[l];
        double sum = 0.0;
        int pairs = 0;
        for (std::size_t a = first_run; a < runs.size(); ++a)
          for (std::size_t b = a + 1; b < runs.size(); ++b, ++pairs)
            sum += segmat::test::randIndexError(runs[a].labels, runs[b].labels);
        if (pairs > 0)
          between[l].push_back(sum / pairs);
        for (std::size_t a = first_run; a < runs.size(); ++a)
          std::vector<int>().swap(runs[a].labels); // only the pairs of one shape are compared
      }
    }
  }
  catch (const segmat::Error& e) {
    std::cerr << "bench_noise: " << e.what() << "\n";
    return 1;
  }

  std::printf("%s, %zu shapes%s%s\n\n",
              kind == "mesh" ? "meshes" : normals ? "clouds (with normals)" : "clouds (no normals)",
              scored, half.empty() ? "" : ", half ",
              half.c_str());
  const int runs = draws * noise_draws; // segmentations per shape and level
  if (runs > 1) {
    std::printf("Runs per shape and level: %d noise seed%s (offset %u + 4k)", noise_draws,
                noise_draws > 1 ? "s" : "", seed_offset);
    if (kind == "mesh")
      std::printf(" x %d jitter seed%s (MeshSegmentation::setJitterSeed 0..%d)", draws,
                  draws > 1 ? "s" : "", draws - 1);
    std::printf("; σ = 0 takes one noise seed. Figures are means over the runs; the last column "
                "is each run's 1 - RI.\n\n");
  }
  if (truth.project)
    std::printf("Every noisy point was moved onto the nearest point of the clean mesh before "
                "segmenting (--true-surface).\n\n");
  // The structured MAT should describe the shape, not the noise (docs/noise.md): its size per
  // level, and how many shapes' structured MATs grew to more than 1.5 times their clean one's.
  const auto clean_level = std::find(levels.begin(), levels.end(), 0.0);
  // Per shape, the clean level's mean structured MAT size and seconds.
  std::map<int, double> clean_structured, clean_seconds;
  if (clean_level != levels.end())
    for (const Result& r : results[std::size_t(clean_level - levels.begin())]) {
      clean_structured[r.shape] += r.structured / double(draws);
      clean_seconds[r.shape] += r.seconds / double(draws);
    }
  const bool grown_column = clean_level != levels.end() && levels.size() > 1;
  std::printf("| noise sigma (%% of diagonal) | 1 - RI | parts per shape | structured MAT spheres "
              "per shape |%s median s | max s |%s%s%s%s\n"
              "|---|---|---|---|%s---|---|%s%s%s%s\n",
              grown_column ? " shapes with structured MAT > 1.5 × clean |" : "",
              grown_column ? " s / clean s, median over shapes |" : "",
              runs > 1 ? " 1 - RI between runs |" : "",
              truth.measure ? " smoothed points to true surface, median (% of diagonal) | "
                              "remaining σ̂ (% of diagonal) |"
                            : "",
              runs > 1 ? " 1 - RI per run |" : "", grown_column ? "---|" : "",
              grown_column ? "---|" : "", runs > 1 ? "---|" : "",
              truth.measure ? "---|---|" : "", runs > 1 ? "---|" : "");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    double ri = 0.0, parts = 0.0, structured = 0.0;
    std::vector<double> seconds;
    std::map<int, std::pair<double, int>> shape_structured; // sum and runs per shape
    std::map<int, double> shape_seconds;                    // sum per shape
    for (const Result& r : results[l]) {
      shape_seconds[r.shape] += r.seconds;
      ri += r.ri / double(results[l].size());
      parts += r.parts / double(results[l].size());
      structured += r.structured / double(results[l].size());
      seconds.push_back(r.seconds);
      shape_structured[r.shape].first += r.structured;
      ++shape_structured[r.shape].second;
    }
    std::printf("| %g | %.4f | %.1f | %.1f |", levels[l], ri, parts, structured);
    if (grown_column) {
      int grown = 0;
      for (const auto& [shape, sum_runs] : shape_structured)
        if (sum_runs.first / sum_runs.second > 1.5 * clean_structured[shape])
          ++grown;
      std::printf(" %d |", grown);
    }
    std::printf(" %.2f | %.2f |", segmat::bench::median(seconds),
                *std::max_element(seconds.begin(), seconds.end()));
    if (grown_column) {
      // Each shape's mean seconds over its clean seconds, the median over the shapes. A shape's
      // runs at every level follow each other within seconds, so the machine's speed, which
      // drifts over minutes, cancels in its ratio; it does not in the ratio of two medians,
      // which are times of different shapes taken minutes apart.
      std::vector<double> ratios;
      for (const auto& [shape, sum] : shape_seconds)
        if (clean_seconds[shape] > 0.0)
          ratios.push_back(sum / shape_structured[shape].second / clean_seconds[shape]);
      std::printf(" %.2f |", ratios.empty() ? 0.0 : segmat::bench::median(ratios));
    }
    if (runs > 1) {
      if (between[l].empty())
        std::printf(" – |"); // one run per shape at this level
      else {
        double mean = 0.0;
        for (double d : between[l])
          mean += d / double(between[l].size());
        std::printf(" %.4f |", mean);
      }
    }
    if (truth.measure) {
      double error = 0.0, remaining = 0.0; // means over the runs
      for (const Result& r : results[l]) {
        error += r.surface_error / double(results[l].size());
        remaining += r.remaining_sigma / double(results[l].size());
      }
      std::printf(" %.3f | %.4f |", error, remaining);
    }
    if (runs > 1) {
      const int level_runs = levels[l] > 0.0 ? runs : draws;
      std::vector<double> per_draw(level_runs, 0.0);
      for (const Result& r : results[l])
        per_draw[r.draw] += r.ri * level_runs / double(results[l].size());
      for (int d = 0; d < level_runs; ++d)
        std::printf(" %.4f", per_draw[d]);
      std::printf(" |");
    }
    std::printf("\n");
  }
  printStageTable(levels, results);
  return 0;
}
