/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Cloud-path speed: CloudSegmentation on an area-uniform sample of a mesh (default: the bundled
 * teddy), single thread unless --threads is given. Prints the CPU and wall seconds of
 * segment() (sampling excluded) and the wall seconds of every stage; on a shared machine the CPU
 * time of a single-thread run is the figure to quote. Peak memory: run it under /usr/bin/time -v. Run from the
 * repository root (the default mesh is data/teddy/teddy.off). --noise adds Gaussian noise of that
 * σ (% of the bounding-box diagonal) to the points, as bench_noise does.
 *
 * Usage: bench_cloud [MESH.off] [--points N] [--estimate-normals] [--threads N] [--repeat R]
 *                    [--working N] [--samples N] [--keep-inside] [--noise PERCENT] [--meso-skeleton]
 *                    [--balls N] [--contraction N]   (meso-skeleton parameters)
 */
// The test sampler is compiled in (bench programs link only the library).
#include "../tests/util/cloud_sampler.cpp"

#include <segmat/common/error.h>
#include <segmat/io/off.h>
#include <segmat/segmentation/cloud_segmentation.h>

#include <pcl/console/print.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <iostream>
#include <string>

int
main(int argc, char** argv)
{
  std::string mesh_path = "data/teddy/teddy.off"; // run from the repository root
  std::size_t points = 100000;
  bool estimate = false;
  unsigned threads = 1;
  int repeat = 1;
  segmat::MesoSkeletonParameters params;
  bool meso = false;
  long samples = -1;
  bool keep_inside = false;
  double noise = 0.0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points" && i + 1 < argc)
      points = std::stoul(argv[++i]);
    else if (arg == "--threads" && i + 1 < argc)
      threads = static_cast<unsigned>(std::stoul(argv[++i]));
    else if (arg == "--repeat" && i + 1 < argc)
      repeat = std::stoi(argv[++i]);
    else if (arg == "--estimate-normals")
      estimate = true;
    else if (arg == "--working" && i + 1 < argc)
      params.working_size = std::stoul(argv[++i]);
    else if (arg == "--samples" && i + 1 < argc)
      samples = std::stol(argv[++i]);
    else if (arg == "--noise" && i + 1 < argc)
      noise = std::stod(argv[++i]);
    else if (arg == "--keep-inside")
      keep_inside = true;
    else if (arg == "--meso-skeleton")
      meso = true;
    else if (arg == "--balls" && i + 1 < argc)
      params.ball_count = std::stoul(argv[++i]);
    else if (arg == "--contraction" && i + 1 < argc)
      params.contraction_iterations = std::stoi(argv[++i]);
    else if (!arg.empty() && arg[0] != '-')
      mesh_path = arg;
    else {
      std::cerr << "usage: bench_cloud [MESH.off] [--points N] [--estimate-normals] "
                   "[--threads N] [--repeat R] [--working N] [--samples N] [--keep-inside] "
                   "[--noise PERCENT] [--meso-skeleton] [--balls N] [--contraction N]\n";
      return 2;
    }
  }
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  segmat::TriangleMesh mesh;
  try {
    mesh = segmat::io::loadOff(mesh_path);
  }
  catch (const segmat::Error& e) {
    std::cerr << "bench_cloud: " << e.what() << "\n";
    return 1;
  }
  segmat::test::SampledCloud sampled = segmat::test::sampleMesh(mesh, points, 1);
  if (noise > 0.0) // bench_noise's noise model, in % of the diagonal
    segmat::test::addGaussianNoise(sampled, noise / 100.0, 2);
  const auto cloud = sampled.toPointNormal();
  for (int r = 0; r < repeat; ++r) {
    segmat::CloudSegmentation<pcl::PointNormal> seg;
    seg.setInputCloud(cloud);
    seg.setMesoSkeletonParameters(params);
    seg.setUseInputNormalsFlag(!estimate);
    seg.setNumberOfThreads(threads);
    if (meso)
      seg.setMedialAxis(segmat::CloudMedialAxis::MesoSkeleton);
    seg.getMedialMeshEstimation().getMedialMeshEstimation().setKeepCentresInside(keep_inside);
    if (samples >= 0)
      seg.getMedialMeshEstimation().getMedialMeshEstimation().setMaxSampleCount(
          static_cast<std::size_t>(samples));
    std::vector<pcl::PointIndices> parts;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const bool ok = seg.segment(parts);
    const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // With one thread the CPU time is what the wall time would be on an idle machine.
    std::printf("%s: %zu points, %s normals, %u thread(s): %s, %zu parts, %.3f s CPU, %.3f s "
                "wall (wall per stage:",
                mesh_path.c_str(), cloud->size(), estimate ? "estimated" : "input", threads,
                ok ? "ok" : "FAILED", parts.size(), cpu, total);
    for (const auto& stage : seg.getStageSeconds())
      std::printf(" %s %.3f", stage.name.c_str(), stage.seconds);
    if (meso) {
      const auto& stats = seg.getMesoSkeletonStatistics();
      std::printf(" ) working %zu, balls %zu (%.3f s), medial points %zu\n",
                  stats.working_points, stats.balls, stats.seconds_balls, stats.medial_points);
    }
    else {
      const auto& stats = seg.getMedialMeshEstimation().getStatistics();
      std::printf(" ) samples %zu, initial %zu spheres (sampling %.3f Delaunay %.3f inside %.3f "
                  "assembly %.3f), Q-MAT %.3f s → base %zu, structured %zu\n",
                  stats.voronoi.num_samples, stats.initial_spheres,
                  stats.voronoi.seconds_sampling, stats.voronoi.seconds_delaunay,
                  stats.voronoi.seconds_inside, stats.voronoi.seconds_assembly,
                  stats.seconds_simplification, stats.base_spheres, stats.structured_spheres);
    }
  }
  return 0;
}
