/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/evaluation/psb_metrics.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

/** \brief PSB category of a model id: (id − 1) div 20, 0..19; −1 outside 1..400. */
int
psbCategoryIndex(int model_id);

/** \brief PSB category name of a model id ("Human" for 1–20 … "FourLeg" for 381–400; "" outside
 * 1..400). 261–280 (Spring) is not part of the benchmark's data.
 */
const char*
psbCategoryName(int model_id);

/** \brief Reads a labeling of the evaluator's mesh from a `.seg` file.
 *
 * Strict (io::loadSeg): one integer per line and one line per face of the input mesh — or per
 * evaluated face, when the mesh has faces with a repeated vertex index that the benchmark drops.
 * \throws segmat::Error naming the file (and line) for a missing file, a bad line or a wrong count
 */
std::vector<int>
loadLabelsFor(const PsbEvaluator& evaluator, const std::string& path);

/** \brief The human segmentations of PSB model \a model_id: `DIR/seg/Benchmark/N/N_k.seg`,
 * k = 0, 1, … in order. Empty when the model has none.
 * \throws segmat::Error when the numbering has a gap (a human file is missing)
 */
std::vector<std::string>
psbHumanSegmentationPaths(const std::string& dataset_dir, int model_id);

/** \brief Scores of a set of PSB models: per model, per category and overall. */
struct PsbBenchmarkResult
{
  std::map<int, PsbScores> models; ///< by model id; count = humans
  /// category name → mean over its scored models (count = models); PSB order, scored ones only
  std::vector<std::pair<std::string, PsbScores>> categories;
  PsbScores overall;        ///< mean over models (not over categories); count = models
  std::vector<int> skipped; ///< models with a mesh but no prediction (only when no list was given)
};

/** \brief Scores a folder of predictions against a PSB-style folder, as the benchmark's
 * evalAlgorithm.py / collectEvaluation.py do: each prediction `PRED/N.seg` against every human
 * `DIR/seg/Benchmark/N/N_k.seg` on mesh `DIR/off/N.off`; per-model value = mean over its humans
 * (CD over the humans where it exists); category value = mean over its models; overall = mean
 * over models. A model with no defined CD drops out of the CD means only.
 * \param[in] dataset_dir the PSB-style folder (`off/`, `seg/Benchmark/`)
 * \param[in] prediction_dir one `N.seg` per scored model
 * \param[in] model_ids the models to score; empty: every model with a mesh and a prediction
 *            (the others are listed in PsbBenchmarkResult::skipped)
 * \throws segmat::Error for a missing or malformed file, a requested model without mesh,
 *         humans or prediction, a mesh that cannot be evaluated, or nothing to score
 */
PsbBenchmarkResult
evaluatePsbFolder(const std::string& dataset_dir, const std::string& prediction_dir,
                  const std::vector<int>& model_ids = {});

} // namespace segmat
