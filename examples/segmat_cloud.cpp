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
#include <segmat/segmentation/cloud_segmentation.h>

#include "box_output.h"
#include "cli_options.h"
#include "render_call.h"
#include "detail_level_option.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

const char* const kUsage =
    "usage: segmat_cloud CLOUD -o PREFIX [options] [--json] [--png PICTURE.png]\n"
    "  CLOUD              point cloud (.pcd, .ply, .xyz/.txt), with or without normals\n"
    "  -o PREFIX          writes PREFIX.pcd (x y z label), PREFIX.ply (points coloured by\n"
    "                     part) and PREFIX.labels (one label per input point, input order;\n"
    "                     -1 for points with a non-finite coordinate)\n"
    "  -g DELTA0          growing threshold (default 0.015)\n"
    "  -n ETA             minimal region, fraction of the medial points (default 0.002)\n"
    "  -w SIZE            working size: points kept for the medial step (default 20000)\n"
    "  -k K               neighbours of the k-NN graphs (default 10)\n"
    "  --estimate-normals ignore the file's normals and estimate them\n"
    "  --no-visibility    merge parts without the visibility test\n"
    "  --max-bend DEG     largest turn of a bulky tube inside one part (default 60; 90 = off,\n"
    "                     as in SEG-MAT)\n"
    "  --meso-skeleton    medial axis from shrinking balls (no faces) instead of the default\n"
    "                     Voronoi medial mesh of the points\n"
    "  --save-mat         also write PREFIX_base.ma and PREFIX_struct.ma (medial mesh only)\n"
    "  --runs N           segmentations of a noisy cloud to keep the consensus of (default 9;\n"
    "                     1: one run). --runs-always: for every cloud, not only noisy ones\n"
    "  --runs-merge F     merge each run's adjacent parts that the runs join with a\n"
    "                     mean co-association above F (default 0.5; above 1: no merging)\n"
    "  --runs-merge-reproduced  the kept run's merge may join a cut a third of the runs make\n"
    "                     alike (by default such cuts are kept)\n"
    "  --boundary-merge K parts of a noisy cloud that share at least K*sqrt(n) spheres merge\n"
    "                     without the visibility test (default 0.5; 0: off, as in SEG-MAT)\n"
    "  --noisy-centres-outside  let Q-MAT move a noisy cloud's merged sphere centres out of\n"
    "                     the surface (faster; by default they are kept inside)\n"
    "  --threads N        threads (default: OpenMP's choice; results do not depend on it)\n"
    "  --png FILE         also draw the parts into a PNG (segmat_render, built with VTK)\n"
    "  --level L          coarse, default or fine: sets -g and -n together (docs/levels.md);\n"
    "                     a number in [-1, 1] goes between them\n"
    "  --boxes            also write PREFIX_boxes.json and PREFIX_boxes.ply: one tight oriented\n"
    "                     box per part (docs/abstraction.md)\n"
    "  --json             print one JSON object: parts, point_counts, seconds per stage\n"
    "                     (summed over the runs), runs [made, kept], origin (what a cloud far\n"
    "                     from 0 was moved by; outputs are written back in the file's frame)\n";




/// \a mat moved back by the reader's origin (LoadedCloud::origin).
segmat::MedialMesh
inFileFrame(const segmat::MedialMesh& mat, const Eigen::Vector3d& origin)
{
  if (origin.isZero())
    return mat;
  std::vector<Eigen::Vector3d> centers = mat.centers();
  for (Eigen::Vector3d& c : centers)
    c += origin;
  return segmat::MedialMesh(std::move(centers), mat.radii(), mat.edges(), mat.triangles());
}

} // namespace

using namespace segmat::cli;

int
main(int argc, char** argv)
{
  std::string cloud_path, prefix;
  std::string png; // --png: a picture by segmat_render
  bool json = false, estimate_normals = false, save_mat = false, boxes = false;
  segmat::CloudSegmentation<pcl::PointNormal> segmentation;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      const auto value = [&]() -> std::string {
        if (i + 1 >= argc)
          throw segmat::Error("option " + arg + " needs a value");
        return argv[++i];
      };
      if (arg == "-h" || arg == "--help") {
        std::cout << kUsage;
        return 0;
      }
      if (arg == "-o")
        prefix = value();
      else if (arg == "-g") {
        const double delta0 = parseNumber(arg, value());
        if (!(delta0 > 0.0))
          throw segmat::Error("option -g: the growing threshold must be > 0");
        segmentation.setGrowingThreshold(delta0);
      }
      else if (arg == "-n") {
        const double eta = parseNumber(arg, value());
        if (eta < 0.0 || eta > 1.0)
          throw segmat::Error("option -n: the minimal region fraction must be in [0, 1]");
        segmentation.setMinRegionFraction(eta);
      }
      else if (arg == "-w")
        segmentation.setWorkingSize(static_cast<std::size_t>(parseInteger(arg, value(), 1)));
      else if (arg == "-k")
        segmentation.setKSearch(parseInteger(arg, value(), 1));
      else if (arg == "--threads")
        segmentation.setNumberOfThreads(static_cast<unsigned>(parseInteger(arg, value(), 1)));
      else if (arg == "--estimate-normals")
        estimate_normals = true;
      else if (arg == "--max-bend")
        segmentation.setMaxBendAngle(parseBendAngle(arg, value()));
      else if (arg == "--no-visibility")
        segmentation.setVisibilityFlag(false);
      else if (arg == "--meso-skeleton")
        segmentation.setMedialAxis(segmat::CloudMedialAxis::MesoSkeleton);
      else if (arg == "--save-mat")
        save_mat = true;
      else if (arg == "--boxes")
        boxes = true;
      else if (arg == "--level")
        applyDetailLevel(segmentation, value());
      else if (arg == "--runs")
        segmentation.setConsensusRuns(parseInteger(arg, value(), 1));
      else if (arg == "--runs-merge") {
        const double threshold = parseNumber(arg, value());
        if (!(threshold >= 0.0))
          throw segmat::Error("option --runs-merge: the threshold must be >= 0");
        segmentation.setConsensusMergeThreshold(threshold);
      }
      else if (arg == "--boundary-merge") {
        const double factor = parseNumber(arg, value());
        if (!(factor >= 0.0))
          throw segmat::Error("option --boundary-merge: the factor must be >= 0");
        segmentation.setNoisyBoundaryMergeFactor(factor);
      }
      else if (arg == "--noisy-centres-outside")
        segmentation.setNoisyCentresInsideFlag(false);
      else if (arg == "--runs-merge-reproduced")
        segmentation.setConsensusKeepReproducedCutsFlag(false);
      else if (arg == "--runs-always")
        segmentation.setConsensusForEveryCloudFlag(true);
      else if (arg == "--json")
        json = true;
      else if (arg == "--png")
        png = value();
      else if (!arg.empty() && arg[0] == '-')
        throw segmat::Error("unknown option " + arg);
      else if (cloud_path.empty())
        cloud_path = arg;
      else
        throw segmat::Error("unexpected argument " + arg);
    }
    if (cloud_path.empty() || prefix.empty())
      throw segmat::Error("CLOUD and -o are required");
  }
  catch (const segmat::Error& e) {
    std::cerr << "segmat_cloud: " << e.what() << "\n" << kUsage;
    return 2;
  }

  try {
    auto start = std::chrono::steady_clock::now();
    const segmat::io::LoadedCloud loaded = segmat::io::loadCloud(cloud_path);
    const double load_seconds = secondsSince(start);
    if (loaded.cloud->empty())
      throw segmat::Error(cloud_path, 0, "the cloud has no points");

    segmentation.setInputCloud(loaded.cloud);
    segmentation.setUseInputNormalsFlag(loaded.has_normals && !estimate_normals);
    std::vector<pcl::PointIndices> parts;
    if (!segmentation.segment(parts))
      throw segmat::Error(cloud_path, 0, "segmentation failed (no finite point?)");
    secondsSince(start);

    pcl::PointCloud<pcl::PointXYZL> labelled;
    segmentation.getLabeledCloud(labelled);
    // Outputs in the file's own frame (the reader moved far-away clouds next to 0).
    if (!loaded.origin.isZero())
      for (pcl::PointXYZL& p : labelled)
        p.getVector3fMap() = (p.getVector3fMap().cast<double>() + loaded.origin).cast<float>();
    segmat::io::saveLabeledCloudPcd(prefix + ".pcd", labelled);
    segmat::io::saveColoredCloudPly(prefix + ".ply", labelled);
    segmat::io::saveLabels(prefix + ".labels", segmentation.getLabels());
    if (!png.empty())
      renderPicture(cloud_path, prefix + ".labels", png);
    if (boxes)
      writePartBoxes(prefix, labelled, segmentation.getLabels());
    if (save_mat && !segmentation.getBaseMat().empty()) {
      segmat::io::saveMa(prefix + "_base.ma", inFileFrame(segmentation.getBaseMat(), loaded.origin));
      segmat::io::saveMa(prefix + "_struct.ma",
                         inFileFrame(segmentation.getStructuredMat(), loaded.origin));
    }
    const double write_seconds = secondsSince(start);

    std::vector<std::pair<std::string, double>> seconds{{"load", load_seconds}};
    for (const auto& stage : segmentation.getStageSeconds())
      seconds.push_back(stage);
    seconds.emplace_back("write", write_seconds);

    if (json) {
      std::printf("{\"parts\": %zu, \"point_counts\": [", parts.size());
      for (std::size_t k = 0; k < parts.size(); ++k)
        std::printf("%s%zu", k ? ", " : "", parts[k].indices.size());
      std::printf("], \"seconds\": {");
      for (std::size_t k = 0; k < seconds.size(); ++k)
        std::printf("%s\"%s\": %.6f", k ? ", " : "", seconds[k].first.c_str(), seconds[k].second);
      std::printf("}, \"runs\": [%d, %d], \"origin\": [%.17g, %.17g, %.17g]}\n",
                  segmentation.getConsensusRunsMade(), segmentation.getConsensusRunKept(),
                  loaded.origin.x(), loaded.origin.y(), loaded.origin.z());
    }
    else {
      std::printf("parts: %zu\npoint counts:", parts.size());
      for (const auto& part : parts)
        std::printf(" %zu", part.indices.size());
      std::printf("\nseconds:");
      for (const auto& stage : seconds)
        std::printf(" %s %.4f", stage.first.c_str(), stage.second);
      if (segmentation.getConsensusRunsMade() > 1)
        std::printf("\nruns: %d (noisy cloud; kept run %d, the consensus; seconds are summed)",
                    segmentation.getConsensusRunsMade(), segmentation.getConsensusRunKept());
      if (!loaded.origin.isZero())
        std::printf("\norigin: %.17g %.17g %.17g (the file's points lie far from 0: segmented "
                    "relative to this point, written back in the file's frame)",
                    loaded.origin.x(), loaded.origin.y(), loaded.origin.z());
      std::printf("\nwrote %s.pcd, %s.ply and %s.labels\n", prefix.c_str(), prefix.c_str(),
                  prefix.c_str());
    }
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_cloud: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
