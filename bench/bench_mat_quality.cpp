// How well the base MAT (segmat::MedialMeshEstimation: Voronoi MAT + Q-MAT, 2000 spheres)
// approximates its surface, per shape and over a set.
//
//   bench_mat_quality [--samples N] [--base N] [--directions D] PATH...
//   bench_mat_quality [--samples N] [--directions D] --mat MAT.ma MESH
//   bench_mat_quality [--samples N] [--directions D] --initial PATH...
//
// PATH is a mesh file or a folder of meshes (e.g. ../shared/data/psb-dev/off). With --mat, the
// given medial mesh is measured against MESH instead (e.g. the authors' data/teddy/teddy_mat.ma);
// with --initial, the initial Voronoi MAT (before Q-MAT), to separate the two steps' errors.
// The MAT's volume
// is the union of its medial primitives: every sphere, every cone (edge: the spheres linearly
// interpolated between its two ends) and every slab (triangle: the spheres interpolated over
// it). It is represented by dense interpolated spheres, spaced at most h = 0.005 × the
// bounding-box diagonal D along edges and over triangles; between two such spheres of radius r
// the true envelope bulges out by at most h²/(8r) (< 0.0003·D for r > 0.01·D).
//
// Columns (distances in % of D):
//  - S→M mean/max: N surface samples (area-uniform, seeded) → |min_i (|s − c_i| − r_i)| over the
//    dense spheres. For a sample outside the union this is its exact distance to the union; for a
//    sample inside it is the depth of the deepest sphere containing it, a lower bound of its
//    distance to the union's boundary. "in%" is the share of samples inside the union.
//  - M→S mean/max: envelope samples → exact distance to the surface (MeshDistance). Envelope
//    samples are D Fibonacci directions on each dense sphere (default 24), kept when no other
//    dense sphere contains them (so they lie on the boundary of the union).
//  - H: max of the two maxima (a two-sided Hausdorff estimate).
//  - out: base-MAT sphere centres outside the surface (winding number <= 0.5); nan: spheres with
//    a non-finite centre or radius.
// The summary gives the mean and the maximum of each column over the shapes.
#include "bench_common.h"
#include "bench_args.h"

#include <segmat/common/error.h>
#include <segmat/geometry/mesh_distance.h>
#include <segmat/geometry/sphere_tree.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/medial/medial_mesh_estimation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

/** Dense interpolated spheres of every sphere, cone and slab of \a mat, spaced at most \a h. */
void
denseSpheres(const segmat::MedialMesh& mat, double h, std::vector<Eigen::Vector3d>& centers,
             std::vector<double>& radii)
{
  centers = mat.centers();
  radii = mat.radii();
  auto add = [&](const Eigen::Vector4d& s) {
    centers.push_back(s.head<3>());
    radii.push_back(s[3]);
  };
  for (const Eigen::Vector2i& e : mat.edges()) {
    const Eigen::Vector4d a = mat.sphere(e[0]), b = mat.sphere(e[1]);
    const int steps = std::min(64, static_cast<int>(std::ceil((a - b).head<3>().norm() / h)));
    for (int i = 1; i < steps; ++i)
      add(a + (b - a) * (static_cast<double>(i) / steps));
  }
  for (const Eigen::Vector3i& t : mat.triangles()) {
    const Eigen::Vector4d a = mat.sphere(t[0]), b = mat.sphere(t[1]), c = mat.sphere(t[2]);
    const double longest = std::max({(a - b).head<3>().norm(), (b - c).head<3>().norm(),
                                     (c - a).head<3>().norm()});
    const int n = std::min(32, static_cast<int>(std::ceil(longest / h)));
    for (int i = 1; i < n; ++i)
      for (int j = 1; i + j < n; ++j) // interior points; the sides are the edges' samples
        add(a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n));
  }
}

/** Uniform double in [0, 1) from the raw engine output (identical on every standard library). */
double
uniform01(std::mt19937_64& rng)
{
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/** \a count area-uniform samples of \a mesh (fixed seed). */
std::vector<Eigen::Vector3d>
surfaceSamples(const segmat::TriangleMesh& mesh, int count)
{
  std::vector<double> cdf(mesh.numFaces());
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.numFaces(); ++f)
    cdf[f] = (total += mesh.faceArea(static_cast<int>(f)));
  std::vector<Eigen::Vector3d> samples;
  if (!(total > 0.0))
    return samples;
  std::mt19937_64 rng(20220101);
  for (int i = 0; i < count; ++i) {
    const double pick = uniform01(rng) * total;
    const std::size_t f = std::min<std::size_t>(
        std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin(), mesh.numFaces() - 1);
    const double u = std::sqrt(uniform01(rng)), v = uniform01(rng);
    const Eigen::Vector3i& t = mesh.faces[f];
    samples.push_back((1.0 - u) * mesh.vertices[t[0]] + u * (1.0 - v) * mesh.vertices[t[1]] +
                      u * v * mesh.vertices[t[2]]);
  }
  return samples;
}

/** \a count unit directions spread evenly (Fibonacci sphere). */
std::vector<Eigen::Vector3d>
fibonacciDirections(int count)
{
  std::vector<Eigen::Vector3d> dirs;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    dirs.emplace_back(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
  }
  return dirs;
}

struct Stats
{
  double mean = 0.0, max = 0.0;
};

Stats
stats(const std::vector<double>& v)
{
  Stats s;
  for (double x : v) {
    s.mean += x;
    s.max = std::max(s.max, x);
  }
  if (!v.empty())
    s.mean /= static_cast<double>(v.size());
  return s;
}

} // namespace

int
main(int argc, char** argv)
{
  segmat::bench::restartSingleThreaded(argv);
  int num_samples = 20000, base_target = 2000, num_directions = 24;
  std::string given_mat;
  bool measure_initial = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] { return segmat::bench::intArgument(argc, argv, i); };
    if (arg == "--samples")
      num_samples = std::max(1, value());
    else if (arg == "--base")
      base_target = std::max(1, value());
    else if (arg == "--directions")
      num_directions = std::max(4, value());
    else if (arg == "--initial")
      measure_initial = true;
    else if (arg == "--mat") {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "missing value after --mat\n");
        return 2;
      }
      given_mat = argv[++i];
    }
    else
      segmat::bench::appendPaths(arg, files);
  }
  if (files.empty()) {
    std::fprintf(stderr,
                 "usage: bench_mat_quality [--samples N] [--base N] [--directions D] PATH...\n");
    return 2;
  }
  const std::vector<Eigen::Vector3d> directions = fibonacciDirections(num_directions);

  std::printf("%-12s %6s %6s | %7s %7s %5s | %7s %7s | %7s | %4s %4s\n", "mesh", "faces", "base",
              "S>M_avg", "S>M_max", "in%", "M>S_avg", "M>S_max", "H", "out", "nan");
  std::vector<double> col_sm_mean, col_sm_max, col_ms_mean, col_ms_max, col_h;
  std::size_t total_out = 0, total_nan = 0, total_spheres = 0;
  for (const std::string& path : files) {
    const segmat::TriangleMesh::Ptr mesh = segmat::bench::loadMeshOrSkip(path);
    if (!mesh)
      continue;
    segmat::MedialMesh base, structured;
    if (!given_mat.empty()) {
      try {
        base = segmat::io::loadMa(given_mat);
      }
      catch (const segmat::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
      }
    }
    else {
      segmat::MedialMeshEstimation estimation;
      estimation.setInputMesh(mesh);
      estimation.setBaseTarget(base_target);
      if (!estimation.compute(base, structured)) {
        std::fprintf(stderr, "failed: %s\n", path.c_str());
        continue;
      }
      if (measure_initial)
        base = estimation.getInitialMat();
    }
    const double diagonal = mesh->boundingBoxDiagonal();

    std::size_t nan = 0, outside = 0;
    const segmat::WindingNumber winding(*mesh);
    for (std::size_t v = 0; v < base.numVertices(); ++v) {
      if (!base.centers()[v].allFinite() || !std::isfinite(base.radii()[v])) {
        ++nan;
        continue;
      }
      outside += !winding.inside(base.centers()[v]);
    }

    std::vector<Eigen::Vector3d> centers;
    std::vector<double> radii;
    denseSpheres(base, 0.005 * diagonal, centers, radii);
    const segmat::SphereTree union_of_spheres(centers, radii);
    const segmat::MeshDistance surface(*mesh);

    std::vector<double> sm;
    std::size_t inside_union = 0;
    int hint = -1;
    for (const Eigen::Vector3d& s : surfaceSamples(*mesh, num_samples)) {
      const double e = union_of_spheres.signedDistance(s, -1e300, &hint);
      inside_union += e < 0.0;
      sm.push_back(std::abs(e) / diagonal);
    }
    std::vector<double> ms;
    const double on_boundary = -1e-9 * diagonal; // rounding of |q − c| − r for q on a sphere
    for (std::size_t i = 0; i < centers.size(); ++i)
      for (const Eigen::Vector3d& dir : directions) {
        const Eigen::Vector3d q = centers[i] + radii[i] * dir;
        if (union_of_spheres.signedDistance(q, on_boundary, &hint) < on_boundary)
          continue; // inside another sphere: not on the envelope
        ms.push_back(surface.distance(q) / diagonal);
      }

    const Stats s_sm = stats(sm), s_ms = stats(ms);
    const double h = std::max(s_sm.max, s_ms.max);
    const std::string name = std::filesystem::path(path).filename().string();
    std::printf("%-12s %6zu %6zu | %7.3f %7.3f %5.1f | %7.3f %7.3f | %7.3f | %4zu %4zu\n",
                name.c_str(), mesh->numFaces(), base.numVertices(), 100 * s_sm.mean,
                100 * s_sm.max, 100.0 * inside_union / std::max<std::size_t>(1, sm.size()),
                100 * s_ms.mean, 100 * s_ms.max, 100 * h, outside, nan);
    std::fflush(stdout);
    col_sm_mean.push_back(s_sm.mean);
    col_sm_max.push_back(s_sm.max);
    col_ms_mean.push_back(s_ms.mean);
    col_ms_max.push_back(s_ms.max);
    col_h.push_back(h);
    total_out += outside;
    total_nan += nan;
    total_spheres += base.numVertices();
  }
  if (col_h.empty())
    return 1;
  const Stats a = stats(col_sm_mean), b = stats(col_sm_max), c = stats(col_ms_mean),
              d = stats(col_ms_max), e = stats(col_h);
  std::printf("\n%zu shapes, %% of the bounding-box diagonal "
              "(mean over shapes / max over shapes):\n",
              col_h.size());
  std::printf("  surface -> MAT   mean %.3f / %.3f   max %.3f / %.3f\n", 100 * a.mean, 100 * a.max,
              100 * b.mean, 100 * b.max);
  std::printf("  MAT -> surface   mean %.3f / %.3f   max %.3f / %.3f\n", 100 * c.mean, 100 * c.max,
              100 * d.mean, 100 * d.max);
  std::printf("  two-sided (H)    %.3f / %.3f\n", 100 * e.mean, 100 * e.max);
  std::printf("  centres outside the surface: %zu of %zu; non-finite spheres: %zu\n", total_out,
              total_spheres, total_nan);
  return 0;
}
