// Timing of the medial meshes SEG-MAT needs: the initial Voronoi MAT (segmat::VoronoiMat) and its
// Q-MAT simplification to the base and structured MATs (segmat::QmatSimplification), per shape.
//
//   bench_mat [--runs N] [--base N] [--struct N] [--max-samples M] [--free-centres] PATH...
//
// PATH is a mesh file or a folder of meshes (e.g. ../shared/data/psb-dev/off). For every mesh it
// prints the face count, the initial MAT's size, the median over N runs (default 3) of the
// initial step and of the simplification (with the surface set, as MedialMeshEstimation does;
// --free-centres leaves it out): CPU seconds of this process (single thread; steadier than wall
// time on a shared machine) and wall seconds; then the median and maximum over the shapes. Runs
// single-threaded unless OMP_NUM_THREADS is set. --max-samples is VoronoiMat's sample cap
// (default 12000; 0 = none, for larger initial MATs).
#include "bench_common.h"
#include "bench_args.h"

#include <segmat/common/error.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/io/mesh.h>
#include <segmat/medial/qmat_simplification.h>
#include <segmat/medial/voronoi_mat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>


namespace {

double
cpuSeconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double
wallSeconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

struct Timing
{
  double cpu = 0.0, wall = 0.0;
};

template <typename F>
Timing
timeIt(F&& work)
{
  const double c0 = cpuSeconds(), w0 = wallSeconds();
  work();
  return {cpuSeconds() - c0, wallSeconds() - w0};
}

} // namespace

using segmat::bench::median;

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  int runs = 3, base_target = 2000, structured_target = -1, max_samples = -1;
  bool keep_inside = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] { return segmat::bench::intArgument(argc, argv, i); };
    if (arg == "--runs")
      runs = std::max(1, value());
    else if (arg == "--base")
      base_target = value();
    else if (arg == "--struct")
      structured_target = value();
    else if (arg == "--max-samples")
      max_samples = value();
    else if (arg == "--free-centres")
      keep_inside = false;
    else
      segmat::bench::appendPaths(arg, files);
  }
  if (files.empty()) {
    std::fprintf(stderr,
                 "usage: bench_mat [--runs N] [--base N] [--struct N] [--max-samples M] "
                 "[--free-centres] PATH...\n");
    return 2;
  }

  std::printf("%-28s %7s %7s %7s %7s | %8s %8s | %8s %8s | %6s %5s\n", "mesh", "faces", "samples",
              "spheres", "edges", "init_cpu", "init_wl", "qmat_cpu", "qmat_wl", "base", "struct");
  std::vector<double> init_cpu, qmat_cpu, total_cpu, spheres;
  for (const std::string& path : files) {
    const segmat::TriangleMesh::Ptr mesh = segmat::bench::loadMeshOrSkip(path);
    if (!mesh)
      continue;
    std::vector<double> ic, iw, qc, qw;
    auto initial = std::make_shared<segmat::MedialMesh>();
    segmat::MedialMesh base, structured;
    std::size_t samples = 0;
    bool ok = true;
    // As MedialMeshEstimation: one winding-number hierarchy, built (and timed) with the initial
    // MAT, serves both stages.
    segmat::WindingNumber::ConstPtr winding_number;
    for (int r = 0; r < runs && ok; ++r) {
      segmat::VoronoiMat voronoi;
      voronoi.setInputMesh(mesh);
      if (max_samples >= 0)
        voronoi.setMaxSampleCount(static_cast<std::size_t>(max_samples));
      const Timing t = timeIt([&] {
        winding_number = std::make_shared<const segmat::WindingNumber>(*mesh);
        voronoi.setWindingNumber(winding_number);
        ok = voronoi.compute(*initial);
      });
      samples = voronoi.getStatistics().num_samples;
      ic.push_back(t.cpu);
      iw.push_back(t.wall);
    }
    for (int r = 0; r < runs && ok; ++r) {
      segmat::QmatSimplification qmat;
      qmat.setInputMat(initial);
      if (keep_inside) {
        qmat.setInputSurface(mesh); // as MedialMeshEstimation: keeps centres inside
        qmat.setWindingNumber(winding_number);
      }
      else
        qmat.setNormalisationScale(mesh->boundingBoxDiagonal());
      qmat.setBaseTarget(base_target);
      qmat.setStructuredTarget(structured_target);
      const Timing t = timeIt([&] { ok = qmat.compute(base, structured); });
      qc.push_back(t.cpu);
      qw.push_back(t.wall);
    }
    if (!ok) {
      std::fprintf(stderr, "failed: %s\n", path.c_str());
      continue;
    }
    const std::string name = std::filesystem::path(path).filename().string();
    std::printf("%-28s %7zu %7zu %7zu %7zu | %8.3f %8.3f | %8.3f %8.3f | %6zu %5zu\n", name.c_str(),
                mesh->numFaces(), samples, initial->numVertices(), initial->numEdges(), median(ic),
                median(iw), median(qc), median(qw), base.numVertices(), structured.numVertices());
    init_cpu.push_back(median(ic));
    qmat_cpu.push_back(median(qc));
    total_cpu.push_back(median(ic) + median(qc));
    spheres.push_back(static_cast<double>(initial->numVertices()));
  }
  if (init_cpu.empty())
    return 1;
  std::printf("\n%zu shapes (CPU seconds, median of %d runs each):\n", init_cpu.size(), runs);
  std::printf("  initial spheres  median %.0f  max %.0f\n", median(spheres),
              *std::max_element(spheres.begin(), spheres.end()));
  std::printf("  initial MAT      median %.3f  max %.3f\n", median(init_cpu),
              *std::max_element(init_cpu.begin(), init_cpu.end()));
  std::printf("  Q-MAT            median %.3f  max %.3f\n", median(qmat_cpu),
              *std::max_element(qmat_cpu.begin(), qmat_cpu.end()));
  std::printf("  both             median %.3f  max %.3f\n", median(total_cpu),
              *std::max_element(total_cpu.begin(), total_cpu.end()));
  return 0;
}
