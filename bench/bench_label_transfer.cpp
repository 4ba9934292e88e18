/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * bench_label_transfer: the surface transfer of SEG-MAT on teddy, in pieces — face graph,
 * data term, α-expansion — and the cloud transfer on area-uniform samples of teddy's surface
 * (normals from the faces), medians over repetitions, one thread. CPU seconds are given too:
 * wall time is inflated when other processes share the cores. With -s K the mesh is teddy
 * subdivided K times (4^K times the faces, the same surface), and the mesh transfer is timed
 * both as it is and cut whole (setMaxFullCutElements(0)), with the Rand distance between the
 * two labellings and their energies.
 *
 *   build/bin/bench_label_transfer [-r REPETITIONS] [-n POINTS[,POINTS...]] [-s K]
 * Run from the repository root.
 */
#include "bench_common.h"
#include "shape_variants.h"

#include <segmat/geometry/aabb_tree.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/segmentation/label_transfer.h>
#include <segmat/segmentation/mat_region_growing.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Timing
{
  double wall = 0.0;
  double cpu = 0.0;
};

// Median wall and CPU seconds of `repetitions` runs of `work`.
Timing
timeIt(int repetitions, const std::function<void()>& work)
{
  std::vector<double> wall, cpu;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    work();
    cpu.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return {segmat::bench::median(wall), segmat::bench::median(cpu)};
}

void
report(const char* what, const Timing& t)
{
  std::printf("  %-40s wall %8.4f s   cpu %8.4f s\n", what, t.wall, t.cpu);
}

} // namespace

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  int repetitions = 5;
  std::vector<long> sizes{100000, 1000000};
  int subdivisions = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-r" && i + 1 < argc)
      repetitions = std::max(1, std::atoi(argv[++i]));
    else if (arg == "-s" && i + 1 < argc)
      subdivisions = std::max(0, std::atoi(argv[++i]));
    else if (arg == "-n" && i + 1 < argc) {
      sizes.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
        sizes.push_back(std::max(1L, std::atol(item.c_str())));
    }
    else {
      std::fprintf(stderr, "usage: bench_label_transfer [-r N] [-n POINTS[,POINTS...]] [-s K]\n");
      return 2;
    }
  }

  try {
    auto mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadMesh("data/teddy/teddy.off"));
    for (int k = 0; k < subdivisions; ++k)
      *mesh = segmat::bench::subdivided(*mesh);
    const segmat::MedialMesh base = segmat::io::loadMa("data/teddy/teddy_mat.ma");
    const segmat::MedialMesh structured = segmat::io::loadMa("data/teddy/teddy_smat.ma");
    auto graph = std::make_shared<segmat::MatGraph>(segmat::MatGraph::fromMedialMesh(base));
    const segmat::AabbTree surface(*mesh);
    segmat::MatRegionGrowing grower;
    grower.setInputGraph(graph);
    grower.setStructureTags(segmat::computeStructureTags(structured, *graph));
    grower.setSegmentVisibility([&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return !surface.segmentIntersects(a, b);
    });
    std::vector<pcl::PointIndices> grown;
    if (!grower.extract(grown)) {
      std::fprintf(stderr, "region growing failed\n");
      return 1;
    }
    const std::vector<std::vector<int>>& parts = grower.getCoarseParts();
    std::size_t coarse = 0;
    for (const auto& p : parts)
      coarse += p.size();
    std::printf("teddy%s: %zu faces, %zu parts, %zu coarse nodes; median of %d runs, "
                "OMP_NUM_THREADS=%s\n",
                subdivisions > 0 ? " subdivided" : "", mesh->numFaces(), parts.size(), coarse,
                repetitions,
                std::getenv("OMP_NUM_THREADS"));

    std::vector<Eigen::Vector3d> centroids(mesh->numFaces());
    for (std::size_t f = 0; f < centroids.size(); ++f)
      centroids[f] = mesh->faceCentroid(static_cast<int>(f));
    std::vector<segmat::PottsEdge> edges;
    Eigen::MatrixXd costs;
    report("mesh: face graph (cached per mesh)", timeIt(repetitions, [&] {
             edges = segmat::computeMeshSmoothnessEdges(*mesh, 0.3);
           }));
    report("mesh: data term", timeIt(repetitions, [&] {
             costs = segmat::computePartDistanceCosts(centroids, *graph, parts);
           }));
    segmat::AlphaExpansion solver;
    std::vector<int> labels;
    report("mesh: alpha-expansion", timeIt(repetitions, [&] {
             solver.setUnaryCosts(costs);
             solver.setEdges(edges);
             solver.compute(labels);
           }));
    std::printf("  (%d cycles, %d moves)\n", solver.getCycles(), solver.getMoves());
    double energy = 0.0;
    report("mesh: MeshLabelTransfer, fresh", timeIt(repetitions, [&] {
             segmat::MeshLabelTransfer transfer;
             transfer.setInputMesh(mesh);
             transfer.setInputGraph(graph);
             transfer.setParts(parts);
             transfer.transfer(labels);
             energy = transfer.getEnergy();
           }));
    if (mesh->numFaces() > segmat::MeshLabelTransfer().getMaxFullCutElements()) {
      std::vector<int> whole;
      double whole_energy = 0.0;
      report("mesh: MeshLabelTransfer, cut whole", timeIt(repetitions, [&] {
               segmat::MeshLabelTransfer transfer;
               transfer.setMaxFullCutElements(0);
               transfer.setInputMesh(mesh);
               transfer.setInputGraph(graph);
               transfer.setParts(parts);
               transfer.transfer(whole);
               whole_energy = transfer.getEnergy();
             }));
      std::printf("  coarse to fine against cut whole: Rand distance %.4f, energy %.0f / %.0f "
                  "(%+.2f %%)\n",
                  segmat::bench::randDistance(labels, whole), energy, whole_energy,
                  100.0 * (energy / whole_energy - 1.0));
    }

    // Area-uniform samples, deterministic (floats from the raw engine output).
    std::vector<double> cumulative(mesh->numFaces());
    double area = 0.0;
    for (std::size_t f = 0; f < mesh->numFaces(); ++f)
      cumulative[f] = area += mesh->faceArea(static_cast<int>(f));
    for (long n : sizes) {
      std::mt19937 rng(2024u);
      const auto unit = [&] { return static_cast<double>(rng()) / 4294967296.0; };
      auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
      auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
      for (long i = 0; i < n; ++i) {
        const std::size_t f = std::min<std::size_t>(
            std::lower_bound(cumulative.begin(), cumulative.end(), unit() * area) -
                cumulative.begin(),
            mesh->numFaces() - 1);
        double a = unit(), b = unit();
        if (a + b > 1.0)
          a = 1.0 - a, b = 1.0 - b;
        const Eigen::Vector3i& t = mesh->faces[f];
        const Eigen::Vector3d p = mesh->vertices[t[0]] +
                                  a * (mesh->vertices[t[1]] - mesh->vertices[t[0]]) +
                                  b * (mesh->vertices[t[2]] - mesh->vertices[t[0]]);
        const Eigen::Vector3d normal = mesh->faceNormal(static_cast<int>(f));
        cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
        normals->push_back(pcl::Normal(normal.x(), normal.y(), normal.z()));
      }
      const std::string what = "cloud " + std::to_string(n) + ": CloudLabelTransfer, fresh";
      report(what.c_str(), timeIt(repetitions, [&] {
               segmat::CloudLabelTransfer transfer;
               transfer.setInputCloud(cloud);
               transfer.setInputNormals(normals);
               transfer.setInputGraph(graph);
               transfer.setParts(parts);
               transfer.transfer(labels);
             }));
    }
  }
  catch (const std::exception& e) {
    std::fprintf(stderr, "bench_label_transfer: %s\n", e.what());
    return 1;
  }
  return 0;
}
