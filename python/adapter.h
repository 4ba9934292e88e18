/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// The one place where the Python module touches the C++ front classes (MeshSegmentation,
// CloudSegmentation): their segment() calls, their setters and getters. A change of those
// signatures is a change here only.

#include <segmat/common/stage_timing.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/segmentation/cloud_segmentation.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <string>
#include <utility>
#include <vector>

namespace segmat_python {

using CloudSegmentation = segmat::CloudSegmentation<pcl::PointNormal>;

/** How a keyword's value is read from Python. */
enum class ParameterKind
{
  Real,  ///< any real number
  Whole, ///< an integer
  Flag   ///< True / False
};

/** One keyword argument of the segmentation functions, mapped onto a setter and a getter. */
template <typename SegmentationT>
struct Parameter
{
  const char* name;
  ParameterKind kind;
  /// Changes the medial step: given to the segmenter's constructor, not to segment().
  bool medial;
  /// Values the C++ type can hold (e.g. unsigned); the setter's own checks come on top.
  double lowest, highest;
  void (*set)(SegmentationT&, double);
  double (*get)(const SegmentationT&);
  const char* doc;
};

/** The parameters of both paths (MatSegmentationParameters: the paper's δ0, η, α, λ, ω). */
template <typename SegmentationT>
std::vector<Parameter<SegmentationT>>
sharedParameters()
{
  using S = SegmentationT;
  constexpr double inf = 1e300;
  return {
      {"delta0", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setGrowingThreshold(v); },
       [](const S& s) { return s.getGrowingThreshold(); }, "growing threshold δ0"},
      {"eta", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setMinRegionFraction(v); },
       [](const S& s) { return s.getMinRegionFraction(); },
       "minimal region, fraction of the medial spheres η"},
      {"alpha", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setAngleWeight(v); },
       [](const S& s) { return s.getAngleWeight(); }, "angle weight α of the growing cost"},
      {"lambda_", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setPrimitiveWeight(v); },
       [](const S& s) { return s.getPrimitiveWeight(); },
       "medial-primitive weight λ of the growing cost"},
      {"omega", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setSmoothnessWeight(v); },
       [](const S& s) { return s.getSmoothnessWeight(); }, "smoothness weight ω of the graph cut"},
      {"min_part", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setMinPartFraction(v); },
       [](const S& s) { return s.getMinPartFraction(); },
       "smallest share of the surface a part keeps after the cut (0: every part)"},
      {"max_bend", ParameterKind::Real, false, -inf, inf,
       [](S& s, double v) { s.setMaxBendAngle(v); },
       [](const S& s) { return s.getMaxBendAngle(); },
       "largest turn of a bulky tube inside one part, degrees (90: off)"},
      {"seed", ParameterKind::Whole, false, 0.0, 4294967295.0,
       [](S& s, double v) { s.setRandomSeed(static_cast<unsigned>(v)); },
       [](const S& s) { return static_cast<double>(s.getRandomSeed()); },
       "seed of the merging's visibility sampling"},
      {"reference_crease", ParameterKind::Flag, false, 0.0, 1.0,
       [](S& s, double v) {
         s.setCreaseModel(v != 0.0 ? segmat::CreaseModel::Reference
                                   : segmat::CreaseModel::SharpConcave);
       },
       [](const S& s) { return s.getCreaseModel() == segmat::CreaseModel::Reference ? 1.0 : 0.0; },
       "price concave creases as SEG-MAT's transfer does"},
  };
}

/** Keyword arguments of segment_mesh() and MeshSegmenter. */
inline const std::vector<Parameter<segmat::MeshSegmentation>>&
meshParameters()
{
  using S = segmat::MeshSegmentation;
  static const std::vector<Parameter<S>> table = [] {
    std::vector<Parameter<S>> t = sharedParameters<S>();
    t.push_back({"threads", ParameterKind::Whole, true, 0.0, 4096.0,
                 [](S& s, double v) { s.setNumberOfThreads(static_cast<unsigned>(v)); },
                 [](const S& s) { return static_cast<double>(s.getNumberOfThreads()); },
                 "threads (0: OpenMP's choice; labels do not depend on it)"});
    t.push_back({"base_spheres", ParameterKind::Whole, true, 1.0, 1e9,
                 [](S& s, double v) { s.setBaseMatTarget(static_cast<int>(v)); },
                 [](const S& s) { return static_cast<double>(s.getBaseMatTarget()); },
                 "spheres of the computed base MAT"});
    t.push_back({"structured_spheres", ParameterKind::Whole, true, -1.0, 1e9,
                 [](S& s, double v) { s.setStructuredMatTarget(static_cast<int>(v)); },
                 [](const S& s) { return static_cast<double>(s.getStructuredMatTarget()); },
                 "spheres of the computed structured MAT (-1: automatic)"});
    return t;
  }();
  return table;
}

/** Keyword arguments of segment_cloud() and CloudSegmenter. */
inline const std::vector<Parameter<CloudSegmentation>>&
cloudParameters()
{
  using S = CloudSegmentation;
  static const std::vector<Parameter<S>> table = [] {
    std::vector<Parameter<S>> t = sharedParameters<S>();
    t.push_back({"threads", ParameterKind::Whole, true, 0.0, 4096.0,
                 [](S& s, double v) { s.setNumberOfThreads(static_cast<unsigned>(v)); },
                 [](const S& s) { return static_cast<double>(s.getMesoSkeletonParameters().threads); },
                 "threads (0: OpenMP's choice; labels do not depend on it)"});
    t.push_back({"working_size", ParameterKind::Whole, true, 1.0, 1e9,
                 [](S& s, double v) { s.setWorkingSize(static_cast<std::size_t>(v)); },
                 [](const S& s) { return static_cast<double>(s.getWorkingSize()); },
                 "points kept for the medial step"});
    t.push_back({"k", ParameterKind::Whole, true, 1.0, 1e6,
                 [](S& s, double v) { s.setKSearch(static_cast<int>(v)); },
                 [](const S& s) { return static_cast<double>(s.getKSearch()); },
                 "neighbours of the k-NN graphs"});
    t.push_back({"meso_skeleton", ParameterKind::Flag, true, 0.0, 1.0,
                 [](S& s, double v) {
                   s.setMedialAxis(v != 0.0 ? segmat::CloudMedialAxis::MesoSkeleton
                                            : segmat::CloudMedialAxis::MedialMesh);
                 },
                 [](const S& s) {
                   return s.getMedialAxis() == segmat::CloudMedialAxis::MesoSkeleton ? 1.0 : 0.0;
                 },
                 "shrinking-ball medial points instead of the Voronoi medial mesh"});
    t.push_back({"visibility", ParameterKind::Flag, false, 0.0, 1.0,
                 [](S& s, double v) { s.setVisibilityFlag(v != 0.0); },
                 [](const S& s) { return s.getVisibilityFlag() ? 1.0 : 0.0; },
                 "test visibility before merging parts"});
    return t;
  }();
  return table;
}

/** What one segment() produced besides the labels (the command-line programs' --json). */
struct RunInfo
{
  segmat::StageTimings stage_seconds;
  double cpp_seconds = 0.0; ///< wall time of the C++ segment() call
  bool mat_computed = false;
  std::size_t base_spheres = 0, structured_spheres = 0;
  std::size_t samples = 0, initial_spheres = 0; ///< getMatStatistics() of either path
  bool cloud = false;  ///< the cloud path (noise_spacing applies)
  double noise_sigma = 0.0, noise_spacing = 0.0; ///< estimated, in the input's units
  double noise_remaining = 0.0; ///< left on the denoised surface (input's units)
  int denoising_passes = 0;
};

/** Mesh: one label per face. Fills what the mesh path reports. */
inline bool
segment(segmat::MeshSegmentation& s, std::vector<int>& labels, RunInfo& info)
{
  if (!s.segment(labels))
    return false;
  info.stage_seconds = s.getStageSeconds();
  info.mat_computed = s.hasComputedMats();
  info.samples = s.getMatStatistics().voronoi.num_samples;
  info.initial_spheres = s.getMatStatistics().initial_spheres;
  info.base_spheres = s.getBaseMat() ? s.getBaseMat()->numVertices() : 0;
  info.structured_spheres = s.getStructuredMat() ? s.getStructuredMat()->numVertices() : 0;
  info.noise_sigma = s.getEstimatedNoise();
  info.noise_remaining = s.getRemainingNoise();
  info.denoising_passes = s.getDenoisingPasses();
  return true;
}

/** Cloud: one label per input point. */
inline bool
segment(CloudSegmentation& s, std::vector<int>& labels, RunInfo& info)
{
  std::vector<pcl::PointIndices> parts;
  if (!s.segment(parts))
    return false;
  labels = s.getLabels();
  info.stage_seconds = s.getStageSeconds();
  info.mat_computed = true;
  info.base_spheres = s.getBaseMat() ? s.getBaseMat()->numVertices() : 0;
  info.structured_spheres = s.getStructuredMat() ? s.getStructuredMat()->numVertices() : 0;
  info.samples = s.getMatStatistics().voronoi.num_samples;
  info.initial_spheres = s.getMatStatistics().initial_spheres;
  info.cloud = true;
  info.noise_sigma = s.getEstimatedNoise();
  info.noise_spacing = s.getEstimatedSpacing();
  info.noise_remaining = s.getRemainingNoise();
  info.denoising_passes = s.getDenoisingPasses();
  return true;
}

/** The mesh to segment. */
inline void
setInput(segmat::MeshSegmentation& s, const segmat::TriangleMesh::ConstPtr& mesh)
{
  s.setInputMesh(mesh);
}

/** The cloud to segment; \a has_normals: use its normals (else they are estimated). */
inline void
setInput(CloudSegmentation& s, const pcl::PointCloud<pcl::PointNormal>::ConstPtr& cloud,
         bool has_normals)
{
  s.setInputCloud(cloud);
  s.setUseInputNormalsFlag(has_normals);
}

/** The medial meshes the last segment() used (null when none). Their identity tells whether
 * a segment() computed them again. */
inline std::pair<segmat::MedialMesh::ConstPtr, segmat::MedialMesh::ConstPtr>
medialMeshes(const segmat::MeshSegmentation& s)
{
  return {s.getBaseMat(), s.getStructuredMat()};
}

inline std::pair<segmat::MedialMesh::ConstPtr, segmat::MedialMesh::ConstPtr>
medialMeshes(const CloudSegmentation& s)
{
  return {s.getBaseMat(), s.getStructuredMat()};
}

} // namespace segmat_python
