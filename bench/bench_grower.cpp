// Times the grower's stages on teddy with the authors' MATs (data/teddy by default).
// Usage: bench_grower [dir-with-teddy.off-teddy_mat.ma-teddy_smat.ma] [repetitions]
#include <segmat/geometry/aabb_tree.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/io/ma.h>
#include <segmat/io/off.h>
#include <segmat/medial/mat_graph.h>
#include <segmat/segmentation/mat_region_growing.h>
#include <segmat/segmentation/structure_tags.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

using namespace segmat;

int
main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : "data/teddy";
  const int reps = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  using clock = std::chrono::steady_clock;
  const auto ms = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  MedialMesh base, smat;
  TriangleMesh mesh;
  try {
    base = io::loadMa(dir + "/teddy_mat.ma");
    smat = io::loadMa(dir + "/teddy_smat.ma");
    mesh = io::loadOff(dir + "/teddy.off");
  }
  catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  // Best of `reps` for each stage (the machine is shared).
  double t_graph = 1e30, t_tags = 1e30, t_tree = 1e30, t_grow = 1e30;
  std::vector<pcl::PointIndices> parts;
  MatRegionGrowing grower;
  MatGraph::Ptr graph;
  StructureTags tags;
  for (int rep = 0; rep < reps; ++rep) {
    const auto t0 = clock::now();
    graph = std::make_shared<MatGraph>(MatGraph::fromMedialMesh(base));
    const auto t1 = clock::now();
    tags = computeStructureTags(smat, *graph);
    const auto t2 = clock::now();
    const auto tree = std::make_shared<AabbTree>(mesh);
    const auto t3 = clock::now();
    grower.setInputGraph(graph);
    grower.setStructureTags(tags);
    grower.setSegmentVisibility([tree](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return !tree->segmentIntersects(a, b);
    });
    grower.extract(parts);
    const auto t4 = clock::now();
    t_graph = std::min(t_graph, ms(t0, t1));
    t_tags = std::min(t_tags, ms(t1, t2));
    t_tree = std::min(t_tree, ms(t2, t3));
    t_grow = std::min(t_grow, ms(t3, t4));
  }
  std::printf("teddy: %zu nodes, %zu graph edges, %d thin parts\n", graph->numNodes(),
              graph->numEdges(), tags.numThinParts());
  std::printf("grown regions %zu:", grower.getGrownRegionSizes().size());
  for (int s : grower.getGrownRegionSizes())
    std::printf(" %d", s);
  std::printf("\ntiny patches %zu:", grower.getTinyPatchSizes().size());
  for (int s : grower.getTinyPatchSizes())
    std::printf(" %d", s);
  std::printf("\nparts %zu (nodes / coarse nodes):", parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p)
    std::printf(" %zu/%zu", parts[p].indices.size(), grower.getCoarseParts()[p].size());
  std::printf("\nbest of %d, ms: graph %.2f | structure tags %.2f | AABB tree %.2f | "
              "grow+swallow+absorb+merge %.2f | total %.2f\n",
              reps, t_graph, t_tags, t_tree, t_grow, t_graph + t_tags + t_tree + t_grow);
  return 0;
}
