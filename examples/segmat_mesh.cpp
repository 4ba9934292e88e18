/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_mesh: segment a triangle mesh into parts with SEG-MAT; its two medial meshes are computed
 * from it unless given.
 */
#include <segmat/common/error.h>
#include <segmat/geometry/medial_mesh_fit.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include "box_output.h"
#include "detail_level_option.h"
#include "hierarchy_output.h"
#include "option_parser.h"
#include "program_files.h"
#include "progress.h"
#include "render_call.h"
#include "report.h"

#include <cstdio>
#include <string>

using namespace segmat;
using namespace segmat::cli;

namespace {

int
run(int argc, char** argv)
{
  std::string mesh_path, base_path, structured_path, prefix;
  bool save_mat = false, boxes = false, hierarchy = false;
  std::string png;
  CommonOptions common;
  MeshSegmentation segmentation;

  OptionParser parser("segmat_mesh", "MESH -o PREFIX [options]",
                      "Segments a closed triangle mesh into parts with SEG-MAT (medial axis\n"
                      "transform, region growing, graph-cut boundaries).",
                      "segmat_mesh data/teddy/teddy.off -o teddy   # writes teddy.seg, teddy.ply");
  parser.positional("MESH", "closed triangle mesh (.off, .ply, .obj, .stl)", mesh_path);
  parser.add(kInput, "-b", "BASE.ma", "base medial mesh (Q-MAT .ma, e.g. 2000 spheres); with -s.\n"
             "Default: computed from the mesh", [&](const std::string& v) { base_path = v; });
  parser.add(kInput, "-s", "STRUCT.ma", "structured medial mesh (e.g. 15-30 spheres); with -b",
             [&](const std::string& v) { structured_path = v; });
  parser.add(kOutput, "-o", "PREFIX",
             "writes PREFIX.seg (one label per face, PSB format) and PREFIX.ply\n"
             "(faces coloured by part)", [&](const std::string& v) { prefix = v; });
  parser.flag(kOutput, "--save-mat",
              "also write the computed medial meshes to PREFIX_base.ma and\nPREFIX_struct.ma",
              save_mat);
  parser.add(kParameters, "-g", "DELTA0", "growing threshold (default 0.015)",
             [&](const std::string& v) {
               segmentation.setGrowingThreshold(parseNumberIn(v, 1e-9, 1e9, "a threshold > 0"));
             });
  parser.add(kParameters, "-n", "ETA", "minimal region, fraction of the base MAT's spheres\n"
             "(default 0.002)", [&](const std::string& v) {
               segmentation.setMinRegionFraction(parseNumberIn(v, 0.0, 1.0, "a fraction in [0, 1]"));
             });
  parser.add(kParameters, "--seed", "S", "seed of the merging's visibility sampling\n"
             "(default 386727)", [&](const std::string& v) {
               segmentation.setRandomSeed(static_cast<unsigned>(parseInteger(v, 0, 4294967295L)));
             });
  parser.add(kParameters, "--max-bend", "DEG", "largest turn of a bulky tube inside one part\n"
             "(default 60; 90 = off, as in SEG-MAT)", [&](const std::string& v) {
               segmentation.setMaxBendAngle(parseNumberIn(v, 1e-9, 90.0, "an angle in (0, 90]"));
             });
  parser.flag(kParameters, "--reference-crease",
              "price concave creases in the surface cut as SEG-MAT does (default:\n"
              "a sharp concave crease is much cheaper to cut than a shallow one)",
              [&] { segmentation.setCreaseModel(CreaseModel::Reference); });
  parser.flag(kParameters, "--input-axes",
              "segment in the mesh's own orientation instead of its principal axes\n"
              "(a rotated mesh may then get other parts; docs/robustness.md)",
              [&] { segmentation.setPrincipalAxesFrame(false); });
  parser.flag(kOutput, "--boxes",
              "also write PREFIX_boxes.json and PREFIX_boxes.ply: one tight oriented\n"
              "box per part (docs/abstraction.md)", boxes);
  parser.flag(kOutput, "--hierarchy",
              "also segment at every level, coarse to fine, each part inside one part\n"
              "of the level above; writes PREFIX_level0.seg.. and PREFIX_hierarchy.json",
              hierarchy);
  parser.add(kOutput, "--png", "FILE", "also draw the parts into a PNG (segmat_render, with VTK)",
             [&](const std::string& v) { png = v; });
  parser.add(kParameters, "--level", "L",
             "coarse, default or fine: sets -g and -n together (docs/levels.md);\n"
             "a number in [-1, 1] goes between them (-1 coarse, 0 default, 1 fine)",
             [&](const std::string& v) { applyDetailLevel(segmentation, v); });
  addCommonOptions(parser, common);

  if (!parser.parse(argc, argv))
    return kExitOk;
  if (mesh_path.empty() || prefix.empty())
    throw UsageError("MESH and -o PREFIX are required");
  if (base_path.empty() != structured_path.empty())
    throw UsageError("give both -b and -s, or neither (the medial meshes are then computed)");
  if (save_mat && !base_path.empty())
    throw UsageError("--save-mat writes computed medial meshes: not with -b and -s");

  std::vector<std::string> inputs{mesh_path};
  if (!base_path.empty())
    inputs.insert(inputs.end(), {base_path, structured_path});
  for (const std::string& input : inputs)
    checkInputFile(input);
  io::OutputSet outputs(inputs);
  std::vector<std::string> suffixes{".seg", ".ply"};
  if (save_mat)
    suffixes.insert(suffixes.end(), {"_base.ma", "_struct.ma"});
  if (boxes)
    for (const std::string& suffix : boxSuffixes())
      suffixes.push_back(suffix);
  if (hierarchy)
    for (const std::string& suffix : hierarchySuffixes())
      suffixes.push_back(suffix);
  declareOutputs(outputs, prefix, suffixes);
  if (!png.empty())
    asInput([&] { outputs.add(png); });
  segmentation.setNumberOfThreads(resolveThreads(parser.program(), common.threads));

  Progress progress(parser.program(), common.quiet);
  progress.stage("reading " + mesh_path);
  TriangleMesh::Ptr mesh;
  MedialMesh::Ptr base, structured;
  asInput([&] {
    mesh = std::make_shared<TriangleMesh>(io::loadMesh(mesh_path));
    if (mesh->empty())
      throw Error(mesh_path, 0, "the mesh has no faces");
    checkMeshSize(mesh_path, *mesh);
    if (!base_path.empty()) {
      base = std::make_shared<MedialMesh>(io::loadMa(base_path));
      structured = std::make_shared<MedialMesh>(io::loadMa(structured_path));
      if (base->empty())
        throw Error(base_path, 0, "the base medial mesh has no spheres");
      std::string reason;
      for (const auto& [path, mat] : {std::make_pair(base_path, base),
                                      std::make_pair(structured_path, structured)})
        if (!MedialMeshFit().check(*mat, *mesh, reason))
          throw Error(path, 0, "does not fit the mesh " + mesh_path + ": " + reason);
    }
  });
  warnIfNotClosed(parser.program(), mesh_path, *mesh);
  const double load_seconds = progress.stage(base ? "segmenting" :
                                             "computing the medial meshes and segmenting");

  segmentation.setInputMesh(mesh);
  if (base) { // otherwise segment() computes them
    segmentation.setBaseMat(base);
    segmentation.setStructuredMat(structured);
  }
  std::vector<int> labels;
  if (!segmentation.segment(labels))
    throw Error(mesh_path, 0, "segmentation failed (see the message above)");
  progress.stage("writing " + prefix + ".*");
  io::saveSeg(outputs.temporary(prefix + ".seg"), labels);
  io::saveColoredMeshPly(outputs.temporary(prefix + ".ply"), *mesh, labels);
  if (save_mat) {
    io::saveMa(outputs.temporary(prefix + "_base.ma"), *segmentation.getBaseMat());
    io::saveMa(outputs.temporary(prefix + "_struct.ma"), *segmentation.getStructuredMat());
  }
  std::vector<pcl::PointIndices> parts;
  segmentation.getParts(parts);
  StageTimings seconds{{"load", load_seconds}};
  for (const auto& stage : segmentation.getStageSeconds())
    seconds.push_back(stage);
  if (boxes)
    writePartBoxes(outputs, prefix, mesh, labels);
  if (hierarchy) // after the report's figures were taken: it segments again
    writeHierarchy(outputs, prefix, segmentation);
  if (!png.empty())
    renderPicture(mesh_path, outputs.temporary(prefix + ".seg"), outputs.temporary(png));
  outputs.commit(); // every output appears together, or none
  seconds.emplace_back("write", progress.done());

  if (common.json) {
    const MedialMeshEstimationStatistics& mat = segmentation.getMatStatistics();
    std::printf("{\"parts\": %zu, \"mat_computed\": %s, \"samples\": %zu, "
                "\"initial_spheres\": %zu, \"base_spheres\": %zu, "
                "\"structured_spheres\": %zu, \"noise\": {\"sigma\": %.6g, "
                "\"remaining_sigma\": %.6g, \"passes\": %d}, "
                "\"face_counts\": %s, \"seconds\": %s}\n",
                parts.size(), segmentation.hasComputedMats() ? "true" : "false",
                mat.voronoi.num_samples, mat.initial_spheres,
                segmentation.getBaseMat()->numVertices(),
                segmentation.getStructuredMat()->numVertices(), segmentation.getEstimatedNoise(),
                segmentation.getRemainingNoise(), segmentation.getDenoisingPasses(),
                jsonSizes(parts).c_str(), jsonSeconds(seconds).c_str());
  }
  else {
    printPartsText("face", parts, seconds);
    std::printf("\n");
    printWrote(outputs);
  }
  return kExitOk;
}

} // namespace

int
main(int argc, char** argv)
{
  return runMain("segmat_mesh", [&] { return run(argc, argv); });
}
