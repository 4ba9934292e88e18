/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_mat: the base and structured medial meshes of a triangle mesh (Voronoi MAT + Q-MAT).
 */
#include <segmat/common/error.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/medial/medial_mesh_estimation.h>

#include "cli_options.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

namespace {

const char* const kUsage =
    "usage: segmat_mat MESH -o PREFIX [--base N] [--struct N] [--spacing S] [--max-samples M]\n"
    "                  [--threads T] [--json]\n"
    "  MESH             closed triangle mesh (.off, .ply, .obj, .stl)\n"
    "  -o PREFIX        writes PREFIX_base.ma and PREFIX_struct.ma (Q-MAT .ma format)\n"
    "  --base N         spheres of the base MAT (default 2000)\n"
    "  --struct N       spheres of the structured MAT (default max(15, 0.001 x initial))\n"
    "  --spacing S      largest surface-sample gap / bounding-box diagonal (default 0.015;\n"
    "                   0 = mesh vertices only, as Q-MAT)\n"
    "  --max-samples M  largest number of surface samples (default 12000; 0 = no limit)\n"
    "  --threads T      threads (default 1; 0 = all); the output does not depend on it\n"
    "  --json           print one JSON object instead of the text report\n";



} // namespace

using namespace segmat::cli;

int
main(int argc, char** argv)
{
  std::string mesh_path, prefix;
  bool json = false;
  segmat::MedialMeshEstimation estimation;
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
      else if (arg == "--base")
        estimation.setBaseTarget(static_cast<int>(parseInteger(arg, value(), 1)));
      else if (arg == "--struct")
        estimation.setStructuredTarget(static_cast<int>(parseInteger(arg, value(), 1)));
      else if (arg == "--spacing")
        estimation.setMaxSpacing(parseNonNegative(arg, value()));
      else if (arg == "--max-samples")
        estimation.setMaxSampleCount(static_cast<std::size_t>(parseInteger(arg, value(), 0)));
      else if (arg == "--threads")
        estimation.setNumberOfThreads(static_cast<unsigned>(parseInteger(arg, value(), 0)));
      else if (arg == "--json")
        json = true;
      else if (!arg.empty() && arg[0] == '-')
        throw segmat::Error("unknown option " + arg);
      else if (mesh_path.empty())
        mesh_path = arg;
      else
        throw segmat::Error("more than one mesh given ('" + mesh_path + "', '" + arg + "')");
    }
    if (mesh_path.empty() || prefix.empty())
      throw segmat::Error("a mesh and -o PREFIX are required");

    const auto start = std::chrono::steady_clock::now();
    const auto mesh = std::make_shared<const segmat::TriangleMesh>(segmat::io::loadMesh(mesh_path));
    const double seconds_load =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    estimation.setInputMesh(mesh);
    segmat::MedialMesh base, structured;
    if (!estimation.compute(base, structured))
      throw segmat::Error(mesh_path, 0, "no medial mesh could be computed (see the message above)");

    const auto before_save = std::chrono::steady_clock::now();
    const std::string base_path = prefix + "_base.ma", structured_path = prefix + "_struct.ma";
    segmat::io::saveMa(base_path, base);
    segmat::io::saveMa(structured_path, structured);
    const double seconds_save =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - before_save).count();

    const segmat::MedialMeshEstimationStatistics& st = estimation.getStatistics();
    if (json) {
      std::printf("{\"mesh\": \"%s\", \"faces\": %zu, \"samples\": %zu, "
                  "\"initial\": {\"spheres\": %zu, \"edges\": %zu, \"triangles\": %zu}, "
                  "\"base\": {\"spheres\": %zu, \"edges\": %zu, \"triangles\": %zu}, "
                  "\"structured\": {\"spheres\": %zu, \"edges\": %zu, \"triangles\": %zu}, "
                  "\"seconds\": {\"load\": %.6f, \"sampling\": %.6f, \"delaunay\": %.6f, "
                  "\"inside\": %.6f, \"assembly\": %.6f, \"initial\": %.6f, "
                  "\"simplification\": %.6f, \"save\": %.6f}}\n",
                  mesh_path.c_str(), mesh->numFaces(), st.voronoi.num_samples,
                  st.initial_spheres, st.voronoi.num_edges, st.voronoi.num_triangles,
                  base.numVertices(), base.numEdges(), base.numTriangles(),
                  structured.numVertices(), structured.numEdges(), structured.numTriangles(),
                  seconds_load, st.voronoi.seconds_sampling, st.voronoi.seconds_delaunay,
                  st.voronoi.seconds_inside, st.voronoi.seconds_assembly, st.seconds_initial,
                  st.seconds_simplification, seconds_save);
    }
    else {
      std::printf("mesh        %s: %zu faces (%.3f s to load)\n", mesh_path.c_str(),
                  mesh->numFaces(), seconds_load);
      std::printf("initial MAT %zu spheres, %zu edges, %zu triangles from %zu samples "
                  "(%.3f s: sampling %.3f, Delaunay %.3f, inside %.3f, assembly %.3f)\n",
                  st.initial_spheres, st.voronoi.num_edges, st.voronoi.num_triangles,
                  st.voronoi.num_samples, st.seconds_initial, st.voronoi.seconds_sampling,
                  st.voronoi.seconds_delaunay, st.voronoi.seconds_inside,
                  st.voronoi.seconds_assembly);
      std::printf("Q-MAT       %.3f s\n", st.seconds_simplification);
      std::printf("base MAT    %zu spheres, %zu edges, %zu triangles -> %s\n", base.numVertices(),
                  base.numEdges(), base.numTriangles(), base_path.c_str());
      std::printf("struct MAT  %zu spheres, %zu edges, %zu triangles -> %s\n",
                  structured.numVertices(), structured.numEdges(), structured.numTriangles(),
                  structured_path.c_str());
      std::printf("total       %.3f s (save %.3f s)\n",
                  seconds_load + st.seconds_total + seconds_save, seconds_save);
    }
    return 0;
  }
  catch (const std::exception& e) {
    std::cerr << "segmat_mat: " << e.what() << "\n";
    if (mesh_path.empty() || prefix.empty())
      std::cerr << kUsage;
    return 1;
  }
}
