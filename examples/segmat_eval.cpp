/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_eval: Princeton Segmentation Benchmark scores of a segmentation (one mesh) or of a
 * folder of segmentations (a PSB-style folder). Parse, call the library, print.
 */
#include <segmat/common/error.h>
#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/off.h>

#include "option_parser.h"
#include "program_files.h"
#include "progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace segmat::cli;

namespace {

// A positive id written in digits only; -1 otherwise.
long
parseId(const std::string& text)
{
  if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
    return -1;
  const long id = std::stol(text);
  return id >= 1 ? id : -1;
}

// "1,5-20" → {1, 5, 6, ..., 20}; false on anything else.
bool
parseModelList(const std::string& text, std::vector<int>& ids)
{
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const std::string item = text.substr(pos, comma - pos);
    const std::size_t dash = item.find('-');
    const long lo = parseId(item.substr(0, dash));
    const long hi = dash == std::string::npos ? lo : parseId(item.substr(dash + 1));
    if (lo < 0 || hi < lo)
      return false;
    for (long id = lo; id <= hi; ++id)
      ids.push_back(static_cast<int>(id));
    pos = comma + 1;
  }
  return true;
}

std::string
number(double value)
{
  if (std::isnan(value))
    return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string
json(const segmat::PsbScores& s, const char* count_key)
{
  return "{\"RI\": " + number(s.RI) + ", \"CD\": " + number(s.CD) + ", \"GCE\": " +
         number(s.GCE) + ", \"LCE\": " + number(s.LCE) + ", \"HD\": " + number(s.HD) +
         ", \"Rm\": " + number(s.Rm) + ", \"Rf\": " + number(s.Rf) + ", \"GCEf\": " +
         number(s.GCEf) + ", \"LCEf\": " + number(s.LCEf) + ", \"" + count_key +
         "\": " + std::to_string(s.count) + ", \"cd_count\": " + std::to_string(s.cd_count) + "}";
}

const char* const kColumns = "CD        HD        Rm        Rf        RI        GCE       LCE       "
                             "GCEf      LCEf";

std::string
row(const segmat::PsbScores& s)
{
  std::string out;
  char buffer[32];
  for (double v : {s.CD, s.HD, s.Rm, s.Rf, s.RI, s.GCE, s.LCE, s.GCEf, s.LCEf}) {
    if (std::isnan(v))
      std::snprintf(buffer, sizeof buffer, "%-10s", "n/a");
    else
      std::snprintf(buffer, sizeof buffer, "%-10.6f", v);
    out += buffer;
  }
  return out.substr(0, out.find_last_not_of(' ') + 1);
}

int
evaluateOne(const std::string& mesh_path, const std::string& pred_path,
            const std::vector<std::string>& truth_paths, bool as_json)
{
  const segmat::PsbEvaluator evaluator(segmat::io::loadOff(mesh_path));
  if (!evaluator.ready())
    throw segmat::Error(mesh_path, 0,
                        "the mesh cannot be evaluated (no non-degenerate face or zero area)");
  const std::vector<int> prediction = segmat::loadLabelsFor(evaluator, pred_path);
  std::vector<std::vector<int>> truths;
  for (const std::string& path : truth_paths)
    truths.push_back(segmat::loadLabelsFor(evaluator, path));
  segmat::PsbScores mean;
  if (!evaluator.scoreAgainstAll(prediction, truths, mean))
    return 1;
  if (as_json) {
    std::printf("%s\n", json(mean, "humans").c_str());
    return 0;
  }
  std::printf("%s against %d reference segmentation(s); CD defined for %d\n", pred_path.c_str(),
              mean.count, mean.cd_count);
  const char* names[] = {"CD", "HD", "Rm", "Rf", "RI (1-Rand)", "GCE", "LCE", "GCEf", "LCEf"};
  const double values[] = {mean.CD,  mean.HD,  mean.Rm,   mean.Rf,  mean.RI,
                           mean.GCE, mean.LCE, mean.GCEf, mean.LCEf};
  for (int k = 0; k < 9; ++k)
    std::printf("  %-12s %s\n", names[k],
                std::isnan(values[k]) ? "n/a (no cut)" : number(values[k]).c_str());
  return 0;
}

int
evaluateFolder(const std::string& dataset_dir, const std::string& pred_dir,
               const std::vector<int>& ids, bool as_json)
{
  const segmat::PsbBenchmarkResult r = segmat::evaluatePsbFolder(dataset_dir, pred_dir, ids);
  if (as_json) {
    std::string out = "{\"models\": {";
    for (auto it = r.models.begin(); it != r.models.end(); ++it)
      out += (it == r.models.begin() ? "\"" : ", \"") + std::to_string(it->first) +
             "\": " + json(it->second, "humans");
    out += "}, \"categories\": {";
    for (std::size_t c = 0; c < r.categories.size(); ++c)
      out += (c == 0 ? "\"" : ", \"") + r.categories[c].first +
             "\": " + json(r.categories[c].second, "models");
    out += "}, \"overall\": " + json(r.overall, "models") + ", \"skipped\": [";
    for (std::size_t k = 0; k < r.skipped.size(); ++k)
      out += (k == 0 ? "" : ", ") + std::to_string(r.skipped[k]);
    std::printf("%s]}\n", out.c_str());
    return 0;
  }
  std::printf("%-7s %-10s %-7s %s\n", "model", "category", "humans", kColumns);
  for (const auto& [id, s] : r.models)
    std::printf("%-7d %-10s %-7d %s\n", id, segmat::psbCategoryName(id), s.count, row(s).c_str());
  std::printf("\n%-18s %-7s %s\n", "category", "models", kColumns);
  for (const auto& [name, s] : r.categories)
    std::printf("%-18s %-7d %s\n", name.c_str(), s.count, row(s).c_str());
  std::printf("\n%-18s %-7d %s\n", "overall", r.overall.count, row(r.overall).c_str());
  std::printf("(overall = mean over models; CD over the %d models where it is defined)\n",
              r.overall.cd_count);
  if (!r.skipped.empty())
    std::printf("skipped %zu model(s) with a mesh but no prediction\n", r.skipped.size());
  return 0;
}

int
run(int argc, char** argv)
{
  std::string mesh, pred, psb, models;
  std::vector<std::string> truths;
  bool has_models = false;
  CommonOptions common;
  OptionParser parser(
      "segmat_eval", "--mesh M.off --pred P.seg --truth T1.seg [T2.seg ...] [--json]\n"
      "       segmat_eval --psb DIR --pred PREDDIR [--models 1,5-20] [--json]",
      "Princeton Segmentation Benchmark scores (fractions, lower is better; CD in units of the\n"
      "mesh's average radius; RI = 1 - Rand index; GCE/LCE measure regions by area, GCEf/LCEf by\n"
      "face count). The first form scores P against each truth and prints the means (CD over the\n"
      "truths where it exists: it is undefined when a segmentation has no cut). The second scores\n"
      "PREDDIR/N.seg against DIR/seg/Benchmark/N/N_k.seg on DIR/off/N.off for every model with a\n"
      "prediction (or exactly the --models given) and prints per-model, per-category and overall\n"
      "means (overall = mean over models).",
      "segmat_eval --mesh data/teddy/teddy.off --pred teddy.seg --truth data/teddy/seg/180_0.seg");
  parser.add(kInput, "--mesh", "M.off", "the mesh the labels belong to",
             [&](const std::string& v) { mesh = v; });
  parser.add(kInput, "--pred", "P", "predicted labels (.seg), or with --psb a folder of N.seg",
             [&](const std::string& v) { pred = v; });
  parser.add(kInput, "--truth", "T.seg", "reference labels; more files may follow",
             [&](const std::string& v) { truths.push_back(v); });
  parser.rest(truths);
  parser.add(kInput, "--psb", "DIR", "a PSB-style folder (off/N.off, seg/Benchmark/N/N_k.seg)",
             [&](const std::string& v) { psb = v; });
  parser.add(kInput, "--models", "LIST", "with --psb: the models to score (example: 1,5-20)",
             [&](const std::string& v) {
               models = v;
               has_models = true;
             });
  addCommonOptions(parser, common, false);

  if (!parser.parse(argc, argv))
    return kExitOk;
  Progress progress(parser.program(), common.quiet);
  progress.stage("scoring");
  if (!psb.empty()) {
    if (!mesh.empty() || !truths.empty())
      throw UsageError("--psb does not combine with --mesh or --truth");
    if (pred.empty())
      throw UsageError("--psb needs --pred PREDDIR");
    std::vector<int> ids;
    if (has_models && !parseModelList(models, ids))
      throw UsageError("bad --models list '" + models + "' (example: 1,5-20)");
    int status = kExitOk;
    asInput([&] { status = evaluateFolder(psb, pred, ids, common.json); });
    progress.done();
    return status;
  }
  if (has_models)
    throw UsageError("--models goes with --psb");
  if (mesh.empty() || pred.empty() || truths.empty())
    throw UsageError("give --mesh, --pred and --truth (or --psb and --pred)");
  for (const std::string& path : truths)
    checkInputFile(path);
  checkInputFile(mesh);
  checkInputFile(pred);
  int status = kExitOk;
  asInput([&] { status = evaluateOne(mesh, pred, truths, common.json); });
  progress.done();
  return status;
}

} // namespace

int
main(int argc, char** argv)
{
  return runMain("segmat_eval", [&] { return run(argc, argv); });
}
