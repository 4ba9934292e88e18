/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Cloud-path quality on PSB meshes: each mesh is sampled area-uniformly (20k points by default,
 * fixed seed), every point takes the label its source face has in each human segmentation, and
 * CloudSegmentation's point labels are scored with the point Rand index (reported as 1 − RI,
 * over point pairs, textbook divisor n(n−1)/2), averaged over humans, then over models. Three
 * conditions: (a) true normals (face normals), (b) no normals (estimated and oriented),
 * (c) Gaussian noise of sigma = 0.5 % of the bounding-box diagonal, no normals.
 *
 * Usage: bench_cloud_psb [PSB_DIR] [--points N] [--models 1,6,...] [--json] [--conditions abc]
 *        [--meso-skeleton] [--samples N] [--smoothing N] [--keep-inside] [--reference-crease]
 *        [--noise-seeds N] [--first-noise-seed S] [--dump DIR] [--no-visibility]
 *        [--eta F] [--omega F]
 *   PSB_DIR defaults to ../shared/data/psb-dev (off/N.off, seg/Benchmark/N/N_k.seg).
 *   --dump DIR writes DIR/<model>_<a|b|c>.txt: "x y z label truth nx ny nz" per point (the
 *   cloud as segmented, our label, the first human's label, the sample's true normal).
 *   --noise-seeds N scores condition (c) as the mean over N noise draws (default 1): one noisy
 *   cloud's parts change with the draw by tenths of RI per model. --first-noise-seed S draws
 *   with seeds S, S + 1, ... instead of 2, 3, ... (held-out draws for a setting chosen on those).
 *   --no-visibility merges parts without the ball-union visibility test (setVisibilityFlag).
 *   --eta F / --omega F set the minimal region fraction η / the transfer smoothness ω
 *   (setMinRegionFraction / setSmoothnessWeight; defaults: the library's).
 *   --keep-inside keeps Q-MAT's merged centres inside the surface.
 */
// The test sampler is compiled in (bench programs link only the library).
#include "../tests/util/cloud_sampler.cpp"
#include "cloud_run.h"

#include <segmat/common/error.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using segmat::test::SampledCloud;

using segmat::test::randIndexError;

const char* kCategories[] = {"Human", "Cup",      "Glasses", "Airplane", "Ant",
                             "Chair", "Octopus",  "Table",   "Teddy",    "Hand",
                             "Plier", "Fish",     "Bird",    "Spring",   "Armadillo",
                             "Bust",  "Mech",     "Bearing", "Vase",     "FourLeg"};

struct Result
{
  double ri = 0;
  int parts = 0;
  double seconds = 0;
};

/// Settings from the command line (defaults: the library's).
struct Settings
{
  segmat::bench::CloudRunSettings run; ///< how each cloud is segmented (normals: per condition)
  int noise_seeds = 1;  ///< condition (c): noise draws averaged
  int first_noise_seed = 2; ///< condition (c): seed of the first draw
  std::string dump_dir; ///< when set: one point file per model and condition (see Usage)
};

Result
run(const SampledCloud& sampled, bool normals, const std::vector<std::vector<int>>& truths,
    const Settings& settings, const std::string& dump_name)
{
  segmat::bench::CloudRunSettings how = settings.run;
  how.normals = normals;
  const segmat::bench::CloudRun segmented = segmat::bench::segmentSampledCloud(sampled, how);
  Result r;
  r.seconds = segmented.seconds;
  r.parts = segmented.parts;
  const std::vector<int>& labels = segmented.labels;
  for (const auto& truth : truths)
    r.ri += randIndexError(labels, truth);
  if (!settings.dump_dir.empty()) {
    std::ofstream out(settings.dump_dir + "/" + dump_name + ".txt");
    out.precision(9); // floats round-trip: segmat_cloud on x y z reproduces the bench's run
    for (std::size_t i = 0; i < sampled.size(); ++i)
      out << sampled.points[i].x() << ' ' << sampled.points[i].y() << ' ' << sampled.points[i].z()
          << ' ' << labels[i] << ' ' << truths[0][i] << ' ' << sampled.normals[i].x() << ' '
          << sampled.normals[i].y() << ' ' << sampled.normals[i].z() << '\n';
  }
  r.ri /= double(truths.size());
  return r;
}

/// Condition (c): the mean over settings.noise_seeds noise draws (seeds 2, 3, ... unless
/// --first-noise-seed says otherwise); a noisy
/// cloud's parts change with the draw, so one draw says less than the mean of a few.
Result
runNoisy(const SampledCloud& clean, const std::vector<std::vector<int>>& truths,
         const Settings& settings, const std::string& dump_name)
{
  Result mean;
  for (int s = 0; s < settings.noise_seeds; ++s) {
    SampledCloud noisy = clean;
    segmat::test::addGaussianNoise(noisy, 0.005, settings.first_noise_seed + s);
    Settings once = settings;
    if (s > 0)
      once.dump_dir.clear(); // the first draw is the one dumped
    const Result r = run(noisy, false, truths, once, dump_name);
    mean.ri += r.ri / settings.noise_seeds;
    mean.parts += r.parts;
    mean.seconds += r.seconds / settings.noise_seeds;
  }
  mean.parts = (mean.parts + settings.noise_seeds / 2) / settings.noise_seeds;
  return mean;
}

} // namespace

int
main(int argc, char** argv)
{
  std::string dir = "../shared/data/psb-dev";
  std::size_t points = 20000;
  bool json = false;
  std::vector<int> only;
  Settings settings;
  std::string conditions = "abc";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points" && i + 1 < argc)
      points = std::stoul(argv[++i]);
    else if (arg == "--models" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');)
        only.push_back(std::stoi(item));
    }
    else if (arg == "--json")
      json = true;
    else if (arg == "--meso-skeleton")
      settings.run.meso_skeleton = true;
    else if (arg == "--samples" && i + 1 < argc)
      settings.run.samples = std::stol(argv[++i]);
    else if (arg == "--keep-inside")
      settings.run.keep_inside = true;
    else if (arg == "--reference-crease")
      settings.run.reference_crease = true;
    else if (arg == "--smoothing" && i + 1 < argc)
      settings.run.smoothing = std::stoi(argv[++i]);
    else if (arg == "--noise-seeds" && i + 1 < argc)
      settings.noise_seeds = std::max(1, std::stoi(argv[++i]));
    else if (arg == "--first-noise-seed" && i + 1 < argc)
      settings.first_noise_seed = std::stoi(argv[++i]);
    else if (arg == "--eta" && i + 1 < argc)
      settings.run.eta = std::stod(argv[++i]);
    else if (arg == "--omega" && i + 1 < argc)
      settings.run.omega = std::stod(argv[++i]);
    else if (arg == "--no-visibility")
      settings.run.visibility = false;
    else if (arg == "--dump" && i + 1 < argc)
      settings.dump_dir = argv[++i];
    else if (arg == "--conditions" && i + 1 < argc)
      conditions = argv[++i];
    else if (!arg.empty() && arg[0] != '-')
      dir = arg;
    else {
      std::cerr << "usage: bench_cloud_psb [PSB_DIR] [--points N] [--models 1,6] [--json] "
                   "[--conditions abc] [--meso-skeleton] [--samples N] [--smoothing N] [--keep-inside] "
                   "[--reference-crease] [--noise-seeds N] [--first-noise-seed S] [--dump DIR] [--no-visibility] [--eta F] [--omega F]\n";
      return 2;
    }
  }
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);

  std::vector<int> models;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/off")) {
    const int id = std::atoi(entry.path().stem().string().c_str());
    if (id > 0 && (only.empty() || std::find(only.begin(), only.end(), id) != only.end()))
      models.push_back(id);
  }
  std::sort(models.begin(), models.end());
  if (models.empty()) {
    std::cerr << "bench_cloud_psb: no model in " << dir << "/off\n";
    return 1;
  }

  const char* names[3] = {"true_normals", "no_normals", "noise_0.5pct"};
  std::map<int, std::vector<std::vector<Result>>> by_category; // category → condition → results
  std::ostringstream rows;
  std::vector<std::vector<Result>> all(3);
  try {
    for (int id : models) {
      const std::string stem = std::to_string(id);
      const segmat::TriangleMesh mesh = segmat::io::loadOff(dir + "/off/" + stem + ".off");
      const SampledCloud clean = segmat::test::sampleMesh(mesh, points, 1);
      std::vector<std::vector<int>> truths;
      for (int k = 0;; ++k) {
        const std::string path =
            dir + "/seg/Benchmark/" + stem + "/" + stem + "_" + std::to_string(k) + ".seg";
        if (!std::filesystem::exists(path))
          break;
        truths.push_back(clean.pointLabels(segmat::io::loadSeg(path, long(mesh.numFaces()))));
      }
      if (truths.empty())
        continue;
      // Conditions left out by --conditions score as 0 with 0 parts.
      auto wanted = [&](char c) { return conditions.find(c) != std::string::npos; };
      const Result r[3] = {
          wanted('a') ? run(clean, true, truths, settings, stem + "_a")
                      : Result(),
          wanted('b') ? run(clean, false, truths, settings, stem + "_b") : Result(),
          wanted('c') ? runNoisy(clean, truths, settings, stem + "_c") : Result()};
      const int category = (id - 1) / 20;
      auto& cat = by_category[category];
      cat.resize(3);
      char line[256];
      std::snprintf(line, sizeof line, "| %d | %s | %.4f | %.4f | %.4f | %d/%d/%d | %.2f/%.2f/%.2f |\n",
                    id, kCategories[category], r[0].ri, r[1].ri, r[2].ri, r[0].parts, r[1].parts,
                    r[2].parts, r[0].seconds, r[1].seconds, r[2].seconds);
      rows << line;
      for (int c = 0; c < 3; ++c) {
        cat[c].push_back(r[c]);
        all[c].push_back(r[c]);
      }
      if (!json)
        std::cerr << line;
    }
  }
  catch (const segmat::Error& e) {
    std::cerr << "bench_cloud_psb: " << e.what() << "\n";
    return 1;
  }
  auto mean = [](const std::vector<Result>& v, auto field) {
    double s = 0;
    for (const Result& r : v)
      s += field(r);
    return v.empty() ? 0.0 : s / double(v.size());
  };
  auto ri = [](const Result& r) { return r.ri; };
  auto secs = [](const Result& r) { return r.seconds; };
  auto nparts = [](const Result& r) { return double(r.parts); };
  if (json) {
    std::cout << "{\"points\": " << points << ", \"models\": " << all[0].size();
    for (int c = 0; c < 3; ++c)
      std::cout << ", \"" << names[c] << "\": {\"RI\": " << mean(all[c], ri)
                << ", \"parts\": " << mean(all[c], nparts) << ", \"seconds\": " << mean(all[c], secs)
                << "}";
    std::cout << ", \"categories\": {";
    bool first = true;
    for (const auto& kv : by_category) {
      std::cout << (first ? "" : ", ") << "\"" << kCategories[kv.first] << "\": ["
                << mean(kv.second[0], ri) << ", " << mean(kv.second[1], ri) << ", "
                << mean(kv.second[2], ri) << "]";
      first = false;
    }
    std::cout << "}}\n";
    return 0;
  }
  std::cout << "Point 1 − Rand index, " << points << " points per model, " << all[0].size()
            << " models (mean over humans, then models)\n\n";
  std::cout << "| model | category | RI true normals | RI no normals | RI noise 0.5 % | parts a/b/c | seconds a/b/c |\n|---|---|---|---|---|---|---|\n"
            << rows.str();
  std::cout << "\n| category | models | RI true normals | RI no normals | RI noise 0.5 % |\n|---|---|---|---|---|\n";
  for (const auto& kv : by_category)
    std::printf("| %s | %zu | %.4f | %.4f | %.4f |\n", kCategories[kv.first], kv.second[0].size(),
                mean(kv.second[0], ri), mean(kv.second[1], ri), mean(kv.second[2], ri));
  std::printf("| **all** | %zu | **%.4f** | **%.4f** | **%.4f** |\n", all[0].size(),
              mean(all[0], ri), mean(all[1], ri), mean(all[2], ri));
  std::printf("\nmean parts a/b/c: %.1f / %.1f / %.1f; mean seconds a/b/c: %.2f / %.2f / %.2f\n",
              mean(all[0], nparts), mean(all[1], nparts), mean(all[2], nparts), mean(all[0], secs),
              mean(all[1], secs), mean(all[2], secs));
  return 0;
}
