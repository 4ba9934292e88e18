/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_boxes: SEG-MAT's primitive abstraction scored on psb-dev. Every Airplane (PSB 61-80),
 * Chair (101-120) and Table (141-160) mesh present is segmented with default parameters, each
 * part replaced by its tight oriented box (PartBoxEstimation), and the boxes scored against the
 * solid (scoreBoxAbstraction: IoU on a grid, Chamfer on surface samples, shape at unit
 * bounding-box diagonal). The same is printed for principal-axes (PCA) boxes of the same parts.
 *
 *   build/bin/bench_boxes [DIR] [--resolution R] [--samples N]
 * DIR defaults to ../shared/data/psb-dev/off (run from the repository root).
 */
#include "bench_args.h"
#include "bench_common.h"

#include <segmat/evaluation/box_abstraction_metrics.h>
#include <segmat/evaluation/part_box_estimation.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {
struct Category
{
  const char* name;
  int first, last; // PSB ids
};

struct Sums
{
  double iou = 0, chamfer = 0, chamfer_squared = 0, pca_iou = 0, pca_chamfer = 0;
  int shapes = 0;
};
} // namespace

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  std::string dir = "../shared/data/psb-dev/off";
  int resolution = 64, samples = 10000;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--resolution")
      resolution = std::max(2, segmat::bench::intArgument(argc, argv, i));
    else if (arg == "--samples")
      samples = std::max(1, segmat::bench::intArgument(argc, argv, i));
    else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "usage: bench_boxes [DIR] [--resolution R] [--samples N]\n");
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
    else
      dir = arg;
  }
  const Category categories[] = {{"Airplane", 61, 80}, {"Chair", 101, 120}, {"Table", 141, 160}};
  using Clock = std::chrono::steady_clock;
  std::printf("grid: %d cells along the longest side; Chamfer: %d samples per surface, shape at "
              "unit bounding-box diagonal, CD = mean of unsquared nearest distances averaged over "
              "both directions, CD2 = the same squared\n\n",
              resolution, samples);
  std::printf("%-9s %5s %5s %7s %8s %9s %8s %8s %7s %7s\n", "category", "shape", "parts", "IoU",
              "CD", "CD2", "pcaIoU", "pcaCD", "seg_s", "box_s");
  std::vector<std::pair<const char*, Sums>> means;
  for (const Category& category : categories) {
    Sums sums;
    for (int id = category.first; id <= category.last; ++id) {
      const std::string path = dir + "/" + std::to_string(id) + ".off";
      if (!std::filesystem::exists(path))
        continue;
      const segmat::TriangleMesh::Ptr mesh = segmat::bench::loadMeshOrSkip(path);
      if (!mesh)
        continue;
      auto start = Clock::now();
      segmat::MeshSegmentation segmentation;
      segmentation.setNumberOfThreads(1);
      segmentation.setInputMesh(mesh);
      std::vector<int> labels;
      if (!segmentation.segment(labels)) {
        std::printf("%-9s %5d failed\n", category.name, id);
        continue;
      }
      const double seg_seconds = std::chrono::duration<double>(Clock::now() - start).count();
      start = Clock::now();
      segmat::PartBoxEstimation estimation;
      estimation.setInputMesh(mesh, labels);
      std::vector<segmat::PartBox> parts;
      estimation.compute(parts);
      const double box_seconds = std::chrono::duration<double>(Clock::now() - start).count();
      std::vector<segmat::OrientedBox> boxes, pca_boxes;
      for (const segmat::PartBox& part : parts) {
        boxes.push_back(part.box);
        std::vector<Eigen::Vector3d> points;
        for (std::size_t f = 0; f < mesh->numFaces(); ++f)
          if (labels[f] == part.part)
            for (int k = 0; k < 3; ++k)
              points.push_back(mesh->vertices[mesh->faces[f][k]]);
        pca_boxes.push_back(segmat::computePcaBox(points));
      }
      const auto s = segmat::scoreBoxAbstraction(*mesh, boxes, resolution, samples);
      const auto p = segmat::scoreBoxAbstraction(*mesh, pca_boxes, resolution, samples);
      std::printf("%-9s %5d %5zu %7.3f %8.4f %9.5f %8.3f %8.4f %7.1f %7.3f\n", category.name, id,
                  parts.size(), s.iou, s.chamfer, s.chamfer_squared, p.iou, p.chamfer, seg_seconds,
                  box_seconds);
      std::fflush(stdout);
      sums.iou += s.iou;
      sums.chamfer += s.chamfer;
      sums.chamfer_squared += s.chamfer_squared;
      sums.pca_iou += p.iou;
      sums.pca_chamfer += p.chamfer;
      ++sums.shapes;
    }
    means.emplace_back(category.name, sums);
  }
  std::printf("\nmeans per category\n%-9s %6s %7s %8s %9s %8s %8s\n", "category", "shapes", "IoU",
              "CD", "CD2", "pcaIoU", "pcaCD");
  for (const auto& [name, s] : means) {
    const double n = std::max(1, s.shapes);
    std::printf("%-9s %6d %7.3f %8.4f %9.5f %8.3f %8.4f\n", name, s.shapes, s.iou / n,
                s.chamfer / n, s.chamfer_squared / n, s.pca_iou / n, s.pca_chamfer / n);
  }
  return 0;
}
