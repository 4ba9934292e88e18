/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_cloud: segment a point cloud into parts with SEG-MAT's cloud path (meso-skeleton,
 * region growing on the medial points, α-expansion back to every point).
 */
#include <segmat/common/error.h>
#include <segmat/io/cloud.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/ma.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/segmentation/cloud_segmentation.h>

#include "box_output.h"
#include "detail_level_option.h"
#include "option_parser.h"
#include "program_files.h"
#include "progress.h"
#include "render_call.h"
#include "report.h"

#include <cstdio>
#include <string>

using namespace segmat;
using namespace segmat::cli;

namespace {

/// \a mat, or an empty one when there is none (a cloud without a medial axis).
MedialMesh
orEmpty(const MedialMesh::ConstPtr& mat)
{
  return mat ? *mat : MedialMesh();
}

/// \a mat moved back by the reader's origin (LoadedCloud::origin).
MedialMesh
inFileFrame(const MedialMesh& mat, const Eigen::Vector3d& origin)
{
  if (origin.isZero())
    return mat;
  std::vector<Eigen::Vector3d> centers = mat.centers();
  for (Eigen::Vector3d& c : centers)
    c += origin;
  return MedialMesh(std::move(centers), mat.radii(), mat.edges(), mat.triangles());
}

int
run(int argc, char** argv)
{
  std::string cloud_path, prefix;
  bool estimate_normals = false, save_mat = false, meso_skeleton = false;
  CommonOptions common;
  bool boxes = false;
  std::string png;
  CloudSegmentation<pcl::PointNormal> segmentation;

  OptionParser parser("segmat_cloud", "CLOUD -o PREFIX [options]",
                      "Segments a point cloud into parts with SEG-MAT's cloud path (medial mesh of\n"
                      "the points, region growing on its spheres, graph cut back to every point).",
                      "segmat_cloud cloud.pcd -o parts   # writes parts.pcd, parts.ply, parts.labels");
  parser.positional("CLOUD", "point cloud (.pcd, .ply, .xyz/.txt), with or without normals",
                    cloud_path);
  parser.flag(kInput, "--estimate-normals", "ignore the file's normals and estimate them\n"
              "(a noisy cloud's are estimated anyway)",
              estimate_normals);
  parser.add(kOutput, "-o", "PREFIX",
             "writes PREFIX.pcd (x y z label), PREFIX.ply (points coloured by\n"
             "part) and PREFIX.labels (one label per input point, input order;\n"
             "-1 for points with a non-finite coordinate)",
             [&](const std::string& v) { prefix = v; });
  parser.flag(kOutput, "--save-mat",
              "also write PREFIX_base.ma and PREFIX_struct.ma (medial mesh only)", save_mat);
  parser.add(kParameters, "-g", "DELTA0", "growing threshold (default 0.015)",
             [&](const std::string& v) {
               segmentation.setGrowingThreshold(parseNumberIn(v, 1e-9, 1e9, "a threshold > 0"));
             });
  parser.add(kParameters, "-n", "ETA", "minimal region, fraction of the medial points\n"
             "(default 0.002)", [&](const std::string& v) {
               segmentation.setMinRegionFraction(parseNumberIn(v, 0.0, 1.0, "a fraction in [0, 1]"));
             });
  parser.add(kParameters, "-w", "SIZE",
             "working size: points kept for the medial step (default 20000;\n"
             "ceiling: see docs/cli.md)", [&](const std::string& v) {
               segmentation.setWorkingSize(static_cast<std::size_t>(parseInteger(v, 1)));
             });
  parser.add(kParameters, "-k", "K", "neighbours of the k-NN graphs (default 10)",
             [&](const std::string& v) { segmentation.setKSearch(parseInteger(v, 1, 1000)); });
  parser.flag(kParameters, "--no-visibility", "merge parts without the visibility test",
              [&] { segmentation.setVisibilityFlag(false); });
  parser.add(kParameters, "--max-bend", "DEG", "largest turn of a bulky tube inside one part\n"
             "(default 60; 90 = off, as in SEG-MAT)", [&](const std::string& v) {
               segmentation.setMaxBendAngle(parseNumberIn(v, 1e-9, 90.0, "an angle in (0, 90]"));
             });
  parser.flag(kParameters, "--meso-skeleton",
              "medial axis from shrinking balls (no faces) instead of the default\n"
              "Voronoi medial mesh of the points",
              [&] {
                segmentation.setMedialAxis(CloudMedialAxis::MesoSkeleton);
                meso_skeleton = true;
              });
  parser.flag(kOutput, "--boxes",
              "also write PREFIX_boxes.json and PREFIX_boxes.ply: one tight oriented\n"
              "box per part (docs/abstraction.md)", boxes);
  parser.add(kOutput, "--png", "FILE", "also draw the parts into a PNG (segmat_render, with VTK)",
             [&](const std::string& v) { png = v; });
  parser.add(kParameters, "--level", "L",
             "coarse, default or fine: sets -g and -n together (docs/levels.md);\n"
             "a number in [-1, 1] goes between them",
             [&](const std::string& v) { applyDetailLevel(segmentation, v); });
  addCommonOptions(parser, common);
  parser.note("A noisy cloud needs no option: its noise is estimated and the points smoothed\n"
              "(docs/noise.md). --json prints parts, point_counts, seconds per stage, the\n"
              "medial mesh's samples and initial, base and structured spheres (0 with\n"
              "--meso-skeleton), noise {sigma, spacing, remaining_sigma, passes} (estimated,\n"
              "in the file's units, with or without the file's normals) and origin (what a\n"
              "cloud far from 0 was moved by; outputs are written back in the file's frame).");

  if (!parser.parse(argc, argv))
    return kExitOk;
  if (cloud_path.empty() || prefix.empty())
    throw UsageError("CLOUD and -o PREFIX are required");
  if (save_mat && meso_skeleton)
    throw UsageError("--save-mat writes the medial mesh: not with --meso-skeleton");
  checkInputFile(cloud_path);
  io::OutputSet outputs({cloud_path});
  std::vector<std::string> suffixes{".pcd", ".ply", ".labels"};
  if (save_mat)
    suffixes.insert(suffixes.end(), {"_base.ma", "_struct.ma"});
  if (boxes)
    for (const std::string& suffix : boxSuffixes())
      suffixes.push_back(suffix);
  declareOutputs(outputs, prefix, suffixes);
  if (!png.empty())
    asInput([&] { outputs.add(png); });
  segmentation.setNumberOfThreads(resolveThreads(parser.program(), common.threads));

  Progress progress(parser.program(), common.quiet);
  progress.stage("reading " + cloud_path);
  io::LoadedCloud loaded;
  asInput([&] {
    loaded = io::loadCloud(cloud_path);
    if (loaded.cloud->empty())
      throw Error(cloud_path, 0, "the cloud has no points");
  });
  const double load_seconds = progress.stage("segmenting");

  segmentation.setInputCloud(loaded.cloud);
  segmentation.setUseInputNormalsFlag(loaded.has_normals && !estimate_normals);
  std::vector<pcl::PointIndices> parts;
  if (!segmentation.segment(parts))
    throw Error(cloud_path, 0, "segmentation failed (no finite point?)");
  progress.stage("writing " + prefix + ".*");

  pcl::PointCloud<pcl::PointXYZL> labelled;
  segmentation.getLabeledCloud(labelled);
  // Outputs in the file's own frame (the reader moved far-away clouds next to 0).
  if (!loaded.origin.isZero())
    for (pcl::PointXYZL& p : labelled)
      p.getVector3fMap() = (p.getVector3fMap().cast<double>() + loaded.origin).cast<float>();
  io::saveLabeledCloudPcd(outputs.temporary(prefix + ".pcd"), labelled);
  io::saveColoredCloudPly(outputs.temporary(prefix + ".ply"), labelled);
  io::saveLabels(outputs.temporary(prefix + ".labels"), segmentation.getLabels());
  if (save_mat) {
    io::saveMa(outputs.temporary(prefix + "_base.ma"),
               inFileFrame(orEmpty(segmentation.getBaseMat()), loaded.origin));
    io::saveMa(outputs.temporary(prefix + "_struct.ma"),
               inFileFrame(orEmpty(segmentation.getStructuredMat()), loaded.origin));
  }
  if (boxes)
    writePartBoxes(outputs, prefix, labelled, segmentation.getLabels());
  if (!png.empty())
    renderPicture(cloud_path, outputs.temporary(prefix + ".labels"), outputs.temporary(png));
  outputs.commit(); // every output appears together, or none
  const double write_seconds = progress.done();

  StageTimings seconds{{"load", load_seconds}};
  for (const auto& stage : segmentation.getStageSeconds())
    seconds.push_back(stage);
  seconds.emplace_back("write", write_seconds);

  if (common.json) {
    const MedialMeshEstimationStatistics& mat = segmentation.getMatStatistics();
    std::printf("{\"parts\": %zu, \"point_counts\": %s, \"seconds\": %s, "
                "\"samples\": %zu, \"initial_spheres\": %zu, \"base_spheres\": %zu, "
                "\"structured_spheres\": %zu, "
                "\"noise\": {\"sigma\": %.9g, \"spacing\": %.9g, \"remaining_sigma\": %.9g, "
                "\"passes\": %d}, "
                "\"origin\": [%.17g, %.17g, %.17g]}\n",
                parts.size(), jsonSizes(parts).c_str(), jsonSeconds(seconds).c_str(),
                mat.voronoi.num_samples, mat.initial_spheres, mat.base_spheres,
                mat.structured_spheres,
                segmentation.getEstimatedNoise(), segmentation.getEstimatedSpacing(),
                segmentation.getRemainingNoise(), segmentation.getDenoisingPasses(),
                loaded.origin.x(), loaded.origin.y(), loaded.origin.z());
    return kExitOk;
  }
  printPartsText("point", parts, seconds);
  if (segmentation.getDenoisingPasses() > 0)
    std::printf("\nnoise: sigma %.3g, spacing %.3g (estimated; the points were smoothed %d "
                "times)",
                segmentation.getEstimatedNoise(), segmentation.getEstimatedSpacing(),
                segmentation.getDenoisingPasses());
  if (!loaded.origin.isZero())
    std::printf("\norigin: %.17g %.17g %.17g (the file's points lie far from 0: segmented "
                "relative to this point, written back in the file's frame)",
                loaded.origin.x(), loaded.origin.y(), loaded.origin.z());
  std::printf("\n");
  printWrote(outputs);
  return kExitOk;
}

} // namespace

int
main(int argc, char** argv)
{
  return runMain("segmat_cloud", [&] { return run(argc, argv); });
}
