// Per-stage timings of the initial Voronoi medial mesh (segmat::VoronoiMat).
//
//   bench_voronoi_mat [--runs N] [--spacing S] [--max-samples M] [--beta B] [--threads T] [--qhull] PATH...
//
// PATH is an OFF file or a folder of OFF files (e.g. ../shared/data/psb-dev/off). For every mesh
// it prints the sample count, tetrahedra, inside tetrahedra, medial vertices/edges/triangles, the
// median wall-clock seconds of each stage over N runs (default 5) and the median CPU seconds of the
// whole compute (steadier than wall time on a busy machine), then the median and maximum totals.
#include <segmat/common/error.h>
#include <segmat/io/off.h>
#include <segmat/medial/voronoi_mat.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace {
double
median(std::vector<double> v)
{
  if (v.empty())
    return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
} // namespace

int
main(int argc, char** argv)
{
  int runs = 5;
  double spacing = -1.0, beta = -1.0;
  unsigned threads = 1;
  long max_samples = -1;
  bool use_qhull = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "missing value after %s\n", arg.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--runs")
      runs = std::max(1, std::atoi(value()));
    else if (arg == "--spacing")
      spacing = std::atof(value());
    else if (arg == "--max-samples")
      max_samples = std::atol(value());
    else if (arg == "--qhull")
      use_qhull = true;
    else if (arg == "--beta")
      beta = std::atof(value());
    else if (arg == "--threads")
      threads = static_cast<unsigned>(std::atoi(value()));
    else if (std::filesystem::is_directory(arg)) {
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.path().extension() == ".off")
          found.push_back(entry.path().string());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    }
    else
      files.push_back(arg);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s [--runs N] [--spacing S] [--max-samples M] [--beta B] "
                         "[--threads T] [--qhull] FILE.off|FOLDER...\n", argv[0]);
    return 2;
  }

  std::printf("%-14s %7s %7s %8s %7s | %7s %7s %7s | %7s %7s %7s %7s %7s %7s\n", "mesh", "faces",
              "samples", "tets", "inside", "V", "E", "F", "sample", "delaun", "inside", "assemb",
              "total", "cpu");
  std::vector<double> totals, cpus;
  int failures = 0;
  for (const std::string& path : files) {
    segmat::TriangleMesh::Ptr mesh;
    try {
      mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadOff(path));
    }
    catch (const segmat::Error& e) {
      std::fprintf(stderr, "%s\n", e.what());
      ++failures;
      continue;
    }
    segmat::VoronoiMat vmat;
    vmat.setInputMesh(mesh);
    if (spacing >= 0.0)
      vmat.setMaxSpacing(spacing);
    if (beta >= 0.0)
      vmat.setWindingNumberAccuracy(beta);
    if (max_samples >= 0)
      vmat.setMaxSampleCount(static_cast<std::size_t>(max_samples));
    if (use_qhull)
      vmat.setDelaunayMethod(segmat::DelaunayMethod::Qhull);
    vmat.setNumberOfThreads(threads);
    std::vector<double> t_sample, t_dt, t_inside, t_assembly, t_total, t_cpu;
    segmat::MedialMesh mat;
    bool ok = true;
    for (int r = 0; r < runs && ok; ++r) {
      const std::clock_t cpu_start = std::clock();
      ok = vmat.compute(mat);
      t_cpu.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
      const auto& s = vmat.getStatistics();
      t_sample.push_back(s.seconds_sampling);
      t_dt.push_back(s.seconds_delaunay);
      t_inside.push_back(s.seconds_inside);
      t_assembly.push_back(s.seconds_assembly);
      t_total.push_back(s.seconds_sampling + s.seconds_delaunay + s.seconds_inside +
                        s.seconds_assembly);
    }
    if (!ok) {
      std::fprintf(stderr, "%s: compute failed\n", path.c_str());
      ++failures;
      continue;
    }
    const auto& s = vmat.getStatistics();
    const std::string name = std::filesystem::path(path).filename().string();
    std::printf("%-14s %7zu %7zu %8zu %7zu | %7zu %7zu %7zu | %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f\n",
                name.c_str(), mesh->faces.size(), s.num_samples, s.num_tetrahedra, s.num_inside,
                s.num_vertices, s.num_edges, s.num_triangles, median(t_sample), median(t_dt),
                median(t_inside), median(t_assembly), median(t_total), median(t_cpu));
    std::fflush(stdout);
    totals.push_back(median(t_total));
    cpus.push_back(median(t_cpu));
  }
  if (totals.size() > 1)
    std::printf("meshes %zu  wall: median %.3f s, max %.3f s  cpu: median %.3f s, max %.3f s\n",
                totals.size(), median(totals), *std::max_element(totals.begin(), totals.end()),
                median(cpus), *std::max_element(cpus.begin(), cpus.end()));
  return failures == 0 ? 0 : 1;
}
