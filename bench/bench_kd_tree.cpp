/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Neighbour search: segmat's kd-tree (src/common/point_kd_tree.h) against pcl::KdTreeFLANN on
 * the same points — every point of an area-uniform sample of a mesh (default: the bundled
 * teddy) asks for its k nearest neighbours, one query at a time as the cloud stages do. Prints
 * the build and query seconds of both (median of the repeats, one thread) and checks that the
 * answers are identical. Run from the repository root.
 *
 * Usage: bench_kd_tree [MESH.off] [--points N] [--k K] [--repeat R]
 */
// The test sampler is compiled in (bench programs link only the library).
#include "../tests/util/cloud_sampler.cpp"

#include "../src/common/point_kd_tree.h"

#include <segmat/common/error.h>
#include <segmat/io/off.h>

#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace {

double
median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double
secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Builds \a Tree on \a cloud and runs one k-NN query per point; returns {build, query} seconds
/// and leaves every answer in \a answers.
template <typename Tree>
std::pair<double, double>
timeTree(const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, int k,
         std::vector<pcl::Indices>& answers)
{
  auto start = std::chrono::steady_clock::now();
  Tree tree;
  tree.setInputCloud(cloud);
  const double build = secondsSince(start);
  start = std::chrono::steady_clock::now();
  std::vector<float> sq;
  answers.resize(cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i)
    tree.nearestKSearch((*cloud)[i], k, answers[i], sq);
  return {build, secondsSince(start)};
}

} // namespace

int
main(int argc, char** argv)
{
  std::string mesh_path = "data/teddy/teddy.off";
  int points = 100000, k = 16, repeat = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points" && i + 1 < argc)
      points = std::stoi(argv[++i]);
    else if (arg == "--k" && i + 1 < argc)
      k = std::stoi(argv[++i]);
    else if (arg == "--repeat" && i + 1 < argc)
      repeat = std::stoi(argv[++i]);
    else if (!arg.empty() && arg[0] != '-')
      mesh_path = arg;
    else {
      std::cerr << "usage: bench_kd_tree [MESH.off] [--points N] [--k K] [--repeat R]\n";
      return 2;
    }
  }
  if (points < 2 || k < 1 || repeat < 1) {
    std::cerr << "bench_kd_tree: --points must be >= 2, --k and --repeat >= 1\n";
    return 2;
  }
  try {
    const segmat::TriangleMesh mesh = segmat::io::loadOff(mesh_path);
    const segmat::test::SampledCloud sample = segmat::test::sampleMesh(mesh, points, 1);
    const auto cloud = sample.toCloud<pcl::PointXYZ>();
    std::vector<double> pcl_build, pcl_query, own_build, own_query;
    bool same = true;
    for (int r = 0; r < repeat; ++r) {
      std::vector<pcl::Indices> a, b;
      const auto [pb, pq] = timeTree<pcl::KdTreeFLANN<pcl::PointXYZ>>(cloud, k, a);
      const auto [ob, oq] = timeTree<segmat::detail::PointKdTree>(cloud, k, b);
      pcl_build.push_back(pb);
      pcl_query.push_back(pq);
      own_build.push_back(ob);
      own_query.push_back(oq);
      same = same && a == b;
    }
    std::printf("%s: %zu points, %d-NN of every point, median of %d:\n", mesh_path.c_str(),
                cloud->size(), k, repeat);
    std::printf("  pcl::KdTreeFLANN       build %.4f s, queries %.4f s\n", median(pcl_build),
                median(pcl_query));
    std::printf("  segmat PointKdTree     build %.4f s, queries %.4f s\n", median(own_build),
                median(own_query));
    std::printf("  answers identical: %s\n", same ? "yes" : "NO");
    return same ? 0 : 1;
  }
  catch (const std::exception& e) {
    std::cerr << "bench_kd_tree: " << e.what() << "\n";
    return 1;
  }
}
