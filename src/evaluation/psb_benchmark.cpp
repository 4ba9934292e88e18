/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/io/off.h>
#include <segmat/io/seg.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

namespace segmat {

namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 20> kCategoryNames{
    "Human", "Cup",      "Glasses", "Airplane", "Ant",  "Chair", "Octopus",
    "Table", "Teddy",    "Hand",    "Plier",    "Fish", "Bird",  "Spring",
    "Armadillo", "Bust", "Mech",    "Bearing",  "Vase", "FourLeg"};

// Positive integer written with digits only ("12", not "012x"); -1 otherwise.
int
parseId(const std::string& text)
{
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    return -1;
  return std::stoi(text);
}

std::string
meshPath(const std::string& dataset_dir, int id)
{
  return (fs::path(dataset_dir) / "off" / (std::to_string(id) + ".off")).string();
}

std::string
predictionPath(const std::string& prediction_dir, int id)
{
  return (fs::path(prediction_dir) / (std::to_string(id) + ".seg")).string();
}

// Ids of all `off/N.off` meshes, ascending.
std::vector<int>
listMeshIds(const std::string& dataset_dir)
{
  const fs::path off_dir = fs::path(dataset_dir) / "off";
  std::error_code ec;
  if (!fs::is_directory(off_dir, ec))
    throw Error(off_dir.string(), 0, "not a directory (expected a PSB folder with off/ and seg/)");
  std::vector<int> ids;
  for (const fs::directory_entry& entry : fs::directory_iterator(off_dir))
    if (entry.path().extension() == ".off") {
      const int id = parseId(entry.path().stem().string());
      if (id > 0)
        ids.push_back(id);
    }
  std::sort(ids.begin(), ids.end());
  return ids;
}

PsbScores
scoreModel(const std::string& dataset_dir, const std::string& prediction_dir, int id)
{
  const std::string mesh_path = meshPath(dataset_dir, id);
  const PsbEvaluator evaluator(io::loadOff(mesh_path));
  if (!evaluator.ready())
    throw Error(mesh_path, 0, "the mesh cannot be evaluated (no non-degenerate face or zero area)");
  const std::vector<std::string> human_paths = psbHumanSegmentationPaths(dataset_dir, id);
  if (human_paths.empty())
    throw Error((fs::path(dataset_dir) / "seg" / "Benchmark" / std::to_string(id)).string(), 0,
                "no human segmentation " + std::to_string(id) + "_0.seg for model " +
                    std::to_string(id));
  const std::vector<int> prediction = loadLabelsFor(evaluator, predictionPath(prediction_dir, id));
  std::vector<std::vector<int>> humans;
  humans.reserve(human_paths.size());
  for (const std::string& path : human_paths)
    humans.push_back(loadLabelsFor(evaluator, path));
  PsbScores mean;
  evaluator.scoreAgainstAll(prediction, humans, mean); // lengths checked by loadLabelsFor
  return mean;
}

} // namespace

int
psbCategoryIndex(int model_id)
{
  return model_id >= 1 && model_id <= 400 ? (model_id - 1) / 20 : -1;
}

const char*
psbCategoryName(int model_id)
{
  const int c = psbCategoryIndex(model_id);
  return c < 0 ? "" : kCategoryNames[c];
}

std::vector<int>
loadLabelsFor(const PsbEvaluator& evaluator, const std::string& path)
{
  const long input_faces = static_cast<long>(evaluator.numInputFaces());
  const long eval_faces = static_cast<long>(evaluator.numEvaluatedFaces());
  if (input_faces == eval_faces)
    return io::loadSeg(path, input_faces);
  // The mesh has faces the benchmark drops: accept a label per input face or per kept face.
  std::vector<int> labels = io::loadSeg(path);
  const long n = static_cast<long>(labels.size());
  if (n != input_faces && n != eval_faces)
    throw Error(path, 0,
                "has " + std::to_string(n) + " labels, the mesh has " +
                    std::to_string(input_faces) + " faces (" + std::to_string(eval_faces) +
                    " without repeated vertex indices)");
  return labels;
}

std::vector<std::string>
psbHumanSegmentationPaths(const std::string& dataset_dir, int model_id)
{
  const std::string name = std::to_string(model_id);
  const fs::path dir = fs::path(dataset_dir) / "seg" / "Benchmark" / name;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    return {};
  std::vector<int> ks;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string stem = entry.path().stem().string();
    if (entry.path().extension() == ".seg" && stem.rfind(name + "_", 0) == 0) {
      const int k = stem.size() > name.size() + 1 ? parseId(stem.substr(name.size() + 1)) : -1;
      if (k >= 0)
        ks.push_back(k);
    }
  }
  std::sort(ks.begin(), ks.end());
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < ks.size(); ++k) {
    const std::string path = (dir / (name + "_" + std::to_string(k) + ".seg")).string();
    if (ks[k] != static_cast<int>(k))
      throw Error(path, 0, "missing: the human segmentations of model " + name +
                               " must be numbered 0.." + std::to_string(ks.size() - 1));
    paths.push_back(path);
  }
  return paths;
}

PsbBenchmarkResult
evaluatePsbFolder(const std::string& dataset_dir, const std::string& prediction_dir,
                  const std::vector<int>& model_ids)
{
  std::error_code ec;
  if (!fs::is_directory(prediction_dir, ec))
    throw Error(prediction_dir, 0, "not a directory (expected one N.seg per model)");
  PsbBenchmarkResult result;
  std::vector<int> ids = model_ids;
  if (ids.empty()) {
    for (int id : listMeshIds(dataset_dir)) {
      if (fs::exists(predictionPath(prediction_dir, id), ec))
        ids.push_back(id);
      else
        result.skipped.push_back(id);
    }
    if (ids.empty())
      throw Error(prediction_dir, 0,
                  "no prediction N.seg matches a mesh in " + (fs::path(dataset_dir) / "off").string());
  } else {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (int id : ids) // a requested model must be complete: report the first gap
      for (const std::string& path : {meshPath(dataset_dir, id), predictionPath(prediction_dir, id)})
        if (!fs::exists(path, ec))
          throw Error(path, 0, "missing (model " + std::to_string(id) + " was requested)");
  }

  std::vector<PsbScores> all;
  std::array<std::vector<PsbScores>, kCategoryNames.size()> by_category;
  for (int id : ids) {
    const PsbScores scores = scoreModel(dataset_dir, prediction_dir, id);
    result.models[id] = scores;
    all.push_back(scores);
    const int c = psbCategoryIndex(id); // ids outside 1..400 count overall only
    if (c >= 0)
      by_category[c].push_back(scores);
  }
  for (std::size_t c = 0; c < by_category.size(); ++c)
    if (!by_category[c].empty())
      result.categories.emplace_back(kCategoryNames[c], averagePsbScores(by_category[c]));
  result.overall = averagePsbScores(all);
  return result;
}

} // namespace segmat
