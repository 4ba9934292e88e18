/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_mat: the base and structured medial meshes of a triangle mesh (Voronoi MAT + Q-MAT).
 */
#include <segmat/common/available_memory.h>
#include <segmat/common/error.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/medial/voronoi_mat.h>

#include "option_parser.h"
#include "program_files.h"
#include "progress.h"

#include <cstdio>
#include <memory>
#include <string>

using namespace segmat;
using namespace segmat::cli;

namespace {

int
run(int argc, char** argv)
{
  std::string mesh_path, prefix;
  CommonOptions common;
  MedialMeshEstimation estimation;

  OptionParser parser("segmat_mat", "MESH -o PREFIX [options]",
                      "Computes the base and structured medial meshes of a closed triangle mesh\n"
                      "(Voronoi MAT of surface samples, then Q-MAT simplification).",
                      "segmat_mat data/teddy/teddy.off -o teddy   # writes teddy_base.ma, "
                      "teddy_struct.ma");
  parser.positional("MESH", "closed triangle mesh (.off, .ply, .obj, .stl)", mesh_path);
  parser.add(kOutput, "-o", "PREFIX", "writes PREFIX_base.ma and PREFIX_struct.ma (Q-MAT .ma)",
             [&](const std::string& v) { prefix = v; });
  parser.add(kParameters, "--base", "N", "spheres of the base MAT (default 2000)",
             [&](const std::string& v) {
               estimation.setBaseTarget(static_cast<int>(parseInteger(v, 1, 10000000L)));
             });
  parser.add(kParameters, "--struct", "N",
             "spheres of the structured MAT (default max(15, 0.001 x initial))",
             [&](const std::string& v) {
               estimation.setStructuredTarget(static_cast<int>(parseInteger(v, 1, 10000000L)));
             });
  parser.add(kParameters, "--spacing", "S",
             "largest surface-sample gap / bounding-box diagonal (default 0.015;\n"
             "0 = mesh vertices only, as Q-MAT)",
             [&](const std::string& v) {
               estimation.setMaxSpacing(parseNumberIn(v, 0.0, 1.0, "a fraction in [0, 1]"));
             });
  parser.add(kParameters, "--max-samples", "M",
             "largest number of surface samples (default 12000; 0 = only the\n"
             "memory ceiling, see docs/cli.md)",
             [&](const std::string& v) {
               estimation.setMaxSampleCount(static_cast<std::size_t>(parseInteger(v, 0)));
             });
  addCommonOptions(parser, common);

  if (!parser.parse(argc, argv))
    return kExitOk;
  if (mesh_path.empty() || prefix.empty())
    throw UsageError("a mesh and -o PREFIX are required");
  checkInputFile(mesh_path);
  io::OutputSet outputs({mesh_path});
  declareOutputs(outputs, prefix, {"_base.ma", "_struct.ma"});
  estimation.setNumberOfThreads(resolveThreads(parser.program(), common.threads));

  Progress progress(parser.program(), common.quiet);
  progress.stage("reading " + mesh_path);
  std::shared_ptr<const TriangleMesh> mesh;
  asInput([&] {
    mesh = std::make_shared<const TriangleMesh>(io::loadMesh(mesh_path));
    if (mesh->empty())
      throw Error(mesh_path, 0, "the mesh has no faces");
    checkMeshSize(mesh_path, *mesh);
  });
  warnIfNotClosed(parser.program(), mesh_path, *mesh);
  const double need = VoronoiMat::estimateMemoryBytes(*mesh, estimation.getMaxSpacing(),
                                                      estimation.getMaxSampleCount());
  const double available = static_cast<double>(availableMemoryBytes());
  if (need > available)
    throw UsageError(mesh_path, 0,
                     "--spacing " + std::to_string(estimation.getMaxSpacing()) +
                         " with --max-samples " + std::to_string(estimation.getMaxSampleCount()) +
                         " needs about " + std::to_string(need * 1e-9) + " GB, more than the " +
                         std::to_string(available * 1e-9) +
                         " GB available; raise --spacing or lower --max-samples");
  const double seconds_load = progress.stage("computing the medial meshes");

  estimation.setInputMesh(mesh);
  MedialMesh base, structured;
  if (!estimation.compute(base, structured))
    throw Error(mesh_path, 0, "no medial mesh could be computed (see the message above)");

  progress.stage("writing " + prefix + "_*.ma");
  const std::string base_path = prefix + "_base.ma", structured_path = prefix + "_struct.ma";
  io::saveMa(outputs.temporary(base_path), base);
  io::saveMa(outputs.temporary(structured_path), structured);
  outputs.commit();
  const double seconds_save = progress.done();

  const MedialMeshEstimationStatistics& st = estimation.getStatistics();
  if (common.json) {
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
  return kExitOk;
}

} // namespace

int
main(int argc, char** argv)
{
  return runMain("segmat_mat", [&] { return run(argc, argv); });
}
